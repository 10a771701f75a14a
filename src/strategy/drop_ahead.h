// A drop ahead, seen from the readings alone: a hole or a step down deeper
// than the robot's legs take (gait.max_step_m). A reading tells the robot
// that the space along the sensor's axis is free up to the distance it
// reports; where that free space reaches deeper than max_drop_m below the
// ground the robot stands on, the surface there is that deep. Two signs, per
// sensor and sample:
//  - a point well below the ground: the reading puts the surface it met more
//    than max_drop_m below the ground (for a beam, even its highest ray at
//    that distance would be that deep);
//  - the floor missing where it was expected: the axis crosses the ground's
//    level at an incidence the device echoes from (3 degrees inside its
//    window, so that a lower floor parallel to it would echo too), and so
//    would a vertical face across it (a riser or a wall: else silence may be
//    a riser met at a grazing angle), yet the
//    device reports nothing at all (its maximum range): the space along the
//    axis is free to the end of the range. Where that free space (on a beam's
//    highest ray) passes max_drop_m below the ground, the surface under it
//    is deeper still.
// The sign stands where the surface is known to be that deep — the deep
// point, or where the free space passes that depth — and must be within the
// corridor the feet sweep and at most the look-ahead ahead of the leading
// toe: a flight of stairs going down, whose whole drop is deep but each of
// whose steps the legs take, shows no sign until a step is that deep. For
// the floor missing, where the axis crosses the ground's level must also be
// at least 0.1 m ahead of the toe: a steeper axis passes over the robot's
// own feet, which hide the floor (a foot met at a grazing angle echoes
// nothing either). A shallower step down proves nothing and is left to the
// legs.
//
// Only what the robot knows is used: the outputs, where its kinematics put
// the sensors and its feet, and the sensors' datasheets.
//
// Frames: W world.
#pragma once

#include <optional>

#include "strategy/strategy.h"
#include "strategy/strategy_config.h"

namespace proxsim {

/// What one sensor's reading showed of a drop.
struct DropSign {
  bool floor_missing = false;  ///< the floor missing where expected (else a point well below it)
  Vec3 p_W = Vec3::Zero();     ///< where the surface is known to be deep: the deep point, or where the free space passes max_drop_m below the ground
  double ahead_m = 0;          ///< p_W ahead of the leading toe, along the heading
  double below_m = 0;          ///< p_W below the ground (the surface there is at least this deep)
};

/// The drop deeper than max_drop_m that one sensor's fresh output shows
/// within the corridor and look-ahead of `rule`; nothing when it shows none.
std::optional<DropSign> SeeDropAhead(const SensorOutput& sensor, const SensorInfo& info, const RobotKnowledge& self,
                                     const StopConfig& rule, double max_drop_m);

}  // namespace proxsim
