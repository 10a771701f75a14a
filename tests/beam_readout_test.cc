// What a beam reports (docs/sensors.md#what-a-beam-reports): ST's
// single-zone time-of-flight parts (VL53L0X, VL53L1X) read their rays'
// returns weighed by the signal each carries — w·ρ·cos θ / d², w the ray's
// weight in the pattern — resolved into one target as a multi-zone zone
// resolves its own (echo_groups.h); sonars and the paper's models keep the
// first echo back. The expected values are written here from the rays'
// weights and the geometry; the runs go through the ray caster, so they are
// compared within 1e-5 m, never exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "sensors/beam.h"
#include "sensors/sensor_model.h"
#include "sensors/sensor_spec.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::ReadCsv;
using testing::RowsOf;
using testing::RunScenarioYaml;

// a part's preset without noise or rounding: the reading is the model's centre itself
SensorSpec NoiselessPart(const std::string& part) {
  SensorSpec spec = *SensorSpec::PartPreset(part);
  spec.noise.sigma = 0.0;
  spec.noise.resolution_m = 0.0;
  spec.sigma_table.clear();
  return spec;
}

// one ray's echo off a flat face across the beam at x = x_m, facing the sensor:
// the ray meets it at t = x / cos θ, at incidence θ (its angle off the axis)
Echo FaceEcho(const BeamRay& ray, double x_m, double ir_albedo) {
  Echo echo;
  echo.distance_m = x_m / ray.dir_S.x();
  echo.incidence_deg = ray.off_axis_deg;
  echo.ir_albedo = ir_albedo;
  return echo;
}

// A face at x = near_x_m over the rays that lean to +y past near_edge (a box's
// edge, y/x > near_edge), a wall at x = far_x_m behind the others.
struct EdgeAndWall {
  double near_x_m = 0.8, near_albedo = 0.88;
  double far_x_m = 2.0, far_albedo = 0.5;
  double near_edge = 0.025;
  bool OnNear(const BeamRay& ray) const { return ray.dir_S.y() / ray.dir_S.x() > near_edge; }
  std::vector<Echo> Echoes(const std::vector<BeamRay>& rays) const {
    std::vector<Echo> echoes;
    for (const BeamRay& ray : rays)
      echoes.push_back(OnNear(ray) ? FaceEcho(ray, near_x_m, near_albedo) : FaceEcho(ray, far_x_m, far_albedo));
    return echoes;
  }
};

// the signal-weighted centre of the rays' echoes, each weighing w·ρ·cos θ / t²
// (the rays for which `use` is true)
template <typename Use>
double WeighedCentre_m(const std::vector<BeamRay>& rays, const std::vector<Echo>& echoes, Use use) {
  double sum_weighted_m = 0, sum_weight = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (!use(i)) continue;
    const double t = echoes[i].distance_m;
    const double signal = rays[i].weight * echoes[i].ir_albedo * std::cos(echoes[i].incidence_deg * M_PI / 180) / (t * t);
    sum_weighted_m += signal * t;
    sum_weight += signal;
  }
  return sum_weighted_m / sum_weight;
}

// the ray of the nearest echo (the lowest index of equal ones)
int NearestRay(const std::vector<Echo>& echoes) {
  int nearest = 0;
  for (std::size_t i = 1; i < echoes.size(); ++i)
    if (echoes[i].distance_m < echoes[nearest].distance_m) nearest = static_cast<int>(i);
  return nearest;
}

NoiseDraw NoReadoutDraw(int) { return NoiseDraw{}; }

TEST(BeamReadoutTest, StsSingleZonePartsWeighTheirReturnsAndSonarsAndThePapersModelsTakeTheFirstEcho) {
  EXPECT_EQ(SensorSpec::PartPreset("vl53l0x")->beam_readout, BeamReadout::kSignalWeighted);
  EXPECT_EQ(SensorSpec::PartPreset("vl53l1x")->beam_readout, BeamReadout::kSignalWeighted);
  EXPECT_TRUE(std::isinf(SensorSpec::PartPreset("vl53l1x")->beam_target_separation_m));
  EXPECT_EQ(SensorSpec::PartPreset("hc_sr04")->beam_readout, BeamReadout::kFirstEcho);
  for (SensorType type : {SensorType::kIdeal, SensorType::kLaser, SensorType::kUltrasonic, SensorType::kReflectance})
    EXPECT_EQ(SensorSpec::Preset(type).beam_readout, BeamReadout::kFirstEcho) << SensorTypeName(type);
}

// A VL53L1X's 19 rays straddle a bright box edge 0.8 m ahead and a grey wall
// 2 m ahead: one target (the part does not separate them) at the centre of
// the 19 returns weighed by their signal — not the box's nearest ray, which
// the first echo would read.
TEST(BeamReadoutTest, ABeamStraddlingANearEdgeAndAFarWallReadsTheSignalWeightedCentre) {
  const SensorSpec spec = NoiselessPart("vl53l1x");
  const std::vector<BeamRay> rays = MakeBeamRays(spec.beam);
  ASSERT_EQ(rays.size(), 19u);
  const EdgeAndWall scene;
  const std::vector<Echo> echoes = scene.Echoes(rays);
  const double expected_m = WeighedCentre_m(rays, echoes, [](std::size_t) { return true; });
  const int nearest = NearestRay(echoes);

  const BeamReading beam = MeasureBeam(spec, echoes, rays, NoReadoutDraw);
  EXPECT_EQ(beam.reading.status, ReadingStatus::kOk);
  EXPECT_NEAR(beam.reading.d_m, expected_m, 1e-12);
  EXPECT_EQ(beam.ray, nearest);
  EXPECT_EQ(beam.truth_ray, nearest);
  // the first echo would read the box's nearest ray; the weighted centre lies
  // well past it, yet nearer than the plain mean (the box returns more)
  const double first_echo_m = echoes[static_cast<std::size_t>(nearest)].distance_m;
  EXPECT_GT(beam.reading.d_m, first_echo_m + 0.1) << "the first-echo rule is back";
  double plain_mean_m = 0;
  for (const Echo& echo : echoes) plain_mean_m += echo.distance_m / static_cast<double>(echoes.size());
  EXPECT_LT(beam.reading.d_m, plain_mean_m);

  // a separation as a histogram part's (600 mm) splits the edge from the
  // wall: the nearest target, the box's rays alone
  SensorSpec split = spec;
  split.beam_target_separation_m = 0.6;
  const double box_m = WeighedCentre_m(rays, echoes, [&](std::size_t i) { return scene.OnNear(rays[i]); });
  EXPECT_NEAR(MeasureBeam(split, echoes, rays, NoReadoutDraw).reading.d_m, box_m, 1e-12);

  // the paper's laser given the same beam keeps the first echo
  SensorSpec laser = SensorSpec::Preset(SensorType::kLaser);
  laser.noise.sigma = 0.0;
  laser.beam = spec.beam;
  EXPECT_EQ(MeasureBeam(laser, echoes, rays, NoReadoutDraw).reading.d_m, first_echo_m);
}

// The noise is the part's, once, from the draw of the target's nearest ray
// (keyed per ray as before: no other ray's draw is asked for), and a
// dropout loses the reading.
TEST(BeamReadoutTest, TheNoiseComesOnceFromTheTargetsNearestRaysDraw) {
  SensorSpec spec = NoiselessPart("vl53l1x");
  spec.noise.sigma = 0.02;  // additive, m
  const std::vector<BeamRay> rays = MakeBeamRays(spec.beam);
  const std::vector<Echo> echoes = EdgeAndWall{}.Echoes(rays);
  const int nearest = NearestRay(echoes);
  std::vector<int> asked;
  const DrawOfRay draw = [&](int ray) {
    asked.push_back(ray);
    return NoiseDraw{.gaussian_g = 1.5, .uniform = 0.5};
  };
  const BeamReading beam = MeasureBeam(spec, echoes, rays, draw);
  EXPECT_EQ(asked, std::vector<int>{nearest});
  const double centre_m = WeighedCentre_m(rays, echoes, [](std::size_t) { return true; });
  EXPECT_NEAR(beam.reading.d_m, centre_m + 0.02 * 1.5, 1e-12);

  spec.noise.dropout = 0.6;
  const BeamReading lost = MeasureBeam(spec, echoes, rays, draw);
  EXPECT_EQ(lost.reading.status, ReadingStatus::kDropout);
  EXPECT_EQ(lost.ray, -1);
}

// The robot's own body makes no target (as in a zone); a beam that meets
// only the robot reads `self`, as its first echo would; rays that do not
// count (beyond range) weigh nothing.
TEST(BeamReadoutTest, TheRobotsOwnBodyAndRaysThatDoNotCountMakeNoTarget) {
  const SensorSpec spec = NoiselessPart("vl53l0x");
  const std::vector<BeamRay> rays = MakeBeamRays(spec.beam);
  const EdgeAndWall scene{.near_x_m = 0.3, .near_albedo = 1.0, .far_x_m = 1.2, .far_albedo = 0.88};
  std::vector<Echo> echoes = scene.Echoes(rays);
  for (std::size_t i = 0; i < rays.size(); ++i) echoes[i].from_robot = scene.OnNear(rays[i]);
  const auto off_robot = [&](std::size_t i) { return !echoes[i].from_robot; };
  const BeamReading beam = MeasureBeam(spec, echoes, rays, NoReadoutDraw);
  EXPECT_EQ(beam.reading.status, ReadingStatus::kOk);
  EXPECT_NEAR(beam.reading.d_m, WeighedCentre_m(rays, echoes, off_robot), 1e-12);

  for (Echo& echo : echoes) echo.from_robot = true;
  const BeamReading self = MeasureBeam(spec, echoes, rays, NoReadoutDraw);
  EXPECT_EQ(self.reading.status, ReadingStatus::kSelf);
  EXPECT_EQ(self.ray, NearestRay(echoes));

  // the wall beyond the part's 2 m: only the box's rays count
  std::vector<Echo> far = EdgeAndWall{.far_x_m = 2.5}.Echoes(rays);
  const BeamReading near_only = MeasureBeam(spec, far, rays, NoReadoutDraw);
  EXPECT_NEAR(near_only.reading.d_m,
              WeighedCentre_m(rays, far, [&](std::size_t i) { return EdgeAndWall{}.OnNear(rays[i]); }), 1e-12);
  // a surface touching the emitter (a range from 0 m) returns without bound: it is the reading
  SensorSpec from_zero = spec;
  from_zero.min_range_m = 0.0;
  far[0].distance_m = 0.0;
  EXPECT_EQ(MeasureBeam(from_zero, far, rays, NoReadoutDraw).reading.d_m, 0.0);
  // nothing within range: no_echo, as before
  const std::vector<Echo> nothing(rays.size());
  EXPECT_EQ(MeasureBeam(spec, nothing, rays, NoReadoutDraw).reading.status, ReadingStatus::kNoEcho);
}

// Through the ray caster. A scenario of one sensor at (0, 0, 1) looking
// along +x, one sample; `objects` the scene's objects.
fs::path RunOneBeam(const std::string& name, const std::string& part, const std::string& objects) {
  return RunScenarioYaml(name, R"(proxsim: 1
duration_s: 0.1
rate_hz: 10
scene:
  objects:
)" + objects + R"(sensors:
  - {name: tof, type: )" + part + R"(, noise: {sigma: 0, resolution_m: 0}, pose: {xyz_m: [0, 0, 1]}}
)");
}

// A wall facing the part head-on, x_m ahead: every ray meets it at x / cos θ
// at incidence θ, so the reading is x·Σw·cos²θ / Σw·cos³θ — the plane's
// distance within the cone's spread of path lengths: within 2 % (1.3 % for
// the VL53L0X's 25° cone, 1.6 % for the VL53L1X's 27°).
TEST(BeamReadoutRun, APartFacingAWallHeadOnReadsTheWallsDistance) {
  for (const std::string part : {"vl53l0x", "vl53l1x"}) {
    const std::vector<BeamRay> rays = MakeBeamRays(SensorSpec::PartPreset(part)->beam);
    double sum_cos2 = 0, sum_cos3 = 0;
    for (const BeamRay& ray : rays) {
      sum_cos2 += ray.weight * std::pow(ray.dir_S.x(), 2);
      sum_cos3 += ray.weight * std::pow(ray.dir_S.x(), 3);
    }
    for (const double x_m : {0.3, 1.2}) {
      const fs::path out = RunOneBeam("beam_readout_wall_" + part + std::to_string(static_cast<int>(x_m * 10)), part,
                                      "    - {name: wall, plane: {}, pose: {xyz_m: [" + std::to_string(x_m) +
                                          ", 0, 0], rpy_deg: [0, -90, 0]}, material: {albedo: 0.88}}\n");
      const auto rows = RowsOf(ReadCsv(out / "readings.csv"), "tof");
      ASSERT_EQ(rows.size(), 1u);
      EXPECT_EQ(rows[0].at("status"), "ok");
      const double d_m = std::stod(rows[0].at("d_m"));
      EXPECT_NEAR(d_m, x_m * sum_cos2 / sum_cos3, 1e-5) << part << " at " << x_m;
      EXPECT_NEAR(d_m / x_m, 1.0, 0.02) << part << " at " << x_m;
    }
  }
}

// The box edge and the wall of the test above, cast: a bright box (ρ 0.88)
// whose face lies 0.8 m ahead and whose edge runs 0.02 m to the left of the
// axis, a grey wall (ρ 0.5) 2 m ahead. The reading is the centre the rays'
// weights and signals give, computed here; the first echo (the box's
// nearest ray) is far from it.
TEST(BeamReadoutRun, ABeamStraddlingABoxEdgeAndAFarWallReadsTheirSignalWeightedCentre) {
  const fs::path out = RunOneBeam("beam_readout_edge", "vl53l1x",
                                  "    - {name: wall, plane: {}, pose: {xyz_m: [2, 0, 0], rpy_deg: [0, -90, 0]}, "
                                  "material: {albedo: 0.5}}\n"
                                  "    - {name: box, box: {size_m: [0.1, 2, 2]}, pose: {xyz_m: [0.85, 1.02, 1]}, "
                                  "material: {albedo: 0.88}}\n");
  const std::vector<BeamRay> rays = MakeBeamRays(SensorSpec::PartPreset("vl53l1x")->beam);
  const EdgeAndWall scene;  // y/x > 0.025 at x = 0.8: the edge at y = 0.02
  const std::vector<Echo> echoes = scene.Echoes(rays);
  const double expected_m = WeighedCentre_m(rays, echoes, [](std::size_t) { return true; });
  const auto rows = RowsOf(ReadCsv(out / "readings.csv"), "tof");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at("status"), "ok");
  const double d_m = std::stod(rows[0].at("d_m"));
  EXPECT_NEAR(d_m, expected_m, 1e-5);
  // the row's ray and truth: the target's nearest ray, on the box (by its
  // distance: rays mirrored about the axis tie, and which one a CPU's float
  // path finds nearer may differ)
  const int nearest = NearestRay(echoes);
  const int ray = std::stoi(rows[0].at("ray"));
  ASSERT_GE(ray, 0);
  EXPECT_NEAR(echoes[static_cast<std::size_t>(ray)].distance_m, echoes[static_cast<std::size_t>(nearest)].distance_m, 1e-5);
  EXPECT_EQ(rows[0].at("object"), "box");
  EXPECT_GT(d_m, echoes[static_cast<std::size_t>(nearest)].distance_m + 0.1) << "the first-echo rule is back";
}

}  // namespace
}  // namespace proxsim
