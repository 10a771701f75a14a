// The ranging error by target and light (SensorSpec::sigma_table): a
// datasheet's σ at a few target reflectances and ambient levels (e.g. the
// VL53L0X's Table 12, σ 4 % on white and 7 % on grey indoors, 7 % and 12 %
// outdoors), read for the surface an echo came from in the scene's light.
//
// Between the points: at one ambient level, linear in the reflectance ρ
// between two rows and the end row's σ beyond them; between two levels,
// linear in the light; beyond the brightest level, its σ. These laws are the
// model's (a datasheet gives only its points); with one row the σ is constant.
#pragma once

#include "sensors/sensor_spec.h"

namespace proxsim {

/// σ for a target of reflectance ρ in the spec's ambient light: the table's,
/// or noise.sigma without one.
double SigmaAt(const SensorSpec& spec, double reflectance);

/// The spec's noise with σ for a target of reflectance ρ.
NoiseSpec NoiseAt(const SensorSpec& spec, double reflectance);

/// The largest σ the sensor can draw with: the table's largest, or noise.sigma.
double LargestSigma(const SensorSpec& spec);

/// The problems of a σ table, worded after the key `noise.sigma_table`.
void ValidateSigmaTable(const SensorSpec& spec, std::vector<std::string>& problems);

}  // namespace proxsim
