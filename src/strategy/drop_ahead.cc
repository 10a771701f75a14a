#include "strategy/drop_ahead.h"

#include <algorithm>
#include <cmath>

#include "sensors/measured_point.h"

namespace proxsim {

namespace {

// The expected floor must lie this far inside the incidence window, degrees.
constexpr double kIncidenceMargin_deg = 3.0;
// Where the floor was expected must lie this far ahead of the leading toe, m:
// nearer, a steep axis passes over the robot's own feet, and a foot met at a
// grazing angle echoes nothing either.
constexpr double kClearOfFeet_m = 0.10;

// The sine of the elevation of the sensor's highest ray (its axis for one
// ray): a surface a reading meets at distance d is at most d times this above
// the sensor.
double SinHighestRay(const SensorOutput& sensor, const SensorInfo& info) {
  const double elevation = std::asin(std::clamp(sensor.dir_W.z(), -1.0, 1.0)) + DegToRad(0.5 * info.aperture_deg);
  return std::sin(std::min(elevation, kPi / 2));
}

}  // namespace

std::optional<DropSign> SeeDropAhead(const SensorOutput& sensor, const SensorInfo& info, const RobotKnowledge& self,
                                     const StopConfig& rule, double max_drop_m) {
  if (!sensor.fresh || !(max_drop_m > 0)) return std::nullopt;
  const double deep_z_m = self.ground_z_m - max_drop_m;
  // p_W ahead within the corridor and the look-ahead: its distance ahead of the toe
  const auto ahead_in_corridor = [&](const Vec3& p_W) -> std::optional<double> {
    const Vec3 from_front = p_W - self.p_W_front;
    const double ahead_m = from_front.dot(self.heading_W);
    const double aside_m = from_front.dot(Vec3::UnitZ().cross(self.heading_W));
    if (ahead_m <= 0 || ahead_m > rule.stop_distance_m || std::abs(aside_m) > rule.corridor_half_width_m) {
      return std::nullopt;
    }
    return ahead_m;
  };

  if (sensor.detected) {
    // a surface met deeper than the legs step down
    const double z_high_m = sensor.p_WS.z() + sensor.d_m / sensor.cos_to_axis * SinHighestRay(sensor, info);
    if (!(z_high_m < deep_z_m)) return std::nullopt;
    const Vec3 p_W = sensor.p_W_measured();
    const auto ahead_m = ahead_in_corridor(p_W);
    if (!ahead_m) return std::nullopt;
    return DropSign{.floor_missing = false, .p_W = p_W, .ahead_m = *ahead_m, .below_m = self.ground_z_m - z_high_m};
  }

  // nothing reported (a self echo reports a distance, and is no sign)
  if (sensor.d_m < info.max_range_m || !(sensor.dir_W.z() < 0)) return std::nullopt;
  // where the axis crosses the ground's level, and whether the floor there would echo
  const double t_ground_m = (self.ground_z_m - sensor.p_WS.z()) / sensor.dir_W.z();
  const double incidence_deg = RadToDeg(std::acos(std::clamp(-sensor.dir_W.z(), 0.0, 1.0)));
  // A vertical face across the axis (a riser, a wall, a hole's far side) is
  // met at the complement of the floor's incidence. Where that is outside the
  // window, such a face would echo nothing too: silence could be a riser met
  // at a grazing angle as well as free space, and proves nothing.
  const double vertical_face_incidence_deg = 90.0 - incidence_deg;
  const double echoing_incidence_deg = info.max_incidence_deg - kIncidenceMargin_deg;
  if (t_ground_m <= info.min_range_m || incidence_deg > echoing_incidence_deg ||
      vertical_face_incidence_deg > echoing_incidence_deg) {
    return std::nullopt;
  }
  const Vec3 p_W_ground = MeasuredPoint_W(sensor.p_WS, sensor.dir_W, t_ground_m);
  const auto ground_ahead_m = ahead_in_corridor(p_W_ground);
  if (!ground_ahead_m || *ground_ahead_m < kClearOfFeet_m) return std::nullopt;
  // the free space reaches deep_z_m within the range (on the beam's highest
  // ray), and there, within the look-ahead, the surface lies deeper still
  const double sin_high = SinHighestRay(sensor, info);
  if (!(sin_high < 0)) return std::nullopt;
  const double t_deep_m = (deep_z_m - sensor.p_WS.z()) / sin_high;
  if (!(t_deep_m < info.max_range_m)) return std::nullopt;
  const Vec2 horizontal = sensor.dir_W.head<2>();
  const Vec2 out_W = horizontal.norm() > 1e-9 ? Vec2(horizontal.normalized()) : Vec2(self.heading_W.head<2>());
  const double reach_m = t_deep_m * std::sqrt(1 - sin_high * sin_high);
  const Vec3 p_W_deep(sensor.p_WS.x() + reach_m * out_W.x(), sensor.p_WS.y() + reach_m * out_W.y(), deep_z_m);
  const auto deep_ahead_m = ahead_in_corridor(p_W_deep);
  if (!deep_ahead_m) return std::nullopt;
  return DropSign{.floor_missing = true, .p_W = p_W_deep, .ahead_m = *deep_ahead_m, .below_m = max_drop_m};
}

}  // namespace proxsim
