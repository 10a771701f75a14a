// The VL53L1X's distance modes and the ranging error by target and light
// (docs/sensors.md#range-by-target-and-light): the datasheet's points come
// back at its reflectances and light levels, a grey wall is seen or not where
// the tables say, and the error σ follows the target.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_helpers.h"
#include "sensors/distance_modes.h"
#include "sensors/noise_table.h"
#include "sensors/range_table.h"
#include "sensors/sensor_model.h"
#include "sensors/sensor_spec.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::RunProxsim;

SensorSpec Vl53l1x(const std::string& mode, double ambient_klux) {
  SensorSpec spec = *SensorSpec::PartPreset("vl53l1x");
  ApplyDistanceMode(*FindDistanceMode("vl53l1x", mode), spec);
  spec.ambient_klux = ambient_klux;
  return spec;
}

TEST(Vl53l1xTest, EachModesTablePointsComeBack) {
  // long (Tables 6, 7): dark, 50 kcps/SPAD (25 klux), 200 kcps/SPAD (100 klux)
  const double long_rows[3][4] = {{0.0, 3.60, 3.40, 1.70}, {25.0, 1.66, 1.54, 1.14}, {100.0, 0.73, 0.69, 0.68}};
  for (const auto& row : long_rows) {
    const SensorSpec spec = Vl53l1x("long", row[0]);
    EXPECT_NEAR(ReflectanceMaxRange_m(spec, 0.88), row[1], 1e-12) << row[0];
    EXPECT_NEAR(ReflectanceMaxRange_m(spec, 0.54), row[2], 1e-12) << row[0];
    EXPECT_NEAR(ReflectanceMaxRange_m(spec, 0.17), row[3], 1e-12) << row[0];
  }
  // short (Table 8): 1.3 m whatever the target and light, but 17 % grey in 200 kcps/SPAD: 1.2 m
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1x("short", 0), 0.17), 1.30, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1x("short", 100), 0.88), 1.30, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1x("short", 100), 0.17), 1.20, 1e-12);
  // medium (Table 4, white): 2.9 m dark, 0.76 m in 200 kcps/SPAD
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1x("medium", 0), 0.88), 2.90, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1x("medium", 100), 0.88), 0.76, 1e-12);
  // the preset is long mode, 4 cm to 3.6 m, at most 10 Hz
  const SensorSpec preset = *SensorSpec::PartPreset("vl53l1x");
  EXPECT_EQ(preset.distance_mode, "long");
  EXPECT_EQ(preset.min_range_m, 0.04);
  EXPECT_EQ(preset.max_range_m, 3.60);
  EXPECT_EQ(PartRateLimit(preset).max_hz, 10.0);
  // the ranging error: ±20 mm in the dark, ±25 mm in light, as σ
  EXPECT_NEAR(SigmaAt(Vl53l1x("long", 0), 0.5), 0.020, 1e-15);
  EXPECT_NEAR(SigmaAt(Vl53l1x("long", 100), 0.5), 0.025, 1e-15);
}

TEST(NoiseTableTest, TheVl53l0xsErrorFollowsTheTargetAndTheLight) {
  SensorSpec spec = *SensorSpec::PartPreset("vl53l0x");
  // Table 12: white 4 %, grey 7 % indoors; 7 % and 12 % outdoors overcast (5 klux)
  EXPECT_NEAR(SigmaAt(spec, 0.88), 0.04, 1e-15);
  EXPECT_NEAR(SigmaAt(spec, 0.17), 0.07, 1e-15);
  EXPECT_NEAR(SigmaAt(spec, 0.525), 0.055, 1e-12);  // linear between the rows
  EXPECT_NEAR(SigmaAt(spec, 0.05), 0.07, 1e-15);    // held beyond them
  spec.ambient_klux = 5;
  EXPECT_NEAR(SigmaAt(spec, 0.88), 0.07, 1e-15);
  EXPECT_NEAR(SigmaAt(spec, 0.17), 0.12, 1e-15);
  spec.ambient_klux = 2.5;
  EXPECT_NEAR(SigmaAt(spec, 0.17), 0.095, 1e-12);  // linear in the light
  spec.ambient_klux = 50;
  EXPECT_NEAR(SigmaAt(spec, 0.17), 0.12, 1e-15);  // held beyond the brightest level
  // a reading: d(1 + σG) with the grey target's σ, to the millimetre
  spec.ambient_klux = 0;
  Echo echo;
  echo.distance_m = 0.5;
  echo.ir_albedo = 0.17;
  EXPECT_NEAR(Measure(spec, echo, 1.0).d_m, 0.5 * 1.07, 1e-9);
  echo.ir_albedo = 0.88;
  EXPECT_NEAR(Measure(spec, echo, 1.0).d_m, 0.5 * 1.04, 1e-9);
}

// A VL53L1X facing a wall of albedo 0.17 at wall_x_m: the status of its first reading.
std::string StatusFacingAGreyWall(const std::string& name, const std::string& mode, double ambient_klux, double wall_x_m) {
  const fs::path out = testing::RunScenarioYaml(
      name, "proxsim: 1\nduration_s: 0.1\nrate_hz: 10\nscene:\n  ambient_klux: " + std::to_string(ambient_klux) +
                "\n  objects:\n    - {name: wall, plane: {}, pose: {xyz_m: [" + std::to_string(wall_x_m) +
                ", 0, 0], rpy_deg: [0, -90, 0]}, material: {albedo: 0.17}}\nsensors:\n"
                "  - {name: tof, type: vl53l1x, distance_mode: " + mode + ", pose: {xyz_m: [0, 0, 1]}}\n");
  const auto rows = testing::ReadCsv(out / "readings.csv").rows;
  return rows.empty() ? "" : rows.front().at("status");
}

TEST(Vl53l1xRun, AGreyWallIsSeenWithinItsModesRangeOnly) {
  EXPECT_EQ(StatusFacingAGreyWall("l1x_long_dark", "long", 0, 1.6), "ok");         // 1.70 m in the dark
  EXPECT_EQ(StatusFacingAGreyWall("l1x_long_dark_far", "long", 0, 1.8), "no_echo");
  EXPECT_EQ(StatusFacingAGreyWall("l1x_short_dark", "short", 0, 1.6), "no_echo");  // 1.30 m
  EXPECT_EQ(StatusFacingAGreyWall("l1x_short_sun", "short", 100, 1.1), "ok");      // 1.20 m in 200 kcps/SPAD
  EXPECT_EQ(StatusFacingAGreyWall("l1x_long_sun", "long", 100, 1.1), "no_echo");   // 0.68 m
}

TEST(Vl53l1xRun, BadModesAndRatesAreRefusedNamingTheLimitAndItsSource) {
  testing::ExpectRefused("l1x_bad",
      "proxsim: 1\nsensors:\n"
      "  - {name: a, type: vl53l1x, distance_mode: far}\n"
      "  - {name: b, type: vl53l0x, distance_mode: short}\n"
      "  - {name: c, type: vl53l1x, rate_hz: 20}\n"
      "  - {name: d, type: laser, noise: {sigma_table: [[0.5, 0, -1]]}}\n"
      "  - {name: e, type: ultrasonic, noise: {sigma_table: [[0.5, 0, 0.01]]}}\n",
      {"sensors[0].distance_mode: expected one of short, medium, long for a vl53l1x (ST VL53L1X datasheet DocID031281 Rev 3",
      "sensors[1].distance_mode: expected no distance_mode for a vl53l0x (only the vl53l1x has distance modes",
      "sensors[2].rate_hz: expected at most 10 Hz for a vl53l1x (ST VL53L1X datasheet DocID031281 Rev 3",
      "sensors[3].noise.sigma_table[0][2]: expected a standard deviation >= 0",
      "sensors[4].noise.sigma_table: expected only for an optical time-of-flight sensor"});
}

}  // namespace
}  // namespace proxsim
