// What the gait asks of the ground: the height of the scene's true surface
// straight below given points. The robot's foot placement is perfect — it
// plans every footstep on the true surface — while what it perceives of the
// ground still comes only from its sensors (strategies never see this).
// sim/caster_terrain.h answers it with the world's ray caster, the robot's own
// links transparent; a gait without a terrain walks on a flat floor at its
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

class TerrainQuery {
 public:
  virtual ~TerrainQuery() = default;
  /// For each start point p_W in `from_W`: the z of the first surface met
  /// going straight down from p_W within depth_m, kNoGround if none, or
  /// kBlockedGround when that surface faces down. z_W.size() == from_W.size().
  virtual void HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const = 0;
};

}  // namespace proxsim
