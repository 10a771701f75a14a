// The 2.5D elevation grid: per cell of the world lattice (grid_traversal.h),
// the fused height of the highest surface below max_height_m, its variance,
// the upper bound that free space puts on it, how many points were fused and
// when the cell last changed. Storage is tiles of 16 × 16 cells made when
// first touched, so memory grows with the area seen, not with a bounding box;
// the terrain map (terrain_map.h) retires the tiles that leave its rolling
// window, so that it stays bounded however long the walk.
//
// The update rules (after elevation_mapping, Fankhauser et al. 2014, where
// this departs from it is said):
//  - a point fuses into the cell by the Kalman rule when it agrees with the
//    cell's height within a gate (3σ of both, plus 1 cm); a point above the
//    gate replaces the height (the cell holds a higher surface: a box's top
//    over its face, an object put down); a point below is the lower part of
//    a face or of the cell, and does not change the height;
//  - a segment of a ray known to be empty lowers the upper bound of every
//    cell it crosses to the lowest height at which it crosses that column;
//    when it is a detection's ray (the echo proves that nothing was in the
//    way) and passes below the cell's height beyond the gate, the height was
//    wrong (an outlier, a moved object) and is forgotten. A ray without an
//    echo only lowers bounds: its silence may be a grazing or dark surface.
//
// Frames: W world.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <unordered_map>
#include <vector>

#include "knowledge/grid_traversal.h"

namespace proxsim {

/// One cell's state. NaN: unknown; upper_bound_m +inf: no bound yet.
struct TerrainCell {
  float elevation_m = std::numeric_limits<float>::quiet_NaN();  ///< fused height of the highest surface seen
  float variance_m2 = std::numeric_limits<float>::quiet_NaN();  ///< of elevation_m
  float upper_bound_m = std::numeric_limits<float>::infinity();  ///< free space says the surface is below this
  float first_t_s = std::numeric_limits<float>::quiet_NaN();  ///< when the cell first held a height
  float last_t_s = std::numeric_limits<float>::quiet_NaN();   ///< when a point or a bound last changed it
  std::uint32_t hits = 0;  ///< points fused into elevation_m (0 after the height is forgotten)

  bool has_elevation() const { return hits > 0; }
};

/// Inclusive cell bounds.
struct CellBox {
  std::int32_t ix_min = 0, iy_min = 0, ix_max = -1, iy_max = -1;
  bool empty() const { return ix_max < ix_min || iy_max < iy_min; }
  std::int32_t nx() const { return empty() ? 0 : ix_max - ix_min + 1; }
  std::int32_t ny() const { return empty() ? 0 : iy_max - iy_min + 1; }
  bool Contains(CellIndex c) const { return c.ix >= ix_min && c.ix <= ix_max && c.iy >= iy_min && c.iy <= iy_max; }
  /// The smallest box holding both.
  void Expand(const CellBox& other) {
    if (other.empty()) return;
    if (empty()) {
      *this = other;
      return;
    }
    ix_min = std::min(ix_min, other.ix_min);
    iy_min = std::min(iy_min, other.iy_min);
    ix_max = std::max(ix_max, other.ix_max);
    iy_max = std::max(iy_max, other.iy_max);
  }
  void Expand(CellIndex c) { Expand(CellBox{c.ix, c.iy, c.ix, c.iy}); }
  /// Whether the boxes share a cell once this one is grown by `margin` cells.
  bool Overlaps(const CellBox& other, int margin = 0) const {
    if (empty() || other.empty()) return false;
    return other.ix_min <= ix_max + margin && other.ix_max >= ix_min - margin && other.iy_min <= iy_max + margin &&
           other.iy_max >= iy_min - margin;
  }
};

/// The cells of tile (tx, ty) (16 cells a side: ElevationGrid::kTileSide).
inline CellBox TileBox(std::int32_t tx, std::int32_t ty) {
  constexpr int n = 16;
  return {tx * n, ty * n, tx * n + n - 1, ty * n + n - 1};
}

/// Index of cell c within its tile (16 cells a side: ElevationGrid::kTileSide), and the tile's index.
inline int CellInTile(CellIndex c) { return (c.iy & 15) * 16 + (c.ix & 15); }
inline std::int32_t TileCoord(std::int32_t i) { return i >> 4; }  // floor(i / 16), also for negative i
/// One key for a tile's two coordinates (a hash map's key).
inline std::uint64_t TileKey(std::int32_t tx, std::int32_t ty) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(tx)) << 32) | static_cast<std::uint32_t>(ty);
}

class ElevationGrid {
 public:
  static constexpr int kTileSide = 16;  ///< cells per tile side
  static constexpr int kTileCells = kTileSide * kTileSide;
  /// Points that agree within 3σ plus this fuse; beyond it the higher wins.
  static constexpr double kGateFloor_m = 0.01;

  struct Tile {
    std::int32_t tx = 0, ty = 0;  ///< tile index: cells [tx·16, tx·16 + 16) in x
    std::array<TerrainCell, kTileCells> cells;
    std::array<std::uint8_t, kTileCells> labels{};  ///< the hazard classifier's per-cell label (hazards.h); during a hazard pass its top bit marks a cell filled (terrain_map.cc, kFilledBit)
    std::uint32_t version = 0;  ///< bumped whenever a cell of the tile changes
    std::uint32_t labelled_version = ~0u;  ///< the version its labels were computed at
    int labelled_count = 0;                ///< cells whose label is not kNone
  };

  explicit ElevationGrid(double resolution_m);

  double resolution_m() const { return resolution_m_; }
  CellIndex IndexOf(double x_m, double y_m) const { return CellOf(x_m, y_m, resolution_m_); }
  /// The centre of a cell, world x-y.
  Vec2 CellCentre(CellIndex c) const { return {(c.ix + 0.5) * resolution_m_, (c.iy + 0.5) * resolution_m_}; }

  /// The cell, its tile made if it had none.
  TerrainCell& At(CellIndex c);
  /// The cell, or null when its tile was never touched.
  const TerrainCell* Find(CellIndex c) const {
    // rays walk cell to cell: most lookups stay in the tile of the last access
    if (last_tile_ != nullptr && last_tile_->tx == TileCoord(c.ix) && last_tile_->ty == TileCoord(c.iy)) {
      return &last_tile_->cells[CellInTile(c)];
    }
    return FindSlow(c);
  }
  /// The tile holding cell c, made if it had none, and the cell's index in it
  /// (a ray's walk reads and bounds a cell through one lookup).
  Tile& TileOf(CellIndex c, int* cell_in_tile) {
    *cell_in_tile = CellInTile(c);
    if (last_tile_ != nullptr && last_tile_->tx == TileCoord(c.ix) && last_tile_->ty == TileCoord(c.iy)) {
      return *last_tile_;
    }
    return TileOfSlow(c);
  }

  /// Fuses a measured height (variance > 0) at time t into the cell (rules above).
  void FusePoint(CellIndex c, double z_m, double variance_m2, double t_s);
  /// A ray known empty crossed the cell's column down to z_m: lowers the
  /// upper bound; with `proves_empty`, a height above z_m beyond the gate is forgotten.
  void BoundFromFreeSpace(CellIndex c, double z_m, bool proves_empty, double t_s) {
    int i = 0;
    BoundFromFreeSpace(TileOf(c, &i), i, z_m, proves_empty, t_s);
  }
  /// The same, for cell i of a tile of this grid.
  void BoundFromFreeSpace(Tile& tile, int i, double z_m, bool proves_empty, double t_s) {
    TerrainCell& cell = tile.cells[i];
    const auto z = static_cast<float>(z_m);
    bool changed = false;
    if (z < cell.upper_bound_m) {
      cell.upper_bound_m = z;
      changed = true;
    }
    if (proves_empty && cell.has_elevation() && z_m < cell.elevation_m - Gate_m(cell.variance_m2, 0.0)) {
      // the ray went through where the height said a surface was
      cell.elevation_m = cell.variance_m2 = std::numeric_limits<float>::quiet_NaN();
      cell.hits = 0;
      changed = true;
    }
    if (changed) {
      ++tile.version;
      cell.last_t_s = static_cast<float>(t_s);
    }
  }

  /// Every tile, in no particular order.
  template <class F>
  void ForEachTile(F&& f) const {
    for (const auto& [key, tile] : tiles_) f(*tile);
  }
  template <class F>
  void ForEachTile(F&& f) {
    for (auto& [key, tile] : tiles_) f(*tile);
  }
  /// The tile holding cell c, or null.
  Tile* FindTile(CellIndex c) {
    if (last_tile_ != nullptr && last_tile_->tx == TileCoord(c.ix) && last_tile_->ty == TileCoord(c.iy)) return last_tile_;
    return FindTileSlow(c);
  }

  /// The cells of every tile held (empty when none).
  CellBox Bounds() const { return bounds_; }
  /// Takes out every tile whose cells `keep(box)` does not want, and returns them.
  template <class Keep>
  std::vector<std::unique_ptr<Tile>> RetireTiles(Keep&& keep) {
    std::vector<std::unique_ptr<Tile>> retired;
    bounds_ = CellBox{};
    for (auto it = tiles_.begin(); it != tiles_.end();) {
      const CellBox box = TileBox(it->second->tx, it->second->ty);
      if (keep(box)) {
        bounds_.Expand(box);
        ++it;
        continue;
      }
      retired.push_back(std::move(it->second));
      it = tiles_.erase(it);
    }
    if (!retired.empty()) last_tile_ = nullptr;
    return retired;
  }
  std::size_t tile_count() const { return tiles_.size(); }
  /// Bytes held by the tiles and their index.
  std::size_t memory_bytes() const;

  /// Forgets every cell.
  void Clear();

  /// The gate within which two heights of variances va, vb agree.
  static double Gate_m(double variance_a_m2, double variance_b_m2) {
    return 3.0 * std::sqrt(variance_a_m2 + variance_b_m2) + kGateFloor_m;
  }

 private:
  // the lookups past the last tile's cache
  const TerrainCell* FindSlow(CellIndex c) const;
  Tile& TileOfSlow(CellIndex c);
  Tile* FindTileSlow(CellIndex c);

  double resolution_m_;
  std::unordered_map<std::uint64_t, std::unique_ptr<Tile>> tiles_;
  // the tile of the last access, a cache that lookups of either constness
  // refresh: rays and flood fills walk cell to cell
  mutable Tile* last_tile_ = nullptr;
  CellBox bounds_;
};

}  // namespace proxsim
