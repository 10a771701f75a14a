// The paper's sensor models (§4–§5): windows, formulas and statuses, checked
// against values computed here from the paper's equations.
#include "sensors/sensor_model.h"

#include <cmath>

#include <gtest/gtest.h>

namespace proxsim {
namespace {

constexpr double kNoNoise = 0.0;  // G = 0 with m = 0 gives N = 0

Echo EchoAt(double d_m, double incidence_deg = 0.0) {
  Echo echo;
  echo.distance_m = d_m;
  echo.incidence_deg = incidence_deg;
  return echo;
}

TEST(SensorPreset, PaperValues) {
  const SensorSpec laser = SensorSpec::Preset(SensorType::kLaser);
  EXPECT_EQ(laser.min_range_m, 0.0);
  EXPECT_EQ(laser.max_range_m, 2.0);
  EXPECT_EQ(laser.max_incidence_deg, 45.0);
  EXPECT_EQ(laser.noise.sigma, 0.01);
  const SensorSpec us = SensorSpec::Preset(SensorType::kUltrasonic);
  EXPECT_EQ(us.min_range_m, 0.1);
  EXPECT_EQ(us.max_range_m, 1.0);
  EXPECT_EQ(us.max_incidence_deg, 15.0);
  const SensorSpec refl = SensorSpec::Preset(SensorType::kReflectance);
  EXPECT_EQ(refl.max_range_m, 1.0);
  EXPECT_EQ(refl.max_incidence_deg, 90.0);
  const SensorSpec ideal = SensorSpec::Preset(SensorType::kIdeal);
  EXPECT_EQ(ideal.noise.sigma, 0.0);
  for (auto type : {SensorType::kIdeal, SensorType::kLaser, SensorType::kUltrasonic, SensorType::kReflectance}) {
    EXPECT_TRUE(SensorSpec::Preset(type).Validate().empty()) << SensorTypeName(type);
  }
}

TEST(SensorPreset, TypeNamesRoundTrip) {
  for (const auto& name : SensorTypeNames()) {
    ASSERT_TRUE(SensorTypeFromName(name).has_value()) << name;
    EXPECT_EQ(name, SensorTypeName(*SensorTypeFromName(name)));
  }
  EXPECT_FALSE(SensorTypeFromName("sonar").has_value());
}

TEST(SensorSpecValidate, ListsEveryProblemAtOnce) {
  SensorSpec spec;
  spec.min_range_m = 2.0;
  spec.max_range_m = 1.0;  // inverted
  spec.max_incidence_deg = 95.0;
  spec.noise.sigma = -0.1;
  spec.noise.mean = std::nan("");
  const auto problems = spec.Validate();
  ASSERT_EQ(problems.size(), 4u);
  EXPECT_NE(problems[0].find("range_m"), std::string::npos);
  EXPECT_NE(problems[1].find("max_incidence_deg"), std::string::npos);
  EXPECT_NE(problems[2].find("noise.sigma"), std::string::npos);
  EXPECT_NE(problems[3].find("noise.mean"), std::string::npos);
}

// Each preset just inside and just outside its range and incidence limits.
class SensorWindows : public ::testing::TestWithParam<SensorType> {};

TEST_P(SensorWindows, RangeAndIncidenceLimits) {
  SensorSpec spec = SensorSpec::Preset(GetParam());
  spec.noise = {};  // exact readings, so the windows alone decide
  const double eps = 1e-9;
  const double d_mid = 0.5 * (spec.min_range_m + spec.max_range_m);

  // inside both windows: a detection
  EXPECT_EQ(Measure(spec, EchoAt(d_mid), kNoNoise).status, ReadingStatus::kOk);

  // just beyond d_max: no echo, reads d_max
  Reading far = Measure(spec, EchoAt(spec.max_range_m + eps), kNoNoise);
  EXPECT_EQ(far.status, ReadingStatus::kNoEcho);
  EXPECT_EQ(far.d_m, spec.max_range_m);
  EXPECT_FALSE(far.detected());

  // nothing hit at all
  EXPECT_EQ(Measure(spec, Echo{}, kNoNoise).status, ReadingStatus::kNoEcho);

  // just inside d_min, and just outside it when there is a dead zone
  EXPECT_EQ(Measure(spec, EchoAt(spec.min_range_m + 1e-6), kNoNoise).status, ReadingStatus::kOk);
  if (spec.min_range_m > 0) {
    Reading near = Measure(spec, EchoAt(spec.min_range_m - eps), kNoNoise);
    EXPECT_EQ(near.status, ReadingStatus::kTooClose);
    EXPECT_EQ(near.d_m, spec.max_range_m);
  }

  // the incidence window [0, α*]
  EXPECT_EQ(Measure(spec, EchoAt(d_mid, spec.max_incidence_deg - 1e-6), kNoNoise).status, ReadingStatus::kOk);
  if (spec.max_incidence_deg < 90.0) {
    Reading grazing = Measure(spec, EchoAt(d_mid, spec.max_incidence_deg + 1e-6), kNoNoise);
    EXPECT_EQ(grazing.status, ReadingStatus::kGrazing);
    EXPECT_EQ(grazing.d_m, spec.max_range_m);
  }
}

INSTANTIATE_TEST_SUITE_P(AllPresets, SensorWindows,
                         ::testing::Values(SensorType::kIdeal, SensorType::kLaser, SensorType::kUltrasonic,
                                           SensorType::kReflectance),
                         [](const auto& info) { return std::string(SensorTypeName(info.param)); });

TEST(TimeOfFlight, ScalesDistanceByOnePlusNoise) {
  const SensorSpec laser = SensorSpec::Preset(SensorType::kLaser);  // σ = 0.01, m = 0
  const double g = 1.7;
  Reading r = Measure(laser, EchoAt(1.2, 30.0), g);
  EXPECT_EQ(r.status, ReadingStatus::kOk);
  EXPECT_DOUBLE_EQ(r.d_m, 1.2 * (1.0 + 0.01 * g));
  EXPECT_TRUE(std::isnan(r.signal));

  SensorSpec biased = laser;
  biased.noise = {0.02, 0.05};
  EXPECT_DOUBLE_EQ(Measure(biased, EchoAt(1.0), -0.5).d_m, 1.0 * (1.0 + 0.02 * -0.5 + 0.05));
}

TEST(Reflectance, InversionReturnsDistanceAtNormalIncidenceWithoutNoise) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kReflectance);
  spec.noise = {};
  for (double d : {0.01, 0.05, 0.2, 0.5, 0.8, 0.99}) {
    Reading r = Measure(spec, EchoAt(d, 0.0), kNoNoise);
    EXPECT_EQ(r.status, ReadingStatus::kOk);
    EXPECT_NEAR(r.d_m, d, 1e-12) << "d = " << d;
  }
}

TEST(Reflectance, SignalAndDistanceFollowEquationOne) {
  const SensorSpec spec = SensorSpec::Preset(SensorType::kReflectance);  // d_max = 1, σ = 0.01
  const double d_max = spec.max_range_m;
  struct Row {
    double d_m, alpha_deg, g;
  };
  for (const Row row : {Row{0.3, 0.0, 0.0}, Row{0.3, 40.0, 0.0}, Row{0.6, 60.0, 1.0}, Row{0.1, 80.0, -2.0},
                        Row{0.9, 20.0, 0.5}}) {
    // Eq. (1) and the §5 inversion, written out here
    const double n = 0.01 * row.g;
    const double cos_a = std::cos(row.alpha_deg * M_PI / 180.0);
    const double s = (d_max - row.d_m) / (row.d_m * row.d_m) * cos_a * cos_a * (1.0 + n);
    const double d_r = (-1.0 + std::sqrt(1.0 + 4.0 * s * d_max)) / (2.0 * s);

    Reading r = Measure(spec, EchoAt(row.d_m, row.alpha_deg), row.g);
    EXPECT_NEAR(r.signal, s, 1e-12 * s);
    EXPECT_NEAR(r.d_m, d_r, 1e-9);
    // an oblique surface returns less light, so the sensor believes it farther
    if (row.alpha_deg > 0 && row.g == 0) EXPECT_GT(r.d_m, row.d_m);
  }
}

TEST(Reflectance, NonPositiveSignalReadsMaxRange) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kReflectance);
  // noise N ≤ −1 drives s ≤ 0: no light, d_r = d_max
  spec.noise = {0.0, -1.0};
  Reading r = Measure(spec, EchoAt(0.5), kNoNoise);
  EXPECT_EQ(r.status, ReadingStatus::kNoEcho);
  EXPECT_EQ(r.d_m, spec.max_range_m);
  EXPECT_EQ(r.signal, 0.0);
  // at exactly d_max the signal is zero
  spec.noise = {};
  EXPECT_EQ(Measure(spec, EchoAt(spec.max_range_m), kNoNoise).status, ReadingStatus::kNoEcho);
}

TEST(SelfEcho, FlaggedAndNotADetection) {
  Echo echo = EchoAt(0.4);
  echo.from_robot = true;
  for (auto type : {SensorType::kLaser, SensorType::kReflectance}) {
    Reading r = Measure(SensorSpec::Preset(type), echo, kNoNoise);
    EXPECT_EQ(r.status, ReadingStatus::kSelf);
    EXPECT_FALSE(r.detected());
    EXPECT_NEAR(r.d_m, 0.4, 1e-12);
  }
}

TEST(Incidence, AngleBetweenReversedRayAndNormalTwoSided) {
  EXPECT_NEAR(IncidenceDeg(1, 0, 0, -1, 0, 0), 0.0, 1e-12);
  EXPECT_NEAR(IncidenceDeg(1, 0, 0, 1, 0, 0), 0.0, 1e-12);  // back face: same angle
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  // a ray pitched 30° down onto a floor meets it at 60° from the normal
  EXPECT_NEAR(IncidenceDeg(c, 0, -s, 0, 0, 1), 60.0, 1e-9);
  EXPECT_NEAR(IncidenceDeg(0, 1, 0, 1, 0, 0), 90.0, 1e-9);
}

TEST(StatusNames, AreTheDocumentedOnes) {
  EXPECT_STREQ(ReadingStatusName(ReadingStatus::kOk), "ok");
  EXPECT_STREQ(ReadingStatusName(ReadingStatus::kNoEcho), "no_echo");
  EXPECT_STREQ(ReadingStatusName(ReadingStatus::kTooClose), "too_close");
  EXPECT_STREQ(ReadingStatusName(ReadingStatus::kGrazing), "grazing");
  EXPECT_STREQ(ReadingStatusName(ReadingStatus::kSelf), "self");
}

// The draws are made on demand: one ray's at most per reading, none without
// an echo that counts, and the reading is the one every draw up front gives.
TEST(LazyDraws, OneDrawPerReadingAtMostAndTheSameReading) {
  const BeamSpec beam{.aperture_deg = 30.0, .rays = 7, .pattern = BeamPattern::kUniform, .width_deg = 10, .table = {}};
  const std::vector<BeamRay> rays = MakeBeamRays(beam);
  std::vector<NoiseDraw> draws(rays.size());
  for (std::size_t i = 0; i < draws.size(); ++i) draws[i] = {0.3 * static_cast<double>(i) - 1.0, 0.5};

  for (SensorType type : {SensorType::kLaser, SensorType::kUltrasonic, SensorType::kReflectance}) {
    SensorSpec spec = SensorSpec::Preset(type);
    spec.noise.dropout = 0.25;
    // echoes that count at different distances, and one that does not (beyond range)
    std::vector<Echo> echoes;
    for (std::size_t i = 0; i < rays.size(); ++i) echoes.push_back(EchoAt(0.9 - 0.1 * static_cast<double>(i % 4)));
    echoes[3] = Echo{};
    int calls = 0;
    const DrawOfRay counting = [&](int ray) {
      ++calls;
      return draws[static_cast<std::size_t>(ray)];
    };
    const BeamReading lazy = MeasureBeam(spec, echoes, rays, counting);
    const BeamReading eager = MeasureBeam(spec, echoes, rays, std::span<const NoiseDraw>(draws));
    EXPECT_EQ(calls, 1) << SensorTypeName(type);
    EXPECT_EQ(lazy.reading.status, eager.reading.status) << SensorTypeName(type);
    EXPECT_EQ(lazy.reading.d_m, eager.reading.d_m) << SensorTypeName(type);
    EXPECT_EQ(lazy.ray, eager.ray) << SensorTypeName(type);

    // nothing within range: no draw at all
    calls = 0;
    const std::vector<Echo> nothing(rays.size());
    EXPECT_EQ(MeasureBeam(spec, nothing, rays, counting).reading.status, ReadingStatus::kNoEcho);
    EXPECT_EQ(Measure(spec, Echo{}, counting).status, ReadingStatus::kNoEcho);
    EXPECT_EQ(calls, 0) << SensorTypeName(type);
  }
}

}  // namespace
}  // namespace proxsim
