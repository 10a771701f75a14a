// Where a distance along a sensor's ray lies in the world. One function for
// every place that turns a distance into a point — the profile, the stop and
// drop rules, the terrain map, the hit point beside a reading — so that they
// cannot disagree about it.
//
// Frames: W world, S the sensor (its rays start at its origin).
#pragma once

#include "core/geometry.h"

namespace proxsim {

/// The point d_m from the sensor's origin p_WS along the unit direction
/// dir_W: for a reading's d_m the point it measured, for an echo's true
/// distance the point the ray hit.
inline Vec3 MeasuredPoint_W(const Vec3& p_WS, const Vec3& dir_W, double d_m) { return p_WS + d_m * dir_W; }

}  // namespace proxsim
