// One shape for what a sensor reports (sensors/measurement.h,
// sensors/sensor_measure.h): the paper's single ray reports only its
// reading; a zone grid lists every zone, its targets ranked, along the
// zone's axis; a beam with several echoes lists them nearest first along its
// axis; the truth list has the same shape with the noise-free distances.
// Echoes are written by hand here (no ray caster), so every value is exact.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sensors/beam.h"
#include "sensors/multizone.h"
#include "sensors/sensor_measure.h"
#include "strategy/stop_strategy.h"

namespace proxsim {
namespace {

Echo EchoAt(double d_m) {
  Echo echo;
  echo.distance_m = d_m;
  return echo;
}

NoiseDraw NoDraw(int) { return NoiseDraw{}; }

// a 2 × 2 grid of one ray per zone, one target per zone, noise off
SensorSpec Grid2x2() {
  SensorSpec spec = SensorSpec::Preset(SensorType::kMultizone);
  spec.zones = ZoneSpec{.nx = 2, .ny = 2, .fov_h_deg = 40, .fov_v_deg = 40, .rays_per_zone = 1, .targets = 1};
  spec.noise.sigma = 0.0;
  return spec;
}

TEST(MeasurementTest, TheSingleRayReportsOnlyItsReading) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kLaser);
  spec.noise.sigma = 0.0;
  const std::vector<Echo> echoes = {EchoAt(0.8)};
  const std::vector<BeamRay> rays = MakeSensorRays(spec);
  SensorMeasurement out;
  MeasureSensorSample(spec, SensorPlacement{}, echoes, rays, NoDraw, out);
  EXPECT_EQ(out.headline.reading.status, ReadingStatus::kOk);
  EXPECT_DOUBLE_EQ(out.headline.reading.d_m, 0.8);
  EXPECT_TRUE(out.measured.empty());
  EXPECT_TRUE(out.truth.empty());
}

TEST(MeasurementTest, AZoneGridListsEveryZoneAlongItsAxisAndTheNearestIsTheReading) {
  const SensorSpec spec = Grid2x2();
  const std::vector<BeamRay> rays = MakeSensorRays(spec);
  ASSERT_EQ(rays.size(), 4u);
  // zone 2 sees nothing within range; the others 1.0, 0.7 and 1.5 m
  const std::vector<Echo> echoes = {EchoAt(1.0), EchoAt(0.7), Echo{}, EchoAt(1.5)};
  std::vector<Vec3> zone_dir_W;
  for (int zone = 0; zone < 4; ++zone) zone_dir_W.push_back(ZoneAxis_S(*spec.zones, zone));
  const SensorPlacement at{.p_WS = Vec3(1, 2, 0.5), .dir_W = Vec3::UnitX(), .zone_dir_W = zone_dir_W};
  SensorMeasurement out;
  MeasureSensorSample(spec, at, echoes, rays, NoDraw, out);

  ASSERT_EQ(out.measured.size(), 4u);
  ASSERT_EQ(out.truth.size(), 4u);
  const double expected_m[] = {1.0, 0.7, spec.max_range_m, 1.5};
  for (std::size_t zone = 0; zone < 4; ++zone) {
    const Measurement& m = out.measured[zone];
    EXPECT_EQ(m.group, static_cast<int>(zone));
    EXPECT_EQ(m.rank, 0);
    EXPECT_EQ(m.detected(), zone != 2) << zone;
    EXPECT_EQ(m.code, zone != 2 ? kZoneRangeValid : kZoneNoTarget) << zone;
    EXPECT_DOUBLE_EQ(m.d_m, expected_m[zone]) << zone;
    EXPECT_EQ(m.dir_W, zone_dir_W[zone]);
    EXPECT_EQ(m.p_WS, at.p_WS);
    // the truth has the same shape; noise off, the same distance
    EXPECT_EQ(out.truth[zone].group, m.group);
    EXPECT_DOUBLE_EQ(out.truth[zone].d_m, m.d_m) << zone;
  }
  // the reading is the nearest target, along its zone's axis
  EXPECT_EQ(out.headline.reading.status, ReadingStatus::kOk);
  EXPECT_DOUBLE_EQ(out.headline.reading.d_m, 0.7);
  EXPECT_EQ(out.headline_dir_W, zone_dir_W[1]);
  EXPECT_EQ(out.headline.ray, 1);
}

TEST(MeasurementTest, AZoneWithTwoTargetsRanksThemAndTheTruthKeepsTheNoiseFreeCentre) {
  SensorSpec spec = Grid2x2();
  spec.zones->nx = spec.zones->ny = 1;
  spec.zones->rays_per_zone = 4;
  spec.zones->targets = 2;
  spec.noise.sigma = 0.01;
  const std::vector<BeamRay> rays = MakeSensorRays(spec);
  // two rays on a box edge at 0.5 m, two on a wall at 1.5 m: two targets, nearest first
  const std::vector<Echo> echoes = {EchoAt(0.5), EchoAt(0.52), EchoAt(1.5), EchoAt(1.5)};
  const std::vector<Vec3> zone_dir_W = {Vec3::UnitX()};
  SensorMeasurement out;
  const auto draw = [](int) { return NoiseDraw{.gaussian_g = 1.0, .uniform = 0.5}; };
  MeasureSensorSample(spec, SensorPlacement{.zone_dir_W = zone_dir_W}, echoes, rays, draw, out);
  ASSERT_EQ(out.measured.size(), 2u);
  EXPECT_EQ(out.measured[0].rank, 0);
  EXPECT_EQ(out.measured[1].rank, 1);
  // the near target: its rays' centre weighed by their signals, 1/d² each (head-on, one albedo)
  const double near_m = (0.5 / (0.5 * 0.5) + 0.52 / (0.52 * 0.52)) / (1 / (0.5 * 0.5) + 1 / (0.52 * 0.52));
  EXPECT_NEAR(out.truth[0].d_m, near_m, 1e-12);
  EXPECT_LT(out.truth[0].d_m, 0.51);  // it leans to the nearer, stronger return
  EXPECT_DOUBLE_EQ(out.truth[1].d_m, 1.5);
  // the reported distances carry the draw (σ = 1 %, G = 1): d·(1 + 0.01)
  EXPECT_NEAR(out.measured[0].d_m, near_m * 1.01, 1e-12);
  EXPECT_NEAR(out.measured[1].d_m, 1.5 * 1.01, 1e-12);
}

TEST(MeasurementTest, ABeamWithSeveralEchoesListsThemNearestFirstAlongItsAxis) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kIdeal);
  spec.beam = BeamSpec{.aperture_deg = 20, .rays = 7};
  spec.echoes = EchoSelection::kAll;
  spec.echo_separation_m = 0.1;
  const std::vector<BeamRay> rays = MakeSensorRays(spec);
  ASSERT_EQ(rays.size(), 7u);
  std::vector<Echo> echoes(rays.size(), EchoAt(1.2));
  echoes[3] = EchoAt(0.6);
  const SensorPlacement at{.p_WS = Vec3(0, 0, 1), .dir_W = Vec3(0, 0, -1)};
  SensorMeasurement out;
  MeasureSensorSample(spec, at, echoes, rays, NoDraw, out);
  ASSERT_EQ(out.measured.size(), 2u);
  EXPECT_DOUBLE_EQ(out.measured[0].d_m, 0.6);
  EXPECT_DOUBLE_EQ(out.measured[1].d_m, 1.2);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(out.measured[k].group, 0);
    EXPECT_EQ(out.measured[k].rank, static_cast<int>(k));
    EXPECT_EQ(out.measured[k].dir_W, at.dir_W);
    EXPECT_GT(out.measured[k].signal, 0.0);
    EXPECT_DOUBLE_EQ(out.truth[k].d_m, out.measured[k].d_m);
  }
  // the reading is the first echo, the paper's beam reading
  EXPECT_DOUBLE_EQ(out.headline.reading.d_m, 0.6);
  EXPECT_EQ(out.headline_dir_W, at.dir_W);
}

}  // namespace
}  // namespace proxsim

namespace proxsim {
namespace {

// The robot at the origin heading +x, its toe at x = 0.1, standing on z = 0.
RobotKnowledge StandingAtOrigin() {
  RobotKnowledge self;
  self.p_W_front = Vec3(0.1, 0, 0);
  self.heading_W = Vec3::UnitX();
  self.ground_z_m = 0.0;
  return self;
}

TEST(MeasurementTest, TheStopRuleSeesARaisedEchoBehindAFloorEcho) {
  // a sonar on the shin pitched down: its reading (first echo) is the floor,
  // its second echo a box edge 0.3 m ahead, 0.1 m up
  SensorOutput sonar;
  sonar.fresh = sonar.detected = true;
  sonar.p_WS = Vec3(0.1, 0, 0.3);
  sonar.dir_W = Vec3(1, 0, -1).normalized();
  sonar.d_m = 0.3 * std::sqrt(2.0);  // the floor at x = 0.4
  const Vec3 box_W(0.4, 0, 0.1);
  const Vec3 to_box = box_W - sonar.p_WS;
  sonar.measurements = {
      Measurement{.p_WS = sonar.p_WS, .dir_W = sonar.dir_W, .d_m = sonar.d_m, .status = ReadingStatus::kOk, .rank = 0},
      Measurement{.p_WS = sonar.p_WS, .dir_W = to_box.normalized(), .d_m = to_box.norm(), .status = ReadingStatus::kOk,
                  .rank = 1}};
  const SensorInfo info{.name = "sonar", .type = SensorType::kUltrasonic, .max_range_m = 1.0};
  const StopConfig rule;
  const std::optional<Vec3> seen = ObstaclePointAhead(sonar, info, StandingAtOrigin(), rule);
  ASSERT_TRUE(seen.has_value());
  EXPECT_NEAR((*seen - box_W).norm(), 0.0, 1e-12);
  // without its second echo, the floor alone is no obstacle
  sonar.measurements.resize(1);
  EXPECT_FALSE(ObstaclePointAhead(sonar, info, StandingAtOrigin(), rule).has_value());
}

}  // namespace
}  // namespace proxsim

namespace proxsim {
namespace {

// A VL53L5CX (8x8, DS13754's ranges: a 17 % target to 1.3 m in the inner
// zones) sees a grey (ρ = 0.5) surface 1.5 m away in every ray. Facing it,
// the surface is a target of 0.5, seen to ≈ 2.6 m: every zone valid. Met at
// 80° (a floor far ahead), it returns ρ·cos θ = 0.087 of the light, seen to
// 1.3·√(0.087/0.17) ≈ 0.93 m: every zone "signal rate too low" (ST's 8).
TEST(MeasurementTest, AGrazingSurfaceFallsBelowTheSignalAPartNeedsWhereAFacingOneDoesNot) {
  const SensorSpec spec = *SensorSpec::PartPreset("vl53l5cx");
  const std::vector<BeamRay> rays = MakeSensorRays(spec);
  std::vector<Vec3> zone_dir_W;
  for (int zone = 0; zone < ZoneCount(*spec.zones); ++zone) zone_dir_W.push_back(ZoneAxis_S(*spec.zones, zone));
  const SensorPlacement at{.zone_dir_W = zone_dir_W};
  const auto zones_valid = [&](double incidence_deg) {
    Echo echo = EchoAt(1.5);
    echo.ir_albedo = 0.5;
    echo.incidence_deg = incidence_deg;
    const std::vector<Echo> echoes(rays.size(), echo);
    SensorMeasurement out;
    MeasureSensorSample(spec, at, echoes, rays, NoDraw, out);
    int valid = 0, too_low = 0;
    for (const Measurement& m : out.measured) {
      valid += m.code == kZoneRangeValid;
      too_low += m.code == kZoneSignalTooLow;
    }
    return std::pair{valid, too_low};
  };
  EXPECT_EQ(zones_valid(0.0), (std::pair{64, 0}));
  EXPECT_EQ(zones_valid(80.0), (std::pair{0, 64}));
}

}  // namespace
}  // namespace proxsim

namespace proxsim {
namespace {

// The single-zone ST parts take the incidence into their range the same way:
// a VL53L1X in long mode (UM2356: a 17 % target to about 1.7 m in the dark)
// sees a grey (ρ = 0.5) surface 1.5 m away facing it, and not when met at 80°
// (ρ·cos 80° = 0.087: about 1.2 m), where the paper's incidence window alone
// would have let it echo.
TEST(MeasurementTest, ASingleZonePartsRangeFallsWithIncidence) {
  SensorSpec spec = *SensorSpec::PartPreset("vl53l1x");
  spec.max_incidence_deg = 90;  // only the range decides
  Echo echo = EchoAt(1.5);
  echo.ir_albedo = 0.5;
  EXPECT_EQ(EchoStatus(spec, echo, 1.0), ReadingStatus::kOk);
  echo.incidence_deg = 80;
  EXPECT_EQ(EchoStatus(spec, echo, 1.0), ReadingStatus::kNoEcho);
  EXPECT_NEAR(IncidentReflectance(spec, echo), 0.5 * std::cos(80 * M_PI / 180), 1e-12);
  // a surface met at a ray's own angle off the axis is as bright as the datasheet's facing target
  echo.incidence_deg = 12.5;
  EXPECT_NEAR(IncidentReflectance(spec, echo, 12.5), 0.5, 1e-12);
}

}  // namespace
}  // namespace proxsim
