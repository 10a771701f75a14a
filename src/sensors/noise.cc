#include "sensors/noise.h"

#include <cmath>
#include <numbers>

#include <Random123/philox.h>

namespace proxsim {

namespace {
// 53 random bits → a double in (0, 1]: (k + 1)·2⁻⁵³ for k in [0, 2⁵³).
double UnitIntervalOpenAtZero(std::uint32_t hi, std::uint32_t lo) {
  const std::uint64_t bits = ((static_cast<std::uint64_t>(hi) << 32) | lo) >> 11;
  return static_cast<double>(bits + 1) * 0x1.0p-53;
}
}  // namespace

UniformPair KeyedUniforms(const NoiseKey& key) {
  using Philox = r123::Philox4x32;
  // The seed is the key; (sample, sensor, ray) is the counter.
  const Philox::key_type k = {{static_cast<std::uint32_t>(key.seed),
                               static_cast<std::uint32_t>(key.seed >> 32)}};
  const Philox::ctr_type c = {{static_cast<std::uint32_t>(key.sample),
                               static_cast<std::uint32_t>(key.sample >> 32), key.sensor, key.ray}};
  const Philox::ctr_type r = Philox()(c, k);
  return {UnitIntervalOpenAtZero(r[0], r[1]), UnitIntervalOpenAtZero(r[2], r[3])};
}

double BoxMuller(double u1, double u2) {
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double KeyedGaussian(const NoiseKey& key) {
  const UniformPair u = KeyedUniforms(key);
  return BoxMuller(u.u1, u.u2);
}

NoiseDraw KeyedNoiseDraw(const NoiseSpec& noise, const NoiseKey& key) {
  NoiseDraw draw;
  draw.gaussian_g = KeyedGaussian(key);
  if (noise.dropout > 0) {
    NoiseKey dropout_key = key;
    dropout_key.ray |= 0x80000000u;
    draw.uniform = KeyedUniforms(dropout_key).u1;
  }
  return draw;
}

}  // namespace proxsim
