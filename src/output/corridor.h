// The robot's corridor, where the map should know the terrain: the cells
// whose centres lie within half_width_m of the path walked (the pelvis's
// track) or of the stretch ahead_m long ahead of its last position, along
// its last heading. Held as sparse 16 × 16-cell bitmaps, so that a long walk
// costs memory in proportion to its length.
//
// Frames: W world.
#pragma once

#include <bitset>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "knowledge/elevation_grid.h"
#include "knowledge/terrain_map.h"
#include "output/track_reader.h"

namespace proxsim {

class Corridor {
 public:
  static constexpr double kHalfWidth_m = 0.3;  ///< the issue's ±0.3 m
  static constexpr double kAhead_m = 2.0;      ///< and 2 m ahead

  /// `track`: the path walked, streamed once; `last`: where the robot is at the end.
  Corridor(const TrackReader& track, const TrackPoint& last, double resolution_m,
           double half_width_m = kHalfWidth_m, double ahead_m = kAhead_m);

  bool Contains(CellIndex c) const;
  /// The bounding box of its cells (empty without a track).
  CellBox Bounds() const { return bounds_; }
  std::size_t cell_count() const { return count_; }

 private:
  // marks the cells within half_width of segment a-b
  void MarkSegment(const Vec2& a, const Vec2& b);

  double resolution_m_;
  double half_width_m_;
  std::unordered_map<std::uint64_t, std::bitset<256>> tiles_;
  CellBox bounds_;
  std::size_t count_ = 0;
};

}  // namespace proxsim
