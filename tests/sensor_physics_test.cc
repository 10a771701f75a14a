// Sensor physics beyond the paper (docs/sensors.md): beams, materials, the physical
// echo model, lookup sensors, timing and noise variants. Expected values are
// computed here with trigonometry and the formulas docs/sensors.md states; noise
// laws are checked statistically with bounds stated next to each test.
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "core/input_error.h"
#include "scenario/scenario.h"
#include "sensors/beam.h"
#include "sensors/noise.h"
#include "sensors/sensor_model.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

// A world-mounted sensor at the origin facing a wall whose face is the plane x = wall_m.
std::string WallScenario(double wall_m, const std::string& sensors, const std::string& material = "{albedo: 1}") {
  std::ostringstream text;
  text << "proxsim: 1\nseed: 3\nduration_s: 0.1\nrate_hz: 10\n"
       << "scene:\n  objects:\n"
       << "    - name: wall\n      box: {size_m: [0.1, 6, 4]}\n"
       << "      pose: {xyz_m: [" << wall_m + 0.05 << ", 0, 0]}\n"
       << "      material: " << material << "\n"
       << "sensors:\n" << sensors;
  return text.str();
}

// The first sample's reading of every sensor of a scenario.
std::vector<SensorSample> FirstSample(const std::string& text) {
  const Scenario scenario = LoadScenarioText(text, "physics.yaml");
  Simulation sim(scenario, 1);
  return sim.Step().sensors;
}

// --- beams -----------------------------------------------------------------

TEST(BeamLayout, OneAxisRayWithoutABeam) {
  const auto rays = MakeBeamRays(std::nullopt);
  ASSERT_EQ(rays.size(), 1u);
  EXPECT_EQ(rays[0].dir_S, Vec3::UnitX());
  EXPECT_EQ(rays[0].weight, 1.0);
}

TEST(BeamLayout, CoversTheConeEvenlyUpToItsEdge) {
  const BeamSpec beam{.aperture_deg = 30.0, .rays = 37, .pattern = BeamPattern::kUniform, .width_deg = 10, .table = {}};
  const auto rays = MakeBeamRays(beam);
  ASSERT_EQ(rays.size(), 37u);
  double weight_sum = 0, max_off_axis = 0;
  Vec3 centroid = Vec3::Zero();
  for (const BeamRay& ray : rays) {
    EXPECT_NEAR(ray.dir_S.norm(), 1.0, 1e-12);
    const double off_axis = RadToDeg(std::acos(std::min(1.0, ray.dir_S.x())));
    EXPECT_NEAR(off_axis, ray.off_axis_deg, 1e-9);
    max_off_axis = std::max(max_off_axis, off_axis);
    weight_sum += ray.weight;
    centroid += ray.weight * ray.dir_S;
  }
  EXPECT_NEAR(weight_sum, 1.0, 1e-12);
  EXPECT_NEAR(max_off_axis, 15.0, 1e-9);  // the outer ring is the cone's edge
  EXPECT_NEAR(centroid.y(), 0.0, 1e-12);  // symmetric about the axis
  EXPECT_NEAR(centroid.z(), 0.0, 1e-12);
  // the uniform weights are the solid angles: the cone's 2π(1 − cos 15°) shared out,
  // so the axis ray (the cap up to 2.5°) weighs (1 − cos 2.5°)/(1 − cos 15°)
  const double cap = (1 - std::cos(DegToRad(2.5))) / (1 - std::cos(DegToRad(15.0)));
  EXPECT_NEAR(rays[0].weight, cap, 1e-12);
}

TEST(BeamLayout, PatternsGiveTheirGains) {
  BeamSpec beam{.aperture_deg = 60.0, .rays = 19, .pattern = BeamPattern::kGaussian, .width_deg = 10.0, .table = {}};
  EXPECT_NEAR(BeamGain(beam, 10.0), std::exp(-0.5), 1e-15);
  EXPECT_NEAR(BeamGain(beam, 20.0), std::exp(-2.0), 1e-15);
  beam.pattern = BeamPattern::kTable;
  beam.table = {{0, 2.0}, {10, 1.0}, {30, 0.0}};  // relative to its largest gain, 2
  EXPECT_NEAR(BeamGain(beam, 0.0), 1.0, 1e-15);
  EXPECT_NEAR(BeamGain(beam, 5.0), 0.75, 1e-15);
  EXPECT_NEAR(BeamGain(beam, 20.0), 0.25, 1e-15);
  EXPECT_NEAR(BeamGain(beam, 45.0), 0.0, 1e-15);
  // a gaussian beam's outer rays weigh less than its inner ones
  beam.pattern = BeamPattern::kGaussian;
  const auto rays = MakeBeamRays(beam);
  EXPECT_LT(rays.back().gain, rays[1].gain);
}

// A cone turned θ away from the wall's normal detects at the distance of its
// nearest echoing edge ray: the edge ray at θ − aperture/2 from the normal
// hits at D / cos(θ − aperture/2), with that incidence. The single ray at θ
// sees the wall at D / cos θ but at an incidence beyond the 15° window.
TEST(BeamTimeOfFlight, ConeFacingAWallAtAnAngleDetectsAtItsNearestEdgeRay) {
  const double wall_m = 1.0;
  for (const double yaw_deg : {20.0, 25.0, 28.0}) {
    std::ostringstream sensors;
    for (const char* name : {"cone", "ray"}) {
      sensors << "  - name: " << name << "\n    type: ultrasonic\n    range_m: [0.1, 3]\n    noise: {sigma: 0}\n"
              << "    pose: {rpy_deg: [0, 0, " << yaw_deg << "]}\n";
      if (std::string(name) == "cone") sensors << "    beam: {aperture_deg: 30, rays: 37}\n";
    }
    const auto samples = FirstSample(WallScenario(wall_m, sensors.str()));
    const SensorSample& cone = samples[0];
    const SensorSample& ray = samples[1];
    const double edge_deg = yaw_deg - 15.0;
    ASSERT_EQ(cone.reading.status, ReadingStatus::kOk) << yaw_deg;
    EXPECT_NEAR(cone.reading.d_m, wall_m / std::cos(DegToRad(edge_deg)), 2e-6) << yaw_deg;
    EXPECT_NEAR(cone.echo.incidence_deg, edge_deg, 1e-3) << yaw_deg;
    EXPECT_GE(cone.ray, 1 + 6 + 12) << "an outer-ring ray";  // rings of 6, 12 and 18 rays
    EXPECT_NEAR(cone.p_WH.x(), wall_m, 1e-5);
    EXPECT_EQ(ray.reading.status, ReadingStatus::kGrazing) << yaw_deg;
    EXPECT_EQ(ray.ray, -1);
    EXPECT_NEAR(ray.echo.distance_m, wall_m / std::cos(DegToRad(yaw_deg)), 2e-6);
  }
}

// A cone whose every ray is beyond the window is grazing, like its single ray.
TEST(BeamTimeOfFlight, ConeEntirelyOutsideTheWindowIsGrazing) {
  const auto samples = FirstSample(WallScenario(
      1.0, "  - name: cone\n    type: ultrasonic\n    range_m: [0.1, 3]\n    pose: {rpy_deg: [0, 0, 35]}\n"
           "    beam: {aperture_deg: 30, rays: 37}\n"));
  EXPECT_EQ(samples[0].reading.status, ReadingStatus::kGrazing);
  EXPECT_EQ(samples[0].ray, -1);
}

// A narrow cone is the single ray: every sensor type, several angles. Its
// rays are at most δ = 0.0005° off the axis, so the distance to a wall turned
// θ away may differ by d·tan θ·δ (plus the caster's float rounding).
TEST(BeamTimeOfFlight, NarrowConeEqualsTheSingleRay) {
  for (const char* type : {"ideal", "laser", "ultrasonic", "reflectance"}) {
    for (const double yaw_deg : {0.0, 10.0, 30.0, 50.0}) {
      std::ostringstream sensors;
      for (const bool cone : {true, false}) {
        sensors << "  - name: " << (cone ? "cone" : "ray") << "\n    type: " << type
                << "\n    noise: {sigma: 0}\n    pose: {rpy_deg: [0, 0, " << yaw_deg << "]}\n";
        if (cone) sensors << "    beam: {aperture_deg: 0.001, rays: 19}\n";
      }
      const auto samples = FirstSample(WallScenario(0.5, sensors.str()));
      EXPECT_EQ(samples[0].reading.status, samples[1].reading.status) << type << " " << yaw_deg;
      const double bound = samples[1].reading.d_m * std::tan(DegToRad(yaw_deg)) * DegToRad(0.0005) + 1e-6;
      EXPECT_NEAR(samples[0].reading.d_m, samples[1].reading.d_m, bound) << type << " " << yaw_deg;
      if (std::string(type) == "reflectance" && samples[1].reading.detected()) {
        EXPECT_NEAR(samples[0].reading.signal / samples[1].reading.signal, 1.0, 1e-5) << yaw_deg;
      }
    }
  }
}

// The reflectance cone sums weighted signals: facing a wall square-on, ray k
// at θ_k hits at d_k = D/cos θ_k with incidence θ_k, so
// s = Σ w_k (d_max − d_k)/d_k² cos²θ_k, inverted with the paper's root.
TEST(BeamReflectance, SumsTheWeightedSignalsOfItsRays) {
  const double wall_m = 0.4, d_max = 1.0;
  const auto samples = FirstSample(WallScenario(
      wall_m, "  - name: spot\n    type: reflectance\n    noise: {sigma: 0}\n"
              "    beam: {aperture_deg: 40, rays: 19, pattern: {gaussian: {width_deg: 8}}}\n"));
  const BeamSpec beam{.aperture_deg = 40, .rays = 19, .pattern = BeamPattern::kGaussian, .width_deg = 8, .table = {}};
  double expected_s = 0;
  for (const BeamRay& ray : MakeBeamRays(beam)) {
    const double theta = DegToRad(ray.off_axis_deg);
    const double d = wall_m / std::cos(theta);
    expected_s += ray.weight * (d_max - d) / (d * d) * std::cos(theta) * std::cos(theta);
  }
  ASSERT_TRUE(samples[0].reading.detected());
  EXPECT_NEAR(samples[0].reading.signal, expected_s, 1e-5 * expected_s);
  EXPECT_NEAR(samples[0].reading.d_m, 2 * d_max / (1 + std::sqrt(1 + 4 * expected_s * d_max)), 1e-6);
  EXPECT_EQ(samples[0].ray, 0);  // the axis ray gives the largest weighted signal
}

// --- materials ---------------------------------------------------------------

// s = ρ·(d_max − d)/d²·cos²α with use_material; two albedos at the same
// distance read as two distances, the darker one farther.
TEST(Materials, ReflectanceOfTwoAlbedosAtEqualDistance) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kReflectance);
  spec.use_material = true;
  const double d = 0.3, d_max = spec.max_range_m;
  for (const double albedo : {0.2, 0.9}) {
    Echo echo;
    echo.distance_m = d;
    echo.ir_albedo = albedo;
    const Reading reading = Measure(spec, echo, 0.0);
    const double s = albedo * (d_max - d) / (d * d);
    EXPECT_NEAR(reading.signal, s, 1e-12);
    EXPECT_NEAR(reading.d_m, 2 * d_max / (1 + std::sqrt(1 + 4 * s * d_max)), 1e-12);
    EXPECT_GT(reading.d_m, d) << "a surface darker than white reads farther";
  }
  // without use_material the paper's formula ignores the albedo
  spec.use_material = false;
  Echo dark;
  dark.distance_m = d;
  dark.ir_albedo = 0.2;
  EXPECT_NEAR(Measure(spec, dark, 0.0).d_m, d, 1e-12);
}

// The scene's material reaches the reading: ir_albedo overrides albedo.
TEST(Materials, SceneMaterialReachesTheReflectanceSensor) {
  const std::string sensors =
      "  - {name: paper, type: reflectance, noise: {sigma: 0}}\n"
      "  - {name: material, type: reflectance, noise: {sigma: 0}, use_material: true}\n";
  const double d = 0.3;
  const auto samples = FirstSample(WallScenario(d, sensors, "{albedo: 0.9, ir_albedo: 0.25}"));
  EXPECT_NEAR(samples[0].reading.d_m, d, 1e-6);
  const double s = 0.25 * (1.0 - d) / (d * d);
  EXPECT_NEAR(samples[1].reading.signal, s, 1e-5 * s);
  EXPECT_NEAR(samples[1].echo.ir_albedo, 0.25, 0);
}

// The physical echo model: E = r((1 − s)cos α + s·max(0, cos 2α)^n) >= threshold.
// A rough (diffuse) surface echoes up to α = acos(threshold); a smooth one
// only near the normal.
TEST(Materials, PhysicalEchoRoughSurfaceEchoesAtWiderAnglesThanSmooth) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kUltrasonic);
  spec.echo_model = EchoModel::kPhysical;
  spec.echo_threshold = 0.5;
  spec.specular_exponent = 20;
  auto widest_echo_deg = [&](double specular) {
    double widest = -1;
    for (int tenth = 0; tenth <= 900; ++tenth) {
      Echo echo;
      echo.distance_m = 0.5;
      echo.incidence_deg = tenth / 10.0;
      echo.specular = specular;
      if (Measure(spec, echo, 0.0).detected()) widest = echo.incidence_deg;
    }
    return widest;
  };
  const double rough = widest_echo_deg(0.0);
  const double smooth = widest_echo_deg(0.9);
  EXPECT_NEAR(rough, 60.0, 0.1);  // cos α >= 0.5
  EXPECT_GT(smooth, 0.0);
  EXPECT_LT(smooth, 15.0);
  EXPECT_GT(rough, smooth);
  // an acoustically dead surface returns nothing
  Echo absorbed;
  absorbed.distance_m = 0.5;
  absorbed.acoustic_reflectivity = 0.3;
  EXPECT_EQ(Measure(spec, absorbed, 0.0).status, ReadingStatus::kGrazing);
  // the window model (the paper) ignores all of it
  spec.echo_model = EchoModel::kWindow;
  EXPECT_TRUE(Measure(spec, absorbed, 0.0).detected());
}

// --- lookup sensors ------------------------------------------------------------

TEST(Lookup, ReproducesItsTableAtTheTablePointsAndInterpolatesBetween) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kLookup);
  spec.lookup_table = {{0.1, 1000, 0}, {0.5, 600, 0}, {1.0, 100, 0}};
  spec.min_range_m = 0.1;
  spec.max_range_m = 1.0;
  ASSERT_TRUE(spec.Validate().empty());
  for (const LookupRow& row : spec.lookup_table) {
    Echo echo;
    echo.distance_m = row.distance_m;
    const Reading reading = Measure(spec, echo, 1.7);  // no noise column: G is ignored
    EXPECT_EQ(reading.output, row.output);
    EXPECT_NEAR(reading.d_m, row.distance_m, 1e-12);
  }
  Echo between;
  between.distance_m = 0.75;
  EXPECT_NEAR(Measure(spec, between, 0.0).output, 350.0, 1e-9);
  // out of the table: its last row beyond (and on a miss), its first before
  Echo miss;
  const Reading far = Measure(spec, miss, 0.0);
  EXPECT_EQ(far.status, ReadingStatus::kNoEcho);
  EXPECT_EQ(far.output, 100.0);
  Echo near;
  near.distance_m = 0.05;
  EXPECT_EQ(Measure(spec, near, 0.0).output, 1000.0);
  EXPECT_EQ(Measure(spec, near, 0.0).status, ReadingStatus::kTooClose);
}

// Webots' noise: σ = fraction·output.
TEST(Lookup, NoiseIsTheTablesFractionOfTheOutput) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kLookup);
  spec.lookup_table = {{0.0, 2.0, 0.1}, {1.0, 1.0, 0.1}};
  spec.max_range_m = 1.0;
  Echo echo;
  echo.distance_m = 0.5;
  EXPECT_NEAR(Measure(spec, echo, 2.0).output, 1.5 + 2.0 * 0.1 * 1.5, 1e-12);
}

// The Sharp GP2Y0A21 preset: the datasheet's 2.3 V at 10 cm and 0.4 V at
// 80 cm, and the non-monotonic curve: an object at 4 cm gives the output of
// 8 cm, and the far-branch reading says 8 cm.
TEST(Lookup, SharpPresetIsNonMonotonicAsItsDatasheet) {
  const auto sharp = SensorSpec::PartPreset("sharp_gp2y0a21");
  ASSERT_TRUE(sharp.has_value());
  EXPECT_TRUE(sharp->Validate().empty());
  SensorSpec spec = *sharp;
  for (auto& row : spec.lookup_table) row.noise_fraction = 0;
  spec.min_range_m = 0.0;
  auto at = [&](double d) {
    Echo echo;
    echo.distance_m = d;
    return Measure(spec, echo, 0.0);
  };
  EXPECT_NEAR(at(0.10).output, 2.30, 1e-12);
  EXPECT_NEAR(at(0.80).output, 0.40, 1e-12);
  EXPECT_NEAR(at(0.04).output, at(0.08).output, 1e-12);
  EXPECT_NEAR(at(0.04).d_m, 0.08, 1e-12);
  EXPECT_NEAR(at(0.30).d_m, 0.30, 1e-12);
  for (const auto& name : SensorSpec::PartNames()) EXPECT_TRUE(SensorSpec::PartPreset(name)->Validate().empty()) << name;
}

// --- timing ----------------------------------------------------------------------

// Moving straight at the surface at v, the echo returns at τ = 2d/(c + v) and
// the sensor reports c·τ/2 = d·c/(c + v): shorter by v·τ/2, half the distance
// it moved during the flight (only the way back is shortened).
TEST(FlightTime, MovingSensorShiftsByHalfTheDistanceMovedDuringTheFlight) {
  const double c = 343.0, d = 1.0;
  for (const double v : {-2.0, 0.5, 1.0, 3.0}) {
    const Vec3 p_WS = Vec3::Zero();
    const Vec3 v_W(v, 0, 0);
    const double shift = FlightTimeShift(p_WS, v_W, Vec3(d, 0, 0), d, c);
    const double tau = 2 * d / (c + v);
    EXPECT_NEAR(d + shift, d * c / (c + v), 1e-12) << v;
    EXPECT_NEAR(shift, -v * tau / 2, 1e-12) << v;
  }
  // sideways at v: the way back is √(d² + (vτ)²)
  const double v = 2.0;
  const double shift = FlightTimeShift(Vec3::Zero(), Vec3(0, v, 0), Vec3(d, 0, 0), d, c);
  const double tau = (2 * d + shift * 2) / c;
  EXPECT_NEAR(2 * (d + shift), d + std::hypot(d, v * tau), 1e-12);
  EXPECT_GT(shift, 0);
  // light: nothing measurable
  EXPECT_LT(std::abs(FlightTimeShift(Vec3::Zero(), Vec3(3, 0, 0), Vec3(d, 0, 0), d, 299792458.0)), 1e-7);
}

// On the walking robot, the swinging tibia moves during the ultrasonic
// flight: with flight_time the reading differs from the same sensor without,
// by the shift FlightTimeShift gives for the sensor's velocity over the sample.
TEST(FlightTime, WalkingRobotUltrasonicReadingShiftsWithTheLegsVelocity) {
  const std::string text =
      "proxsim: 1\nseed: 1\nduration_s: 3.0\nrate_hz: 100\nscene: {builtin: dining_room}\n"
      "robot: {model: builtin:biped, path: {waypoints_m: [[0, 0], [4.5, 0]]}}\n"
      "sensors:\n"
      "  - {name: plain, type: ideal, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 15, 0]}}\n"
      "  - {name: flight, type: ideal, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 15, 0]},\n"
      "     flight_time: true, wave_speed_m_s: 343}\n";
  const Scenario scenario = LoadScenarioText(text, "flight.yaml");
  Simulation sim(scenario, 1);
  Vec3 p_previous = Vec3::Zero();
  int compared = 0;
  double largest_shift = 0;
  while (!sim.done()) {
    const SampleFrame& frame = sim.Step();
    const SensorSample& plain = frame.sensors[0];
    const SensorSample& flight = frame.sensors[1];
    if (frame.sample > 0 && plain.reading.detected() && flight.reading.detected()) {
      const Vec3 v_W = (plain.p_WS - p_previous) * scenario.rate_hz;
      const double shift = FlightTimeShift(plain.p_WS, v_W, plain.p_WH, plain.echo.distance_m, 343.0);
      EXPECT_NEAR(flight.reading.d_m - plain.reading.d_m, shift, 1e-9) << frame.t_s;
      largest_shift = std::max(largest_shift, std::abs(shift));
      ++compared;
    }
    p_previous = plain.p_WS;
  }
  EXPECT_GT(compared, 100);
  EXPECT_GT(largest_shift, 0.002) << "a swinging tibia moves millimetres during a 343 m/s flight";
}

// rate_hz: a 30 Hz sensor in a 100 Hz run samples once per period; latency
// reports later and the strategy sees it then.
TEST(Timing, SensorRateAndLatency) {
  const std::string text = WallScenario(
      0.5, "  - {name: fast, type: ideal}\n  - {name: slow, type: ideal, rate_hz: 30, latency_s: 0.025}\n");
  Scenario scenario = LoadScenarioText(text, "timing.yaml");
  scenario.duration_s = 1.0;
  scenario.rate_hz = 100;
  Simulation sim(scenario, 1);
  int fast = 0, slow = 0, delivered = 0;
  double last_slow_t = -1;
  std::vector<double> slow_times;
  while (!sim.done()) {
    const SampleFrame& frame = sim.Step();
    fast += frame.sensors[0].reading.status != ReadingStatus::kNotSampled;
    const SensorSample& s = frame.sensors[1];
    if (s.reading.status != ReadingStatus::kNotSampled) {
      ++slow;
      slow_times.push_back(frame.t_s);
      EXPECT_NEAR(s.t_reported_s, frame.t_s + 0.025, 1e-12);
      last_slow_t = frame.t_s;
    }
    const SensorSample& seen = sim.delivered().sensors[1];
    if (seen.reading.status != ReadingStatus::kNotSampled) {
      ++delivered;
      // delivered at the first run sample at or after its report time
      EXPECT_GE(frame.t_s + 1e-9, seen.t_reported_s);
      EXPECT_LT(frame.t_s, seen.t_reported_s + 0.01);
    }
  }
  EXPECT_EQ(fast, 100);
  EXPECT_EQ(slow, 30);  // periods 0..29 of 1/30 s in [0, 1)
  for (std::size_t k = 0; k < slow_times.size(); ++k) {
    // the first run sample at or after k/30 s
    EXPECT_NEAR(slow_times[k], std::ceil(k * 100.0 / 30.0 - 1e-9) / 100.0, 1e-12) << k;
  }
  EXPECT_EQ(delivered, slow - (last_slow_t + 0.025 > 0.99 + 1e-9 ? 1 : 0));
}

// --- noise variants ----------------------------------------------------------------

// The draws of n keys, as the simulation makes them.
std::vector<NoiseDraw> Draws(int n, bool with_uniform) {
  std::vector<NoiseDraw> draws;
  for (int k = 0; k < n; ++k) {
    const NoiseKey key{11, 2, static_cast<std::uint64_t>(k), 0};
    NoiseKey dropout_key = key;
    dropout_key.ray |= 0x80000000u;
    draws.push_back({KeyedGaussian(key), with_uniform ? KeyedUniforms(dropout_key).u1 : 1.0});
  }
  return draws;
}

// Sample mean and standard deviation of d_r for n keyed draws. With n = 40000
// the mean's standard error is σ_d/200, so |mean − expected| < 5·σ_d/200; the
// standard deviation's relative standard error is 1/√(2n) ≈ 0.35 %, so 2 %.
struct Moments {
  double mean = 0, sd = 0;
};
Moments ReadingMoments(const SensorSpec& spec, double d, int n) {
  double sum = 0, sum2 = 0;
  int count = 0;
  for (const NoiseDraw& draw : Draws(n, false)) {
    Echo echo;
    echo.distance_m = d;
    const Reading r = Measure(spec, echo, draw.gaussian_g, draw.uniform);
    sum += r.d_m;
    sum2 += r.d_m * r.d_m;
    ++count;
  }
  const double mean = sum / count;
  return {mean, std::sqrt(sum2 / count - mean * mean)};
}

TEST(NoiseVariants, EachLawHasItsMeanAndSpread) {
  const int n = 40000;
  const double d = 1.5;
  SensorSpec spec = SensorSpec::Preset(SensorType::kLaser);
  struct Case {
    NoiseModel model;
    double sigma, mean, expected_mean, expected_sd;
  };
  const Case cases[] = {
      {NoiseModel::kMultiplicative, 0.02, 0.01, d * 1.01, d * 0.02},
      {NoiseModel::kAdditive, 0.01, -0.005, d - 0.005, 0.01},
      {NoiseModel::kDistanceScaled, 0.01, 0.0, d, 0.01 * d * d},
  };
  for (const Case& c : cases) {
    spec.noise.model = c.model;
    spec.noise.sigma = c.sigma;
    spec.noise.mean = c.mean;
    const Moments m = ReadingMoments(spec, d, n);
    EXPECT_NEAR(m.mean, c.expected_mean, 5 * c.expected_sd / std::sqrt(n)) << NoiseModelName(c.model);
    EXPECT_NEAR(m.sd, c.expected_sd, 0.02 * c.expected_sd) << NoiseModelName(c.model);
  }
}

TEST(NoiseVariants, ResolutionQuantisesTheReading) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kLaser);
  spec.noise.resolution_m = 0.005;
  for (const NoiseDraw& draw : Draws(2000, false)) {
    Echo echo;
    echo.distance_m = 0.7321;
    const double d = Measure(spec, echo, draw.gaussian_g).d_m;
    EXPECT_NEAR(d / 0.005, std::round(d / 0.005), 1e-9);
    EXPECT_LE(std::abs(d - 0.7321 * (1 + 0.01 * draw.gaussian_g)), 0.0025 + 1e-12);
  }
}

// A dropout probability p loses a fraction p of the detections: with n =
// 40000 the fraction's standard error is √(p(1−p)/n) ≈ 0.0018 at p = 0.2; 5 of them.
TEST(NoiseVariants, DropoutLosesItsFractionOfDetections) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kUltrasonic);
  spec.noise.dropout = 0.2;
  const int n = 40000;
  int dropped = 0;
  for (const NoiseDraw& draw : Draws(n, true)) {
    Echo echo;
    echo.distance_m = 0.5;
    const Reading r = Measure(spec, echo, draw.gaussian_g, draw.uniform);
    if (r.status == ReadingStatus::kDropout) {
      ++dropped;
      EXPECT_EQ(r.d_m, spec.max_range_m);
    }
  }
  EXPECT_NEAR(dropped / double(n), 0.2, 5 * std::sqrt(0.2 * 0.8 / n));
}

// --- the scenario file -------------------------------------------------------------

TEST(SensorPhysicsScenario, EveryKeyParses) {
  const std::string text = WallScenario(
      1.0,
      "  - name: us\n    type: ultrasonic\n"
      "    beam: {aperture_deg: 40, rays: 19, pattern: {table: [[0, 1], [10, 0.5], [20, 0]]}}\n"
      "    echo_model: physical\n    echo_threshold: 0.3\n    specular_exponent: 8\n"
      "    noise: {model: additive, sigma: 0.002, mean: 0.001, resolution_m: 0.001, dropout: 0.05}\n"
      "    rate_hz: 20\n    latency_s: 0.03\n    flight_time: true\n"
      "  - name: sharp\n    type: sharp_gp2y0a21\n"
      "  - name: table\n    type: lookup\n    lookup_table: [[0.2, 5, 0.01], [1.2, 1, 0.02]]\n"
      "  - {name: ir, type: reflectance, use_material: true, beam: {aperture_deg: 10, rays: 7, pattern: uniform}}\n",
      "{albedo: 0.5, specular: 0.2, ir_albedo: 0.4, acoustic_reflectivity: 0.7}");
  const Scenario scenario = LoadScenarioText(text, "keys.yaml");
  const SensorConfig& us = scenario.sensors[0];
  ASSERT_TRUE(us.spec.beam.has_value());
  EXPECT_EQ(us.spec.beam->rays, 19);
  EXPECT_EQ(us.spec.beam->pattern, BeamPattern::kTable);
  EXPECT_EQ(us.spec.beam->table.size(), 3u);
  EXPECT_EQ(us.spec.echo_model, EchoModel::kPhysical);
  EXPECT_EQ(us.spec.echo_threshold, 0.3);
  EXPECT_EQ(us.spec.specular_exponent, 8);
  EXPECT_EQ(us.spec.noise.model, NoiseModel::kAdditive);
  EXPECT_EQ(us.spec.noise.resolution_m, 0.001);
  EXPECT_EQ(us.spec.noise.dropout, 0.05);
  EXPECT_EQ(us.rate_hz, 20);
  EXPECT_EQ(us.latency_s, 0.03);
  EXPECT_TRUE(us.flight_time);
  EXPECT_EQ(scenario.sensors[1].spec.part, "sharp_gp2y0a21");
  EXPECT_EQ(scenario.sensors[1].spec.type, SensorType::kLookup);
  EXPECT_EQ(scenario.sensors[2].spec.min_range_m, 0.2);  // the table's range
  EXPECT_EQ(scenario.sensors[2].spec.max_range_m, 1.2);
  EXPECT_TRUE(scenario.sensors[3].spec.use_material);
  const Material& material = scenario.scene.objects.back().material;
  EXPECT_EQ(material.ir_albedo, 0.4);
  EXPECT_EQ(material.acoustic_reflectivity, 0.7);
}

TEST(SensorPhysicsScenario, BadValuesAreReportedAtTheirKeys) {
  const std::string text = WallScenario(
      1.0,
      "  - name: bad\n    type: reflectance\n"
      "    beam: {aperture_deg: 200, rays: 0, pattern: {gaussian: {width_deg: -1}}}\n"
      "    echo_model: physical\n    flight_time: true\n"
      "    noise: {model: distance_scaled, dropout: 2}\n"
      "  - name: table\n    type: lookup\n    lookup_table: [[0.5, 1, 0], [0.2, 2, 0]]\n"
      "  - {name: p, type: ultrasonic, beam: {aperture_deg: 20, pattern: cardioid}}\n",
      "{albedo: 0.5, ir_albedo: 1.5}");
  std::vector<std::string> problems;
  try {
    LoadScenarioText(text, "bad.yaml");
  } catch (const InputError& error) {
    problems = error.problems();
  }
  std::string all;
  for (const auto& p : problems) all += p + "\n";
  for (const char* key : {"sensors[0].beam.aperture_deg", "sensors[0].beam.rays", "sensors[0].beam.pattern.gaussian.width_deg",
                          "sensors[0].echo_model", "sensors[0].flight_time", "sensors[0].noise.model",
                          "sensors[0].noise.dropout", "sensors[1].lookup_table[1][0]", "sensors[2].beam.pattern",
                          "objects[0].material.ir_albedo"}) {
    EXPECT_NE(all.find(key), std::string::npos) << key << " in\n" << all;
  }
}

// --- end to end: the shipped comparison scenario ---------------------------------------

// The cone sees the obstacle earlier than the single ray, and sees floor the
// single ray never does; readings.csv says which ray gave each echo.
TEST(SensorPhysicsCli, ConeVsRayScenarioRunsEndToEnd) {
  const auto out = testing::FreshDir("cone_vs_ray");
  const std::string scenario = std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/ultrasonic_cone_vs_ray.yaml";
  const auto result = testing::RunProxsim("run " + scenario + " --out " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream summary_file(out / "summary.json");
  const auto summary = nlohmann::json::parse(summary_file);
  const auto& sensors = summary.at("sensors");
  const double ray_first = sensors.at("us_ray").at("first_detection_t_s").at("obstacle").get<double>();
  const double cone_first = sensors.at("us_cone").at("first_detection_t_s").at("obstacle").get<double>();
  EXPECT_LT(cone_first, ray_first);
  EXPECT_FALSE(sensors.at("us_ray").at("detections_by_object").contains("floor"));
  EXPECT_GT(sensors.at("us_cone").at("detections_by_object").value("floor", 0), 0);

  const auto rows = testing::ReadCsv(out / "readings.csv").rows;
  int off_axis = 0;
  for (const auto& row : rows) {
    if (row.at("sensor") == "us_cone" && row.at("status") == "ok" && std::stoi(row.at("ray")) > 0) ++off_axis;
    if (row.at("sensor") == "us_ray") EXPECT_EQ(row.at("ray"), row.at("status") == "ok" || row.at("status") == "self" ? "0" : "-1");
  }
  EXPECT_GT(off_axis, 0);
}

}  // namespace
}  // namespace proxsim
