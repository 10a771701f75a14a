// An optical part's range by the target's reflectance and the ambient light
// (sensors/range_table.h): the VL53L0X's datasheet points (DocID029104
// Table 11) come back exactly, the laws between and beyond them in closed
// form, and a run sees a white wall that a grey one at the same distance, or
// the same wall in daylight, hides.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_helpers.h"
#include "sensors/range_table.h"
#include "strategy/strategy.h"
#include "knowledge/ray_evidence.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::RunProxsim;

SensorSpec Vl53l0x(double ambient_klux) {
  SensorSpec spec = *SensorSpec::PartPreset("vl53l0x");
  spec.ambient_klux = ambient_klux;
  return spec;
}

TEST(RangeTableTest, TheDatasheetsPointsComeBackAtItsReflectancesAndLight) {
  // Table 11, typical: white 88 % / grey 17 %, indoor (0) / outdoor overcast (5 klux)
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l0x(0), 0.88), 2.0, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l0x(0), 0.17), 0.8, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l0x(5), 0.88), 0.8, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l0x(5), 0.17), 0.5, 1e-12);
}

TEST(RangeTableTest, BetweenAndBeyondThePointsTheLawsHold) {
  // d² linear in ρ between the rows
  const double u = (0.5 - 0.17) / (0.88 - 0.17);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l0x(0), 0.5), std::sqrt(0.64 + u * (4.0 - 0.64)), 1e-12);
  // below the darkest row d ∝ √ρ; above the brightest the same, capped at the part's 2 m
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l0x(0), 0.05), 0.8 * std::sqrt(0.05 / 0.17), 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l0x(5), 1.0), 0.8 * std::sqrt(1.0 / 0.88), 1e-12);
  EXPECT_EQ(ReflectanceMaxRange_m(Vl53l0x(0), 1.0), 2.0);
  // linear in the light between levels, A^(−1/4) beyond the brightest
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l0x(2.5), 0.88), 1.4, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l0x(80), 0.17), 0.5 * std::pow(5.0 / 80.0, 0.25), 1e-12);
  // a part without a table keeps its range
  EXPECT_EQ(ReflectanceMaxRange_m(SensorSpec::Preset(SensorType::kLaser), 0.01), 2.0);
}

TEST(RangeTableTest, TheMapTakesASilenceOnlyAsFarAsTheDarkestTarget) {
  SensorOutput output;
  output.fresh = true;
  output.detected = false;
  output.d_m = 2.0;
  output.dir_W = -Vec3::UnitZ();
  EXPECT_NEAR(InterpretReading(Vl53l0x(0), output).free_end_m, 0.8, 1e-12);
  EXPECT_NEAR(InterpretReading(Vl53l0x(5), output).free_end_m, 0.5, 1e-12);
  EXPECT_EQ(InterpretReading(SensorSpec::Preset(SensorType::kLaser), output).free_end_m, 2.0);
}

// A VL53L0X 1 m before a wall of albedo `albedo` in `ambient_klux`: the status of its one reading.
std::string StatusFacingAWall(const std::string& name, double albedo, double ambient_klux, double wall_x_m = 1.0) {
  const fs::path dir = FreshDir(name);
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << "proxsim: 1\nduration_s: 0.1\nrate_hz: 10\nscene:\n  ambient_klux: " << ambient_klux
                                << "\n  objects:\n    - {name: wall, plane: {}, pose: {xyz_m: [" << wall_x_m
                                << ", 0, 0], rpy_deg: [0, -90, 0]}, material: {albedo: " << albedo
                                << "}}\nsensors:\n  - {name: tof, type: vl53l0x, pose: {xyz_m: [0, 0, 1]}}\n";
  const auto run = RunProxsim("run " + (dir / "s.yaml").string() + " --no-report --out " + (dir / "out").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  const auto rows = testing::ReadCsv(dir / "out" / "readings.csv").rows;
  return rows.empty() ? "" : rows.front().at("status");
}

TEST(RangeTableTest, AWhiteWallIsSeenWhereAGreyOneOrDaylightHidesIt) {
  EXPECT_EQ(StatusFacingAWall("range_white", 0.88, 0), "ok");
  EXPECT_EQ(StatusFacingAWall("range_grey", 0.17, 0), "no_echo");
  EXPECT_EQ(StatusFacingAWall("range_daylight", 0.88, 5), "no_echo");
  EXPECT_EQ(StatusFacingAWall("range_daylight_near", 0.88, 5, 0.7), "ok");
}

TEST(RangeTableTest, NegativeLightIsRefusedNamingTheLimitAndItsSource) {
  const fs::path dir = FreshDir("range_negative_light");
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << "proxsim: 1\nscene: {ambient_klux: -1}\nsensors:\n  - {name: a, type: vl53l0x}\n";
  const auto result = RunProxsim("validate " + (dir / "s.yaml").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("scene.ambient_klux: expected an ambient light >= 0 klux"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("DocID029104 Table 11"), std::string::npos) << result.output;
  std::ofstream(dir / "t.yaml") << "proxsim: 1\nsensors:\n  - {name: a, type: ultrasonic, range_table: [[0.5, 0, 1]]}\n";
  const auto table = RunProxsim("validate " + (dir / "t.yaml").string());
  EXPECT_EQ(table.exit_code, 2) << table.output;
  EXPECT_NE(table.output.find("range_table: expected only for an optical time-of-flight sensor"), std::string::npos)
      << table.output;
}

// A zone whose wall lies within the part's range but beyond the range for its
// reflectance reads ST's "signal rate too low for the current target" (8).
TEST(RangeTableTest, AZoneBeyondItsTargetsRangeReadsSignalTooLow) {
  const fs::path dir = FreshDir("range_zone");
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml")
      << "proxsim: 1\nduration_s: 0.1\nrate_hz: 10\nscene:\n  objects:\n    - {name: wall, plane: {}, pose: {xyz_m: "
         "[1.5, 0, 0], rpy_deg: [0, -90, 0]}, material: {albedo: 0.1}}\nsensors:\n  - {name: z, type: multizone, "
         "zones: [1, 1], fov_deg: [10, 10], pose: {xyz_m: [0, 0, 1]}, range_table: [[0.88, 0, 4.0], [0.17, 0, 1.7]]}\n";
  const auto run = RunProxsim("run " + (dir / "s.yaml").string() + " --no-report --out " + (dir / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  // ρ = 0.1 < 0.17: 1.7·√(0.1/0.17) = 1.30 m < 1.5 m
  const std::string status = testing::ReadFile(dir / "out" / "zones" / "z" / "status.npy");
  EXPECT_EQ(static_cast<unsigned char>(status.back()), 8);
}

}  // namespace
}  // namespace proxsim
