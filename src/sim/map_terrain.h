// The gait's terrain (gait/terrain_query.h) answered by the robot's own
// in-loop terrain map (`gait.footholds: map`): the footholds are planned on
// what the robot's readings built, never on the truth. A vertical line meets
// the height the map holds in the cell under it (its fused elevation, a
// piecewise constant surface on the map's cells); a cell the map holds no
// height for is unknown (kUnknownGround) — also when free space bounded it:
// a silent ray's bound says only that the surface is lower, and a grazing or
// dark floor is silent too — and the planner takes it as level with the
// stance foot. Only TerrainMap's public query API is read (CellAt).
//
// The map is the one the simulation updated at the last sample: a step
// planned at a heel strike sees what was delivered up to the sample before.
//
// Frames: W world.
#pragma once

#include "gait/terrain_query.h"
#include "knowledge/terrain_map.h"

namespace proxsim {

class MapTerrain : public TerrainQuery {
 public:
  /// `map` must outlive this.
  explicit MapTerrain(const TerrainMap& map) : map_(map) {}

  void HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const override;

 private:
  const TerrainMap& map_;
};

}  // namespace proxsim
