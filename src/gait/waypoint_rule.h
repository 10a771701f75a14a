// The gait's rule for following a path (gait_walker.h), as pure functions a
// strategy asks of a path it gave the gait, so that it predicts where the
// gait heads rather than keeping a copy of the rule:
//  - waypoint i is passed when the pelvis is within half a stride of it or
//    beyond the line through it square to the way it is approached (from
//    waypoint i − 1; for the first, from where the pelvis was when the path
//    was given, or along the path when the path begins on it);
//  - the gait heads for the first waypoint not passed (the last once all are);
//  - at a heel strike it turns toward it by at most kMaxTurnPerStep_rad, or
//    more sharply, up to kMaxSharpTurnPerStep_rad, when the waypoint lies
//    inside the circle the smaller turns would walk.
// Frames: W world (x-y on the floor).
#pragma once

#include <cstddef>
#include <span>

#include "core/geometry.h"

namespace proxsim {

/// Largest heading change per step toward a waypoint, rad.
constexpr double kMaxTurnPerStep_rad = DegToRad(15.0);
/// Largest heading change per step toward a waypoint that kMaxTurnPerStep_rad cannot reach, rad.
constexpr double kMaxSharpTurnPerStep_rad = DegToRad(45.0);

/// Whether waypoint i of `waypoints_W` counts as passed with the pelvis at
/// `p_W`; `origin_W` is where the pelvis was when the path was given.
bool WaypointPassed(std::span<const Vec2> waypoints_W, std::size_t i, const Vec2& origin_W, const Vec2& p_W,
                    double stride_m);

/// The waypoint the gait heads for: the first from `from` on not passed, or
/// the last. `waypoints_W` must not be empty.
std::size_t WaypointAhead(std::span<const Vec2> waypoints_W, std::size_t from, const Vec2& origin_W, const Vec2& p_W,
                          double stride_m);

/// The heading change, rad (left +), the gait takes at a heel strike with the
/// pelvis at `p_W` heading `yaw_rad`, toward `target_W`, with steps of `step_m`.
double TurnTowardRad(const Vec2& p_W, double yaw_rad, const Vec2& target_W, double step_m);

}  // namespace proxsim
