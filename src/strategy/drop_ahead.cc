#include "strategy/drop_ahead.h"

#include <algorithm>
#include <cmath>

namespace proxsim {

namespace {

// The expected floor must lie this far inside the incidence window, degrees,
constexpr double kIncidenceMargin_deg = 3.0;
// and within this fraction of the range (noise cannot push it out).
constexpr double kRangeFraction = 0.9;

}  // namespace

DropSign FindDropAhead(const Observation& observation, std::span<const SensorInfo> sensors, const StopConfig& rule,
                       double max_drop_m) {
  DropSign sign;
  if (observation.robot == nullptr || !(max_drop_m > 0)) return sign;
  const RobotKnowledge& self = *observation.robot;
  const Vec3 lateral_W = Vec3::UnitZ().cross(self.heading_W);
  // a point ahead within the corridor and the look-ahead
  const auto in_corridor = [&](const Vec3& p_W, double* ahead_m) {
    const Vec3 from_front = p_W - self.p_W_front;
    *ahead_m = from_front.dot(self.heading_W);
    return *ahead_m > 0 && *ahead_m <= rule.stop_distance_m && std::abs(from_front.dot(lateral_W)) <= rule.corridor_half_width_m;
  };
  for (std::size_t i = 0; i < observation.sensors.size() && i < sensors.size(); ++i) {
    const SensorOutput& out = observation.sensors[i];
    const SensorInfo& info = sensors[i];
    if (!out.fresh) continue;
    double ahead = 0;
    if (out.detected) {
      // the highest the surface met can be: along the axis, or the beam's highest ray
      const double elevation = std::asin(std::clamp(out.dir_W.z(), -1.0, 1.0)) + DegToRad(0.5 * info.aperture_deg);
      const double z_high = out.p_WS.z() + out.d_m * std::sin(std::min(elevation, kPi / 2));
      const Vec3 p_W = out.p_W_measured();
      if (z_high < self.ground_z_m - max_drop_m && in_corridor(p_W, &ahead)) {
        return DropSign{.sensor = static_cast<int>(i), .floor_missing = false, .p_W = p_W, .ahead_m = ahead,
                        .below_m = self.ground_z_m - z_high};
      }
      continue;
    }
    // nothing reported: was a floor expected where the axis meets the ground's plane?
    if (out.d_m < info.max_range_m || out.dir_W.z() >= 0) continue;
    const double t = (self.ground_z_m - out.p_WS.z()) / out.dir_W.z();
    const double incidence_deg = RadToDeg(std::acos(std::clamp(-out.dir_W.z(), 0.0, 1.0)));
    if (t <= info.min_range_m || t > kRangeFraction * info.max_range_m ||
        incidence_deg > info.max_incidence_deg - kIncidenceMargin_deg)
      continue;
    const Vec3 p_W = out.p_WS + t * out.dir_W;
    if (in_corridor(p_W, &ahead))
      return DropSign{.sensor = static_cast<int>(i), .floor_missing = true, .p_W = p_W, .ahead_m = ahead, .below_m = 0};
  }
  return sign;
}

}  // namespace proxsim
