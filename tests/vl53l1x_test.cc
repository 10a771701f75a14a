// The VL53L1X's distance modes and the ranging error by target and light
// (docs/sensors.md#range-by-target-and-light): the datasheet's points come
// back at its reflectances and light levels, a grey wall is seen or not where
// the tables say, and the error σ follows the target.
#include <gtest/gtest.h>

#include <array>
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
#include "sensors/vl53l1x_settings.h"

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
      "sensors[2].rate_hz: expected at most 10 Hz for a vl53l1x (one ranging per timing budget of 100 ms",
      "sensors[3].noise.sigma_table[0][2]: expected a standard deviation >= 0",
      "sensors[4].noise.sigma_table: expected only for an optical time-of-flight sensor"});
}

// A VL53L1X with a region of interest and a timing budget (in `mode`, dark).
SensorSpec Vl53l1xWith(const std::string& mode, std::array<int, 2> roi, double budget_ms) {
  SensorSpec spec = *SensorSpec::PartPreset("vl53l1x");
  spec.roi_spads = roi;
  spec.timing_budget_ms = budget_ms;
  ApplyDistanceMode(*FindDistanceMode("vl53l1x", mode), spec);
  return spec;
}

TEST(Vl53l1xTest, ARegionOfInterestNarrowsTheConeAndShortensTheRangeAsTable9Says) {
  // Table 9 (dark, long mode): 16x16 27°, 8x8 20°, 4x4 15° diagonal; white / grey 54 % / grey 17 %
  const double columns[3][5] = {{16, 27, 3.60, 3.40, 1.70}, {8, 20, 3.08, 2.54, 1.19}, {4, 15, 1.70, 1.43, 0.45}};
  for (const auto& c : columns) {
    const int side = static_cast<int>(c[0]);
    const SensorSpec spec = Vl53l1xWith("long", {side, side}, 100);
    EXPECT_NEAR(spec.beam->aperture_deg, c[1], 1e-12) << side;
    EXPECT_NEAR(ReflectanceMaxRange_m(spec, 0.88), c[2], 1e-12) << side;
    EXPECT_NEAR(ReflectanceMaxRange_m(spec, 0.54), c[3], 1e-12) << side;
    EXPECT_NEAR(ReflectanceMaxRange_m(spec, 0.17), c[4], 1e-12) << side;
    EXPECT_NEAR(spec.max_range_m, c[2], 1e-12) << side;
  }
  // between the columns, linear in the side √(w·h): 12x12 and 8x16 (side √128)
  EXPECT_NEAR(RoiFieldOfView_deg({12, 12}), 20 + 0.5 * 7, 1e-12);
  const double side = std::sqrt(128.0), u = (side - 8) / 8;
  EXPECT_NEAR(RoiFieldOfView_deg({8, 16}), 20 + u * 7, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1xWith("long", {8, 16}, 100), 0.17), 1.70 * ((1 - u) * 119 / 170.0 + u), 1e-12);
  // in daylight the same fraction of the full array's range (an assumption beyond Table 9's dark column)
  SensorSpec lit = Vl53l1xWith("long", {8, 8}, 100);
  lit.ambient_klux = 100;
  EXPECT_NEAR(ReflectanceMaxRange_m(lit, 0.17), 0.68 * 119 / 170.0, 1e-12);
  // the ranging error stays ±20 mm (Table 9)
  EXPECT_NEAR(SigmaAt(Vl53l1xWith("long", {4, 4}, 100), 0.5), 0.020, 1e-15);
}

TEST(Vl53l1xTest, ATimingBudgetScalesTheRangesAndBoundsTheRate) {
  const double k = std::log(400.0 / 360.0) / std::log(1.4);
  // Table 6: white 360 cm at 100 ms, 400 cm with TB = 140 ms; beyond, the part's 4 m
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1xWith("long", {16, 16}, 140), 0.88), 4.0, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1xWith("long", {16, 16}, 500), 0.88), 4.0, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1xWith("long", {16, 16}, 140), 0.17), 1.70 * 400 / 360, 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1xWith("long", {16, 16}, 33), 0.88), 3.60 * std::pow(0.33, k), 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1xWith("medium", {16, 16}, 50), 0.88), 2.90 * std::pow(0.5, k), 1e-12);
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1xWith("medium", {16, 16}, 500), 0.88), 2.90, 1e-12);  // the mode's own range
  // short mode is held by its window, not by signal: 1.3 m at 20 ms as at 100 ms
  EXPECT_NEAR(ReflectanceMaxRange_m(Vl53l1xWith("short", {16, 16}, 20), 0.17), 1.30, 1e-12);
  // one ranging per budget
  EXPECT_NEAR(PartRateLimit(Vl53l1xWith("short", {16, 16}, 20)).max_hz, 50.0, 1e-12);
  EXPECT_NEAR(PartRateLimit(Vl53l1xWith("long", {16, 16}, 200)).max_hz, 5.0, 1e-12);
  // ST's limits by mode
  EXPECT_EQ(TimingBudgetLimits_ms("short"), (std::array<double, 2>{20, 1000}));
  EXPECT_EQ(TimingBudgetLimits_ms("long"), (std::array<double, 2>{33, 1000}));
}

// A VL53L1X (dark, long mode) facing a wall of albedo `albedo` at wall_x_m,
// with `settings` among its keys: its first reading's status.
std::string StatusWith(const std::string& name, const std::string& settings, double albedo, double wall_x_m) {
  const fs::path out = testing::RunScenarioYaml(
      name, "proxsim: 1\nduration_s: 0.3\nrate_hz: 10\nscene:\n  objects:\n    - {name: wall, plane: {}, pose: {xyz_m: [" +
                std::to_string(wall_x_m) + ", 0, 0], rpy_deg: [0, -90, 0]}, material: {albedo: " +
                std::to_string(albedo) + "}}\nsensors:\n  - {name: tof, type: vl53l1x, pose: {xyz_m: [0, 0, 1]}" +
                settings + "}\n");
  const auto rows = testing::ReadCsv(out / "readings.csv").rows;
  return rows.empty() ? "" : rows.front().at("status");
}

TEST(Vl53l1xRun, TheRegionOfInterestAndTheTimingBudgetChangeWhatIsSeen) {
  // a 17 % grey wall 1 m away: the full array sees it (1.70 m), a 4x4 ROI does not (0.45 m)
  EXPECT_EQ(StatusWith("l1x_roi_full", "", 0.17, 1.0), "ok");
  EXPECT_EQ(StatusWith("l1x_roi_4", ", roi: [4, 4]", 0.17, 1.0), "no_echo");
  // a white wall 3.8 m away: beyond 3.6 m at 100 ms, within 4 m at 200 ms (5 Hz)
  EXPECT_EQ(StatusWith("l1x_tb_100", "", 0.88, 3.8), "no_echo");
  EXPECT_EQ(StatusWith("l1x_tb_200", ", timing_budget_ms: 200", 0.88, 3.8), "ok");
}

TEST(Vl53l1xRun, BadRegionsBudgetsAndRatesAreRefusedNamingTheLimitAndItsSource) {
  testing::ExpectRefused("l1x_bad_roi",
      "proxsim: 1\nsensors:\n"
      "  - {name: a, type: vl53l1x, roi: [2, 16]}\n"
      "  - {name: b, type: vl53l1x, timing_budget_ms: 20}\n"
      "  - {name: c, type: vl53l1x, distance_mode: short, timing_budget_ms: 15}\n"
      "  - {name: d, type: vl53l1x, timing_budget_ms: 50, rate_hz: 25}\n"
      "  - {name: e, type: vl53l0x, roi: [8, 8]}\n"
      "  - {name: f, type: vl53l1x, roi: [8.5, 8]}\n",
      {"sensors[0].roi[0]: expected a region of interest of 4 to 16 SPADs a side (VL53L1X datasheet DocID031281 Rev 3",
       "sensors[1].timing_budget_ms: expected 33 to 1000 ms in long distance mode (ST STEVAL-BCN002V1 user manual",
       "sensors[2].timing_budget_ms: expected 20 to 1000 ms in short distance mode",
       "sensors[3].rate_hz: expected at most 20 Hz for a vl53l1x (one ranging per timing budget of 50 ms",
       "sensors[4].roi: expected only for a vl53l1x",
       "sensors[5].roi: expected whole numbers of SPADs"});
}

}  // namespace
}  // namespace proxsim
