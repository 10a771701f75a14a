#include "knowledge/elevation_grid.h"

#include <algorithm>
#include <cmath>

namespace proxsim {

static_assert(ElevationGrid::kTileSide == 16, "TileCoord shifts by 4, CellInTile masks by 15, TileBox multiplies by 16");

ElevationGrid::ElevationGrid(double resolution_m) : resolution_m_(resolution_m) {}

ElevationGrid::Tile& ElevationGrid::TileOfSlow(CellIndex c) {
  const std::int32_t tx = TileCoord(c.ix), ty = TileCoord(c.iy);
  auto& slot = tiles_[TileKey(tx, ty)];
  if (!slot) {
    slot = std::make_unique<Tile>();
    slot->tx = tx;
    slot->ty = ty;
    bounds_.Expand(TileBox(tx, ty));
  }
  last_tile_ = slot.get();
  return *slot;
}

TerrainCell& ElevationGrid::At(CellIndex c) {
  int i = 0;
  return TileOf(c, &i).cells[i];
}

ElevationGrid::Tile* ElevationGrid::FindTileSlow(CellIndex c) {
  const auto it = tiles_.find(TileKey(TileCoord(c.ix), TileCoord(c.iy)));
  if (it == tiles_.end()) return nullptr;
  last_tile_ = it->second.get();
  return last_tile_;
}

const TerrainCell* ElevationGrid::FindSlow(CellIndex c) const {
  const std::int32_t tx = TileCoord(c.ix), ty = TileCoord(c.iy);
  const auto it = tiles_.find(TileKey(tx, ty));
  if (it == tiles_.end()) return nullptr;
  last_tile_ = it->second.get();
  return &last_tile_->cells[CellInTile(c)];
}

void ElevationGrid::FusePoint(CellIndex c, double z_m, double variance_m2, double t_s) {
  int i = 0;
  Tile& tile = TileOf(c, &i);
  TerrainCell& cell = tile.cells[i];
  ++tile.version;
  cell.last_t_s = static_cast<float>(t_s);
  if (!cell.has_elevation()) {
    cell.elevation_m = static_cast<float>(z_m);
    cell.variance_m2 = static_cast<float>(variance_m2);
    cell.hits = 1;
    if (std::isnan(cell.first_t_s)) cell.first_t_s = static_cast<float>(t_s);
    return;
  }
  const double h = cell.elevation_m, v = cell.variance_m2;
  const double gate_m = Gate_m(v, variance_m2);
  ++cell.hits;
  if (z_m > h + gate_m) {
    // a higher surface in the cell: it is the one a 2.5D map keeps
    cell.elevation_m = static_cast<float>(z_m);
    cell.variance_m2 = static_cast<float>(variance_m2);
  } else if (z_m >= h - gate_m) {
    // the same surface: the Kalman update of two Gaussian estimates
    cell.elevation_m = static_cast<float>((h * variance_m2 + z_m * v) / (v + variance_m2));
    cell.variance_m2 = static_cast<float>(v * variance_m2 / (v + variance_m2));
  }
  // below the gate: the lower part of a face or of the cell; the height stays
}

std::size_t ElevationGrid::memory_bytes() const {
  // the tiles, plus the hash map's nodes and buckets
  return tiles_.size() * (sizeof(Tile) + sizeof(void*) * 4) + tiles_.bucket_count() * sizeof(void*);
}

void ElevationGrid::Clear() {
  tiles_.clear();
  last_tile_ = nullptr;
  bounds_ = CellBox{};
}

}  // namespace proxsim
