// The noise of paper §4.3, checked statistically with a fixed seed and stated
// bounds, and for its keyed determinism.
#include "sensors/noise.h"

#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "sensors/sensor_model.h"

namespace proxsim {
namespace {

constexpr int kSamples = 10000;

TEST(BoxMuller, IsThePaperFormula) {
  EXPECT_DOUBLE_EQ(BoxMuller(0.5, 0.0), std::sqrt(-2.0 * std::log(0.5)));
  EXPECT_NEAR(BoxMuller(0.5, 0.25), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(BoxMuller(1.0, 0.3), 0.0);  // u1 = 1 gives 0, never NaN
}

TEST(KeyedUniforms, InOpenUnitIntervalAndReproducible) {
  for (std::uint64_t sample = 0; sample < 1000; ++sample) {
    const NoiseKey key{42, 3, sample, 0};
    const UniformPair u = KeyedUniforms(key);
    EXPECT_GT(u.u1, 0.0);
    EXPECT_LE(u.u1, 1.0);
    EXPECT_GT(u.u2, 0.0);
    EXPECT_LE(u.u2, 1.0);
    const UniformPair again = KeyedUniforms(key);
    EXPECT_EQ(u.u1, again.u1);
    EXPECT_EQ(u.u2, again.u2);
  }
}

TEST(KeyedGaussian, EveryKeyFieldChangesTheDraw) {
  const NoiseKey base{7, 1, 100, 2};
  std::set<double> draws = {KeyedGaussian(base)};
  NoiseKey k = base;
  k.seed = 8;
  draws.insert(KeyedGaussian(k));
  k = base;
  k.sensor = 2;
  draws.insert(KeyedGaussian(k));
  k = base;
  k.sample = 101;
  draws.insert(KeyedGaussian(k));
  k = base;
  k.ray = 3;
  draws.insert(KeyedGaussian(k));
  k = base;
  k.sample = base.sample + (std::uint64_t{1} << 32);  // the high half of the sample counter counts too
  draws.insert(KeyedGaussian(k));
  EXPECT_EQ(draws.size(), 6u);
}

// 10⁴ draws of G: mean within 4 standard errors of 0 (1/√n = 0.01), variance
// within 4 standard errors of 1 (√(2/n) ≈ 0.0141), and the fraction within one
// σ within 4 binomial standard errors (√(0.683·0.317/n) ≈ 0.0047) of 0.6827.
TEST(KeyedGaussian, IsStandardNormal) {
  double sum = 0, sum_sq = 0;
  int within_one_sigma = 0;
  for (int i = 0; i < kSamples; ++i) {
    const double g = KeyedGaussian({2024, 0, static_cast<std::uint64_t>(i), 0});
    sum += g;
    sum_sq += g * g;
    if (std::abs(g) <= 1.0) ++within_one_sigma;
  }
  const double mean = sum / kSamples;
  const double variance = sum_sq / kSamples - mean * mean;
  EXPECT_NEAR(mean, 0.0, 4 * 0.01);
  EXPECT_NEAR(variance, 1.0, 4 * std::sqrt(2.0 / kSamples));
  EXPECT_NEAR(static_cast<double>(within_one_sigma) / kSamples, 0.6827, 4 * 0.0047);
}

// The laser preset's readings at a fixed distance: d_r = d(1 + σG), so their
// mean is d and their standard deviation σ·d, within the same bounds.
TEST(LaserNoise, ReadingsHaveThePaperSpread) {
  const SensorSpec laser = SensorSpec::Preset(SensorType::kLaser);
  Echo echo;
  echo.distance_m = 1.5;
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < kSamples; ++i) {
    const double d = Measure(laser, echo, KeyedGaussian({99, 1, static_cast<std::uint64_t>(i), 0})).d_m;
    sum += d;
    sum_sq += d * d;
  }
  const double mean = sum / kSamples;
  const double sd = std::sqrt(sum_sq / kSamples - mean * mean);
  const double expected_sd = 0.01 * 1.5;
  EXPECT_NEAR(mean, 1.5, 4 * expected_sd / std::sqrt(kSamples));
  EXPECT_NEAR(sd, expected_sd, 4 * expected_sd / std::sqrt(2.0 * kSamples));
}

}  // namespace
}  // namespace proxsim
