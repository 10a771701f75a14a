// A drop ahead, seen from the readings alone: a hole or a step down deeper
// than the robot's legs take (gait.max_step_m). Two signs, per sensor and
// sample, each within the corridor the feet sweep and at most the look-ahead
// ahead of the leading toe:
//  - a point well below the ground: the reading puts the surface it met more
//    than max_drop_m below the ground the robot stands on (for a beam, even
//    its highest ray at that distance would be that deep);
//  - the floor missing where it was expected: the sensor's axis meets the
//    ground's plane within 90 % of its range and 3 degrees inside its
//    incidence window — where the device would echo off a floor — and the
//    device reports nothing at all (its maximum range).
// Only what the robot knows is used: the outputs, where its kinematics put
// the sensors and its feet, and the sensors' datasheets.
//
// Frames: W world.
#pragma once

#include <span>

#include "strategy/strategy.h"
#include "strategy/strategy_config.h"

namespace proxsim {

/// What a sensor showed of a drop.
struct DropSign {
  int sensor = -1;             ///< -1: no drop seen
  bool floor_missing = false;  ///< the floor missing where expected (else a point well below it)
  Vec3 p_W = Vec3::Zero();     ///< the deep point, or where the floor was expected
  double ahead_m = 0;          ///< p_W ahead of the leading toe
  double below_m = 0;          ///< how far below the ground (the expected point: 0)
};

/// The first sensor showing a drop deeper than max_drop_m ahead, within the
/// corridor and look-ahead of `rule`; sensor -1 when none does.
DropSign FindDropAhead(const Observation& observation, std::span<const SensorInfo> sensors, const StopConfig& rule,
                       double max_drop_m);

}  // namespace proxsim
