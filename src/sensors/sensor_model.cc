#include "sensors/sensor_model.h"

#include <algorithm>

namespace proxsim {

const char* ReadingStatusName(ReadingStatus status) {
  switch (status) {
    case ReadingStatus::kOk: return "ok";
    case ReadingStatus::kNoEcho: return "no_echo";
    case ReadingStatus::kTooClose: return "too_close";
    case ReadingStatus::kGrazing: return "grazing";
    case ReadingStatus::kSelf: return "self";
  }
  return "?";
}

double IncidenceDeg(double dir_x, double dir_y, double dir_z, double normal_x, double normal_y,
                    double normal_z) {
  // Two-sided surfaces: the normal's sign does not matter.
  const double cos_alpha = std::abs(dir_x * normal_x + dir_y * normal_y + dir_z * normal_z);
  return RadToDeg(std::acos(std::min(cos_alpha, 1.0)));
}

namespace {

Reading NoDetection(const SensorSpec& spec, ReadingStatus status) {
  Reading reading;
  reading.status = status;
  reading.d_m = spec.max_range_m;
  reading.signal = spec.type == SensorType::kReflectance ? 0.0 : std::numeric_limits<double>::quiet_NaN();
  return reading;
}

// Eq. (1) and its inversion at α = 0, N = 0 (§5).
Reading MeasureReflectance(const SensorSpec& spec, const Echo& echo, double noise) {
  const double d = echo.distance_m;
  const double d_max = spec.max_range_m;
  const double cos_alpha = std::cos(DegToRad(echo.incidence_deg));
  Reading reading;
  if (d <= 0.0) {
    // a surface touching the emitter: infinite signal, the inversion's limit is 0
    reading.signal = std::numeric_limits<double>::infinity();
    reading.d_m = 0.0;
  } else {
    reading.signal = (d_max - d) / (d * d) * cos_alpha * cos_alpha * (1.0 + noise);
    // s ≤ 0 (at d_max, at 90°, or noise ≤ −1): no light comes back
    if (!(reading.signal > 0.0)) return NoDetection(spec, ReadingStatus::kNoEcho);
    // the positive root of s·d² + d − d_max = 0, in a form without cancellation
    reading.d_m = 2.0 * d_max / (1.0 + std::sqrt(1.0 + 4.0 * reading.signal * d_max));
  }
  reading.status = echo.from_robot ? ReadingStatus::kSelf : ReadingStatus::kOk;
  return reading;
}

}  // namespace

Reading Measure(const SensorSpec& spec, const Echo& echo, double gaussian_g) {
  // the range and incidence windows of §4.1–§4.2
  if (!(echo.distance_m <= spec.max_range_m)) return NoDetection(spec, ReadingStatus::kNoEcho);
  if (echo.distance_m < spec.min_range_m) return NoDetection(spec, ReadingStatus::kTooClose);
  if (echo.incidence_deg > spec.max_incidence_deg) return NoDetection(spec, ReadingStatus::kGrazing);

  // the Gaussian law of §4.3
  const double noise = spec.noise.sigma * gaussian_g + spec.noise.mean;

  if (spec.type == SensorType::kReflectance) return MeasureReflectance(spec, echo, noise);

  // time of flight (laser, ultrasonic) and the ideal sensor: d_r = d·(1 + N)
  Reading reading;
  reading.status = echo.from_robot ? ReadingStatus::kSelf : ReadingStatus::kOk;
  reading.d_m = echo.distance_m * (1.0 + noise);
  return reading;
}

}  // namespace proxsim
