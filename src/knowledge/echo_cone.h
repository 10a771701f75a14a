// Where a beam's echo may have come from. A sensor with a cone of rays
// reports the nearest echo anywhere in its cone (or, a part that weighs its
// returns, their signal-weighted centre: no nearer than that echo), not on
// its axis: the point a reading puts on the axis (SensorOutput::p_W_measured)
// may stand centimetres above a floor that echoed at the cone's lower edge. Whether a
// reading shows something raised is therefore asked of the lowest point the
// echo can have come from: the cone's lowest direction at the reported
// distance. One ray (aperture 0) is its axis.
//
// Frames: W world.
#pragma once

#include <algorithm>
#include <cmath>

#include "knowledge/observation.h"

namespace proxsim {

/// The height (world z) of the lowest point an echo at `d_m` can have come
/// from, for a sensor at `p_WS` whose axis is `dir_W` (unit) and whose beam's
/// full cone angle is `aperture_deg`: the axis turned down by half the
/// aperture in its vertical plane, z = p_z + d·(cos θ·a_z − sin θ·√(1 − a_z²)).
inline double LowestEchoZ_m(const Vec3& p_WS, const Vec3& dir_W, double d_m, double aperture_deg) {
  const double half_rad = 0.5 * aperture_deg * M_PI / 180.0;
  const double a_z = std::clamp(dir_W.z(), -1.0, 1.0);
  return p_WS.z() + d_m * (std::cos(half_rad) * a_z - std::sin(half_rad) * std::sqrt(1.0 - a_z * a_z));
}

/// The cone's lowest direction (unit): the axis `dir_W` (unit) turned down by
/// `half_rad` in its vertical plane; the axis itself when it is vertical.
inline Vec3 LowestEchoDirection_W(const Vec3& dir_W, double half_rad) {
  const double a_z = std::clamp(dir_W.z(), -1.0, 1.0);
  const double horizontal = std::sqrt(1.0 - a_z * a_z);
  if (horizontal < 1e-9) return dir_W;
  // the unit vector across the axis in its vertical plane, pointing down
  const Vec3 down_W = (a_z * dir_W - Vec3::UnitZ()) / horizontal;
  return (std::cos(half_rad) * dir_W + std::sin(half_rad) * down_W).normalized();
}

/// Whether a detection (a fresh reading's headline, a zone's target, a beam's
/// echo) stands at least `min_height_m` above the ground at `ground_z_m`
/// wherever in the sensor's cone it came from (a zone's own axis: the parts
/// with zones have no beam, aperture 0).
inline bool EchoIsRaised(const Measurement& measurement, const SensorInfo& info, double ground_z_m,
                         double min_height_m) {
  return measurement.detected() &&
         LowestEchoZ_m(measurement.p_WS, measurement.dir_W, measurement.ray_d_m(), info.aperture_deg) - ground_z_m >=
             min_height_m;
}

/// Calls `visit(measurement)` for each detection a fresh sensor output puts
/// in the world that stands `min_height_m` above the ground (EchoIsRaised):
/// every one the part reports beside its reading (its reading is one of
/// them: a zone's nearest target, a beam's first or strongest echo), or the
/// reading alone.
template <typename Visit>
void ForEachRaisedEcho(const SensorOutput& sensor, const SensorInfo& info, double ground_z_m, double min_height_m,
                       Visit&& visit) {
  if (!sensor.fresh) return;
  if (sensor.measurements.empty()) {
    if (const Measurement headline = sensor.headline(); EchoIsRaised(headline, info, ground_z_m, min_height_m))
      visit(headline);
    return;
  }
  for (const Measurement& measurement : sensor.measurements) {
    if (EchoIsRaised(measurement, info, ground_z_m, min_height_m)) visit(measurement);
  }
}

}  // namespace proxsim
