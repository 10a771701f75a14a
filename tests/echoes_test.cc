// Several echoes of one ping (`echoes: first | strongest | all`,
// docs/sensors.md#several-echoes): a sonar facing a thin pole before a wall
// hears the pole on its axis ray and on the two rays of its 10° ring that lie
// in the pole's plane (φ = 90°, 270°; the 5° ring's rays, 60° apart, pass
// 21 mm beside the pole's axis, outside its 15 mm half-width), and the wall
// on every other ray. Closed forms written here: the echoes' distances (the
// pole's face; the wall's nearest ray, 5° off the axis: 1.5 m / cos 5°) and
// signals (those rays' shares of the beam's solid angle, and the rest times
// the wall's reflectivity).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "npy_read.h"
#include "sensors/beam.h"
#include "sensors/beam_echoes.h"
#include "sensors/sensor_spec.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::RunScenarioYaml;
using testing::LoadNpy;
using testing::ReadCsv;
using testing::RowsOf;
using testing::RunProxsim;

constexpr double kPoleFace_m = 0.485;  // a 3 cm pole centred 0.5 m ahead
constexpr double kWall_m = 1.5;       // the wall's face

// the 37-ray, 30° cone's rings of 6, 12 and 18 rays lie at 5°, 10° and 15°
// (beam.h); the axis ray stands for the cap out to half the ring step (2.5°)
// of the cone's 15° cap, a ray of the 10° ring for 1/12 of the band 7.5°–12.5°
double Cos(double deg) { return std::cos(deg * std::numbers::pi / 180); }
double PoleSignal() { return ((1 - Cos(2.5)) + 2 * (Cos(7.5) - Cos(12.5)) / 12) / (1 - Cos(15)); }

std::string PoleBeforeWall(const std::string& echoes, double wall_reflectivity) {
  return "proxsim: 1\nduration_s: 0.2\nrate_hz: 10\nscene:\n  objects:\n"
         "    - {name: pole, box: {size_m: [0.03, 0.03, 2]}, pose: {xyz_m: [0.5, 0, 1]}}\n"
         "    - {name: wall, box: {size_m: [0.02, 4, 3]}, pose: {xyz_m: [1.51, 0, 1]}, "
         "material: {albedo: 0.5, acoustic_reflectivity: " + std::to_string(wall_reflectivity) + "}}\n"
         "sensors:\n  - {name: sonar, type: ultrasonic, range_m: [0.02, 3], max_incidence_deg: 20, "
         "noise: {sigma: 0}, beam: {aperture_deg: 30, rays: 37}, echoes: " + echoes + ", pose: {xyz_m: [0, 0, 1]}}\n";
}

std::vector<double> ReadDistances(const fs::path& out) {
  std::vector<double> d;
  for (const auto& row : RowsOf(ReadCsv(out / "readings.csv"), "sonar")) d.push_back(std::stod(row.at("d_m")));
  return d;
}

TEST(EchoesRun, AllHearsThePoleThenTheWallInOrder) {
  const fs::path out = RunScenarioYaml("echoes_all", PoleBeforeWall("all", 1.0));
  const auto d = LoadNpy(out / "echoes" / "sonar" / "d_m.npy");
  const auto signal = LoadNpy(out / "echoes" / "sonar" / "signal.npy");
  const auto count = LoadNpy(out / "echoes" / "sonar" / "count.npy");
  ASSERT_EQ(d.shape.size(), 2u);
  ASSERT_GT(d.shape[0], 0);
  EXPECT_EQ(d.shape[1], 4);
  EXPECT_EQ(signal.shape, d.shape);
  const double w0 = PoleSignal();
  for (long k = 0; k < d.shape[0]; ++k) {
    EXPECT_EQ(count.values[k], 2.0) << k;
    EXPECT_NEAR(d.values[4 * k + 0], kPoleFace_m, 1e-6);
    EXPECT_NEAR(d.values[4 * k + 1], kWall_m / std::cos(5 * std::numbers::pi / 180), 1e-6);
    EXPECT_TRUE(std::isnan(d.values[4 * k + 2]) && std::isnan(d.values[4 * k + 3]));
    EXPECT_NEAR(signal.values[4 * k + 0], w0, 1e-6);
    EXPECT_NEAR(signal.values[4 * k + 1], 1 - w0, 1e-6);
  }
  // the reading is the first echo; the folder is described
  for (const double d_m : ReadDistances(out)) EXPECT_NEAR(d_m, kPoleFace_m, 1e-6);
  std::ifstream columns(out / "echoes" / "columns.json");
  const nlohmann::json json = nlohmann::json::parse(columns);
  EXPECT_EQ(json["sensors"]["sonar"]["echoes"], "all");
  EXPECT_EQ(json["columns"].size(), 4u);
}

TEST(EchoesRun, StrongestPicksTheWallWhenItReturnsMoreAndThePoleOtherwise) {
  // the wall's 34 rays return (1 − w0)·1 against the pole's w0
  for (const double d_m : ReadDistances(RunScenarioYaml("echoes_strongest", PoleBeforeWall("strongest", 1.0)))) {
    EXPECT_NEAR(d_m, kWall_m / std::cos(5 * std::numbers::pi / 180), 1e-6);
  }
  // a wall that returns 2 % of the sound: (1 − w0)·0.02 < w0
  ASSERT_LT((1 - PoleSignal()) * 0.02, PoleSignal());
  for (const double d_m : ReadDistances(RunScenarioYaml("echoes_strongest_soft", PoleBeforeWall("strongest", 0.02)))) {
    EXPECT_NEAR(d_m, kPoleFace_m, 1e-6);
  }
  // first is the pole, and writes no echoes/
  const fs::path first = RunScenarioYaml("echoes_first", PoleBeforeWall("first", 1.0));
  for (const double d_m : ReadDistances(first)) EXPECT_NEAR(d_m, kPoleFace_m, 1e-6);
  EXPECT_FALSE(fs::exists(first / "echoes"));
}

// echoes closer than the separation merge; at most 4 are kept, nearest first
TEST(EchoesTest, EchoesSplitAtTheSeparationAndKeepFourNearestFirst) {
  SensorSpec spec = SensorSpec::Preset(SensorType::kIdeal);
  spec.beam = BeamSpec{.aperture_deg = 10, .rays = 7};
  spec.echo_separation_m = 0.1;
  const std::vector<BeamRay> rays = MakeBeamRays(spec.beam);
  ASSERT_EQ(rays.size(), 7u);
  std::vector<Echo> echoes(7);
  const double d[7] = {1.95, 0.50, 0.55, 0.90, 1.20, 1.40, 1.62};  // 0.50 and 0.55 merge
  for (int i = 0; i < 7; ++i) echoes[i].distance_m = d[i];
  const auto all = BeamEchoes(spec, echoes, rays, kMaxEchoes);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[0].d_m, 0.50);
  EXPECT_EQ(all[0].ray, 1);
  EXPECT_NEAR(all[0].signal, rays[1].weight + rays[2].weight, 1e-15);
  EXPECT_EQ(all[1].d_m, 0.90);
  EXPECT_EQ(all[2].d_m, 1.20);
  EXPECT_EQ(all[3].d_m, 1.40);
  // beyond the range (2 m for the ideal preset) nothing is heard
  echoes[0].distance_m = 2.5;
  EXPECT_EQ(BeamEchoes(spec, echoes, rays, 100).size(), 5u);
}

// the bad inputs: exit 2, naming the key, the limit and its source
TEST(EchoesRun, BadEchoesAreRefusedNamingTheLimitAndItsSource) {
  testing::ExpectRefused("echoes_bad",
      "proxsim: 1\nsensors:\n"
      "  - {name: a, type: hc_sr04, echoes: all}\n"
      "  - {name: b, type: laser, echoes: strongest}\n"
      "  - {name: c, type: reflectance, echoes: all}\n"
      "  - {name: d, type: ultrasonic, beam: {aperture_deg: 30, rays: 7}, echoes: most}\n"
      "  - {name: e, type: vl53l5cx, echoes: all}\n"
      "  - {name: f, type: ultrasonic, beam: {aperture_deg: 30, rays: 7}, echoes: all, "
      "echo_separation_m: 0}\n"
      "  - {name: g, type: vl53l0x, echoes: strongest}\n",
      {"sensors[0].echoes: expected first for a hc_sr04, which reports one echo (HC-SR04 datasheet",
      "sensors[1].echoes: expected first for a sensor of one ray", "sensors[2].echoes: expected first for a reflectance",
      "sensors[3].echoes: expected first, strongest or all, got 'most'",
      "sensors[4].echoes: expected first for a multizone sensor", "sensors[5].echo_separation_m: expected a finite separation > 0 m",
      "sensors[6].echoes: expected first for a vl53l0x, which reports one echo (VL53L0X datasheet DocID029104"});
}

}  // namespace
}  // namespace proxsim
