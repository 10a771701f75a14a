#include "gait/waypoint_rule.h"

#include <algorithm>
#include <cmath>

namespace proxsim {

bool WaypointPassed(std::span<const Vec2> waypoints_W, std::size_t i, const Vec2& origin_W, const Vec2& p_W,
                    double stride_m) {
  const Vec2& waypoint = waypoints_W[i];
  if ((waypoint - p_W).norm() < 0.5 * stride_m) return true;
  // the way it is approached: from the previous waypoint, or from where the
  // path began; along the path when it begins on it
  Vec2 approach = waypoint - (i == 0 ? origin_W : waypoints_W[i - 1]);
  if (approach.norm() < 1e-9 && i + 1 < waypoints_W.size()) approach = waypoints_W[i + 1] - waypoint;
  return approach.norm() < 1e-9 || (p_W - waypoint).dot(approach) >= 0;
}

std::size_t WaypointAhead(std::span<const Vec2> waypoints_W, std::size_t from, const Vec2& origin_W, const Vec2& p_W,
                          double stride_m) {
  std::size_t i = from;
  while (i + 1 < waypoints_W.size() && WaypointPassed(waypoints_W, i, origin_W, p_W, stride_m)) ++i;
  return i;
}

double TurnTowardRad(const Vec2& p_W, double yaw_rad, const Vec2& target_W, double step_m) {
  // more sharply when the target lies inside the circle that steps of the
  // usual turn walk (they would circle around it): as sharply as the circle
  // through it tangent to the heading needs, or (the target behind) the sharpest turn
  const Vec2 to = target_W - p_W;
  const double bearing = std::remainder(std::atan2(to.y(), to.x()) - yaw_rad, 2 * kPi);
  double limit = kMaxTurnPerStep_rad;
  const double radius_m = step_m / (2 * std::sin(kMaxTurnPerStep_rad / 2));
  const Vec2 left(-std::sin(yaw_rad), std::cos(yaw_rad));
  const Vec2 centre = p_W + (bearing >= 0 ? radius_m : -radius_m) * left;
  if ((target_W - centre).norm() < radius_m) {
    const double chord = step_m * std::abs(std::sin(bearing)) / std::max(to.norm(), 1e-9);
    limit = std::abs(bearing) < kPi / 2 && chord < 1 ? std::clamp(2 * std::asin(chord), limit, kMaxSharpTurnPerStep_rad)
                                                     : kMaxSharpTurnPerStep_rad;
  }
  return std::clamp(bearing, -limit, limit);
}

}  // namespace proxsim
