// Sensor noise draws (paper §4.3): G = √(−2 ln U1)·cos(2π U2), Box–Muller from
// two uniforms. The uniforms come from Random123's Philox4x32-10, a
// counter-based generator: the draw for (seed, sensor, sample, ray) is a pure
// function of those four numbers, so readings are bit-identical whatever the
// thread count or the order in which samples are computed. There is no global
// or stateful generator anywhere in proxsim.
#pragma once

#include <cstdint>

#include "sensors/sensor_spec.h"

namespace proxsim {

/// Identifies one noise draw.
struct NoiseKey {
  std::uint64_t seed = 0;    ///< the run's seed
  std::uint32_t sensor = 0;  ///< sensor index in the scenario
  std::uint64_t sample = 0;  ///< sample index from t = 0
  std::uint32_t ray = 0;     ///< ray index within the sensor's beam
};

/// Two independent uniforms in (0, 1] (never 0, so ln U1 is finite).
struct UniformPair {
  double u1;
  double u2;
};

/// The uniforms of one key, from Philox4x32-10.
UniformPair KeyedUniforms(const NoiseKey& key);

/// Box–Muller as written in the paper: √(−2 ln u1)·cos(2π u2), a standard normal variate.
double BoxMuller(double u1, double u2);

/// A standard normal variate G for a key: BoxMuller(KeyedUniforms(key)).
double KeyedGaussian(const NoiseKey& key);

/// The random draws of one (seed, sensor, sample, ray) key.
struct NoiseDraw {
  double gaussian_g = 0.0;  ///< a standard normal variate
  double uniform = 1.0;     ///< a uniform in (0, 1], for the dropout
};

/// The draws of one key as every reading makes them: G from the key and,
/// only when `noise` drops detections, the dropout's uniform from a key of
/// its own (the ray's top bit set), so G is the same with dropout on or off.
NoiseDraw KeyedNoiseDraw(const NoiseSpec& noise, const NoiseKey& key);

}  // namespace proxsim
