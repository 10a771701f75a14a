#include "sensors/range_inverse.h"

#include <algorithm>
#include <cmath>

#include "core/geometry.h"
#include "sensors/noise_table.h"
#include "sensors/sensor_model.h"

namespace proxsim {

namespace {

// The standard deviation of the distance a lookup sensor implies: the
// output's σ over the table's slope at d (a flat part of the table says
// nothing about d: its whole range).
double LookupSigma_m(const SensorSpec& spec, double d_m) {
  constexpr double kStep_m = 0.001;
  double fraction = 0;
  const double output = LookupOutput(spec.lookup_table, d_m, &fraction);
  const double slope = (LookupOutput(spec.lookup_table, d_m + kStep_m) - LookupOutput(spec.lookup_table, d_m - kStep_m)) /
                       (2 * kStep_m);
  const double sigma_output = std::abs(fraction * output);
  if (std::abs(slope) < 1e-12) return sigma_output > 0 ? spec.max_range_m : 0.0;
  return std::min(sigma_output / std::abs(slope), spec.max_range_m);
}

// The reflectance inversion d(s) of s·d² + d − d_max = 0 spreads the signal's
// noise over d by |dd/ds| = d³/(2·d_max − d) (from s = (d_max − d)/d²).
double ReflectanceSigma_m(const SensorSpec& spec, double d_m) {
  const double d_max = spec.max_range_m;
  if (d_m <= 0 || d_m >= d_max) return 0.0;
  const double s = (d_max - d_m) / (d_m * d_m);
  const double sigma_s = spec.noise.model == NoiseModel::kAdditive ? spec.noise.sigma : spec.noise.sigma * s;
  return sigma_s * d_m * d_m * d_m / (2 * d_max - d_m);
}

}  // namespace

double UnbiasedDistance_m(const SensorSpec& spec, double d_m) {
  const double mean = spec.noise.mean;
  if (mean == 0 || !IsTimeOfFlight(spec.type)) return d_m;
  switch (spec.noise.model) {
    case NoiseModel::kMultiplicative: return 1.0 + mean > 0 ? d_m / (1.0 + mean) : d_m;
    case NoiseModel::kAdditive: return d_m - mean;
    case NoiseModel::kDistanceScaled: {
      // d + m·d² = d_r: the positive root
      const double disc = 1.0 + 4.0 * mean * d_m;
      return disc > 0 && mean != 0 ? (-1.0 + std::sqrt(disc)) / (2.0 * mean) : d_m;
    }
  }
  return d_m;
}

double RangeSigma_m(const SensorSpec& spec, double d_m) {
  double sigma_m = 0;
  if (spec.type == SensorType::kLookup) {
    sigma_m = LookupSigma_m(spec, d_m);
  } else if (spec.type == SensorType::kReflectance) {
    sigma_m = ReflectanceSigma_m(spec, d_m);
  } else {
    // with a σ table the robot does not know the target's reflectance: the table's largest σ
    const double sigma = LargestSigma(spec);
    switch (spec.noise.model) {
      case NoiseModel::kMultiplicative: sigma_m = sigma * d_m; break;
      case NoiseModel::kAdditive: sigma_m = sigma; break;
      case NoiseModel::kDistanceScaled: sigma_m = sigma * d_m * d_m; break;
    }
  }
  // rounding to a resolution adds a uniform error of variance r²/12
  const double r = spec.noise.resolution_m;
  return std::sqrt(sigma_m * sigma_m + r * r / 12.0);
}

double SpreadHalfAngleRad(const SensorSpec& spec) {
  if (spec.beam) return DegToRad(spec.beam->aperture_deg) / 2;
  if (spec.zones) {
    const ZoneSpec& z = *spec.zones;
    return std::max(std::atan(std::tan(DegToRad(z.fov_h_deg) / 2) / z.nx), std::atan(std::tan(DegToRad(z.fov_v_deg) / 2) / z.ny));
  }
  return 0.0;
}

double EchoIncidenceLimitDeg(const SensorSpec& spec) {
  if (spec.echo_model == EchoModel::kPhysical && IsTimeOfFlight(spec.type)) {
    return RadToDeg(std::acos(std::clamp(spec.echo_threshold, 0.0, 1.0)));
  }
  return spec.max_incidence_deg;
}

}  // namespace proxsim
