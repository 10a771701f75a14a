// The OctoMap reconstruction of a walk of any length. OctoMap's keys reach
// ±reach_m() of its tree's origin (16 bits a coordinate: ±655.36 m at the
// map's 2 cm), so a longer walk is kept in tiles, each an OctomapRecorder of
// its own with its origin moved: terrain/map.bt is the tile about the world
// origin, holding every reading within its reach, as a short walk's always
// did; a reading beyond it goes into the tile whose origin is nearest its
// sensor, the origins every reach_m() along x and y, written as
// terrain/map_tiles/map_X_Y.bt (X, Y the tile's indices: its origin at
// (X, Y, 0)·reach_m() in the world; octovis shows each in its own frame, and
// summary.json terrain.map_bt lists them with their origins).
//
// Frames: W world, T a tile (W moved by the tile's origin).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "output/octomap_recorder.h"

namespace proxsim {

class OctomapTiles {
 public:
  explicit OctomapTiles(double resolution_m);

  /// Inserts one reading's ray into the tile that holds it.
  void Add(const RayEvidence& evidence_W);
  /// Moves every tile's subtrees outside [lo_W, hi_W] out of memory.
  void RetireOutside(const Vec2& lo_W, const Vec2& hi_W);

  /// A tile beyond the first, as written.
  struct Tile {
    int ix = 0, iy = 0;
    Vec3 origin_W = Vec3::Zero();   ///< where the tile's frame T stands in the world
    std::string file;               ///< relative to the terrain folder
  };
  /// Writes `dir`/map.bt and, for a walk beyond its reach, `dir`/map_tiles/;
  /// returns the tiles beyond map.bt (empty for a walk within its reach).
  /// Throws std::runtime_error on failure.
  std::vector<Tile> WriteBinary(const std::filesystem::path& dir) const;

  /// The tile about the world origin (terrain/map.bt's).
  OctomapRecorder& origin_tile() { return *tiles_.at({0, 0}); }
  const OctomapRecorder& origin_tile() const { return *tiles_.at({0, 0}); }
  /// The tile (ix, iy), in its own frame; null when no reading went there.
  const OctomapRecorder* tile(int ix, int iy) const {
    const auto found = tiles_.find({ix, iy});
    return found == tiles_.end() ? nullptr : found->second.get();
  }
  /// How far from its origin a tile reaches, and how far apart the origins stand, m.
  double reach_m() const { return origin_tile().reach_m(); }
  /// Readings no tile could hold (a ray longer than a tile's reach: none from a sensor's range).
  std::uint64_t left_out() const { return left_out_; }

 private:
  double resolution_m_;
  std::map<std::pair<int, int>, std::unique_ptr<OctomapRecorder>> tiles_;  // (0, 0) always
  std::uint64_t left_out_ = 0;
};

}  // namespace proxsim
