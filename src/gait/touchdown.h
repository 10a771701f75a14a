// Where a foot planned on what the robot knows comes to rest on the true
// ground (`gait.footholds: map`, docs/terrain.md): the legs feel the ground.
//
// At its heel strike the landed sole is held against the true surface under
// it — vertical lines through its heel, its middle (under the ankle) and its
// toe, each on the sole's centre line and its two edges. The foot rests on the
// highest of them. It falls when:
//  - there is nothing under it (within the lines' depth);
//  - it rests lower than the tread it was planned on by more than the
//    tolerance (`gait.touchdown_tolerance_m`): the leg reached for ground that
//    was not there;
//  - only its toe touches within the tolerance of where it rests: the heel and
//    the middle of the sole hang over an edge, and the foot tips off it.
// Otherwise it settles where it rests, higher or lower than planned (a foot
// meeting ground much higher than planned has struck it: the simulation's
// contact check, sim/contacts.h, reports that as a collision, not this).
//
// Frames: W world.
#pragma once

#include <array>
#include <string>

#include "core/geometry.h"
#include "gait/terrain_query.h"

namespace proxsim {

/// The landed sole: its heel, middle and toe on its centre line, in W.
struct LandedSole {
  std::array<Vec3, 3> p_W;    ///< heel, middle, toe
  Vec3 across_W = Vec3::UnitY();  ///< unit, horizontal, across the sole
  double half_width_m = 0;
  const char* side = "left";  ///< for the reason
};

struct Touchdown {
  bool fell = false;
  double rest_z_m = 0;  ///< where the sole rests (not fell)
  std::string reason;   ///< when it fell: one line for a person, naming where
};

/// How the sole lands on `ground` when planned on a tread at planned_z_m;
/// the lines start reach_m above that tread and reach reach_m + 3 m down.
Touchdown FeelTouchdown(const TerrainQuery& ground, const LandedSole& sole, double planned_z_m, double tolerance_m,
                        double reach_m);

}  // namespace proxsim
