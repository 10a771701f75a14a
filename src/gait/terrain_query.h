// What the gait asks of the ground: the height of a surface straight below
// given points. By default (`gait.footholds: truth`) that is the scene's true
// surface and the robot's foot placement is perfect — it plans every footstep
// on it — while what it perceives still comes only from its sensors
// (strategies never see this); sim/caster_terrain.h answers it with the
// world's ray caster, the robot's own links transparent. Under
// `gait.footholds: map` the footholds are planned on the robot's own terrain
// map (sim/map_terrain.h), which may not know a place (kUnknownGround), while
// the true surface still decides where a foot comes to rest (the legs feel
// it: gait/touchdown.h). A gait without a terrain walks on a flat floor at its
// start height, as before the gait walked uneven ground.
//
// Frames: W world (z up).
#pragma once

#include <limits>
#include <span>

#include "core/geometry.h"

namespace proxsim {

/// Height answered where a vertical line meets nothing within its depth.
constexpr double kNoGround = -std::numeric_limits<double>::infinity();
/// Height answered where a vertical line starts inside an object (or under an
/// overhang): the first surface it meets faces down. Nothing can stand there.
constexpr double kBlockedGround = std::numeric_limits<double>::infinity();
/// Height answered where the terrain does not know (a map that has seen
/// nothing there): the planner takes it as level with the stance foot.
constexpr double kUnknownGround = std::numeric_limits<double>::quiet_NaN();

class TerrainQuery {
 public:
  virtual ~TerrainQuery() = default;
  /// For each start point p_W in `from_W`: the z of the first surface met
  /// going straight down from p_W within depth_m, kNoGround if none, or
  /// kBlockedGround when that surface faces down, or kUnknownGround (NaN)
  /// where the terrain does not know. z_W.size() == from_W.size().
  virtual void HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const = 0;
};

}  // namespace proxsim
