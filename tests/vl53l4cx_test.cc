// ST's VL53L4CX (type: vl53l4cx; docs/sensors.md#multi-zone-time-of-flight):
// a single-zone time-of-flight part with histogram processing that reports
// up to 4 targets in its one zone, modelled as a multi-zone part of one zone.
// Its preset's figures and their sources, its limits refused with their
// source, and through the binary: a wall facing it read at the closed form
// of its rays' signal-weighted distances, and two surfaces in its cone read
// as two targets, nearest first (merged when closer than 600 mm).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "npy_read.h"
#include "sensors/multizone.h"
#include "sensors/part_prices.h"
#include "sensors/sensor_spec.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;

// The VL53L4CX's 16 rays, written here from its geometry: one square zone
// of 18° a side cut into 4 × 4 sub-cells, ray (a, b) through the centre of
// sub-cell (a, b) on the image plane x = 1 (a along −y, b along −z).
struct L4cxRay {
  double x, y, z;
};
std::vector<L4cxRay> L4cxRays() {
  const double half = std::tan(9.0 * std::numbers::pi / 180.0);
  std::vector<L4cxRay> rays;
  for (int b = 0; b < 4; ++b) {
    for (int a = 0; a < 4; ++a) {
      const double u = half - (a + 0.5) / 4.0 * 2.0 * half, v = half - (b + 0.5) / 4.0 * 2.0 * half;
      const double norm = std::sqrt(1.0 + u * u + v * v);
      rays.push_back({1.0 / norm, u / norm, v / norm});
    }
  }
  return rays;
}

// The target distance of the rays with y > 0 (left) or y < 0 (right) on a
// face across the axis at x_m: radial t = x_m / r.x, each ray weighed by the
// signal it returns, cos α / t², cos α = r.x (one surface: its albedo cancels).
double L4cxHalfDistance(double x_m, bool left) {
  double weighted_m = 0, weight = 0;
  for (const L4cxRay& r : L4cxRays()) {
    if ((r.y > 0) != left) continue;
    const double t = x_m / r.x;
    weighted_m += r.x / (t * t) * t;
    weight += r.x / (t * t);
  }
  return weighted_m / weight;
}

TEST(Vl53l4cxTest, ThePresetCarriesItsSourcedFiguresAndStatesItsAssumptions) {
  const SensorSpec spec = *SensorSpec::PartPreset("vl53l4cx");
  EXPECT_TRUE(spec.Validate().empty());
  EXPECT_EQ(spec.type, SensorType::kMultizone);
  EXPECT_EQ(spec.part, "vl53l4cx");
  // ST STSW-IMG029: "18° FoV", "up to 6 m"; the 2 cm minimum is the family's assumption
  ASSERT_TRUE(spec.zones.has_value());
  EXPECT_EQ(spec.zones->nx, 1);
  EXPECT_EQ(spec.zones->ny, 1);
  EXPECT_EQ(spec.zones->fov_h_deg, 18.0);
  EXPECT_EQ(spec.zones->fov_v_deg, 18.0);
  EXPECT_EQ(spec.max_range_m, 6.0);
  EXPECT_EQ(spec.min_range_m, 0.02);
  // up to 4 objects per measurement (VL53L4CX_MAX_RANGE_RESULTS), nearest first,
  // told apart at 600 mm (assumed: the multi-zone parts' UM2884 figure), radial
  EXPECT_EQ(spec.zones->targets, 4);
  EXPECT_FALSE(spec.zones->strongest_first);
  EXPECT_EQ(spec.zones->target_separation_m, 0.6);
  EXPECT_FALSE(spec.zones->perpendicular);
  EXPECT_EQ(spec.zones->rays_per_zone, 16);
  // no range or accuracy table was found: none, and σ = 3 % of d
  EXPECT_TRUE(spec.range_table.empty());
  EXPECT_TRUE(spec.corner_range_table.empty());
  EXPECT_TRUE(spec.sigma_table.empty());
  EXPECT_EQ(spec.noise.model, NoiseModel::kMultiplicative);
  EXPECT_EQ(spec.noise.sigma, 0.03);
  EXPECT_EQ(spec.noise.resolution_m, 0.001);
  // one measurement per the driver's default 33.3 ms timing budget: 30 Hz
  const RateLimit limit = PartRateLimit(spec);
  EXPECT_EQ(limit.max_hz, 30.0);
  EXPECT_NE(limit.source.find("33.3 ms"), std::string::npos) << limit.source;
  EXPECT_NE(limit.source.find("STSW-IMG029"), std::string::npos) << limit.source;
  // its price row (an estimate: the VL53L1X board's)
  ASSERT_TRUE(PartPriceOf("vl53l4cx").has_value());
  EXPECT_GT(PartPriceOf("vl53l4cx")->price_usd, 0);
  EXPECT_GT(PartPriceOf("vl53l4cx")->mass_g, 0);
}

TEST(Vl53l4cxTest, ItsRaysFillTheEighteenDegreeCone) {
  const std::vector<BeamRay> rays = MakeSensorRays(*SensorSpec::PartPreset("vl53l4cx"));
  ASSERT_EQ(rays.size(), 16u);
  const std::vector<L4cxRay> expected = L4cxRays();
  double widest_deg = 0, nearest_deg = 90;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    EXPECT_NEAR(rays[i].dir_S.x(), expected[i].x, 1e-12) << i;
    EXPECT_NEAR(rays[i].dir_S.y(), expected[i].y, 1e-12) << i;
    EXPECT_NEAR(rays[i].dir_S.z(), expected[i].z, 1e-12) << i;
    widest_deg = std::max(widest_deg, rays[i].off_axis_deg);
    nearest_deg = std::min(nearest_deg, rays[i].off_axis_deg);
  }
  // the corner rays on the diagonal at atan(√2·¾·tan 9°) ≈ 9.5°, the inner ones at atan(√2·¼·tan 9°)
  const double tan9 = std::tan(9.0 * std::numbers::pi / 180.0);
  EXPECT_NEAR(widest_deg, std::atan(std::sqrt(2.0) * 0.75 * tan9) * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(nearest_deg, std::atan(std::sqrt(2.0) * 0.25 * tan9) * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(widest_deg, 9.5, 0.05);
}

TEST(Vl53l4cxTest, ItsGridAndRateLimitsAreItsOwnAndTheFamilysUnchanged) {
  EXPECT_EQ(MultizonePartGrids(*FindMultizonePart("vl53l4cx")), "[1, 1]");
  EXPECT_EQ(MultizonePartGrids(*FindMultizonePart("vl53l5cx")), "[4, 4] or [8, 8]");
  SensorSpec spec = *SensorSpec::PartPreset("vl53l4cx");
  spec.zones->nx = spec.zones->ny = 4;
  EXPECT_EQ(MultizoneMaxRate_hz(spec), 0.0);
  const auto problems = spec.Validate();
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("zones: expected [1, 1] for a vl53l4cx (ST STSW-IMG029"), std::string::npos) << problems[0];
  // the multi-zone parts keep their preset grid and rates
  const SensorSpec l5 = *SensorSpec::PartPreset("vl53l5cx");
  EXPECT_EQ(l5.zones->nx, 8);
  EXPECT_EQ(l5.zones->targets, 1);
  EXPECT_TRUE(l5.zones->perpendicular);
  EXPECT_EQ(PartRateLimit(l5).max_hz, 15.0);
}

// A VL53L4CX at the origin 1 m up facing +x, noise off; `objects` the scene's.
std::string L4cxScenario(const std::string& objects, const std::string& sensor_extra = "") {
  return "proxsim: 1\nduration_s: 0.1\nrate_hz: 10\nscene:\n  objects:\n" + objects +
         "sensors:\n  - {name: l4, type: vl53l4cx, pose: {xyz_m: [0, 0, 1]}, noise: {sigma: 0, resolution_m: 0}" +
         sensor_extra + "}\n";
}

// a wall across the axis at x_m
std::string L4cxWall(double x_m) {
  return "    - {name: wall, plane: {}, pose: {xyz_m: [" + std::to_string(x_m) + ", 0, 0], rpy_deg: [0, -90, 0]}}\n";
}

// a box whose face at x_m fills the left half (+y) of the cone
std::string L4cxLeftBox(double x_m) {
  return "    - {name: box, box: {size_m: [0.1, 2, 2]}, pose: {xyz_m: [" + std::to_string(x_m + 0.05) +
         ", 1, 1], rpy_deg: [0, 0, 0]}}\n";
}

TEST(Vl53l4cxRun, AWallFacingItReadsItsRaysSignalWeightedDistance) {
  const fs::path out = testing::RunScenarioYaml("l4cx_wall", L4cxScenario(L4cxWall(1.5)));
  const testing::NpyArray d = testing::LoadNpy(out / "zones" / "l4" / "d_m.npy");
  const testing::NpyArray status = testing::LoadNpy(out / "zones" / "l4" / "status.npy");
  const testing::NpyArray count = testing::LoadNpy(out / "zones" / "l4" / "target_count.npy");
  ASSERT_EQ(d.shape, (std::vector<long>{1, 1, 4}));
  EXPECT_EQ(count.values[0], 1);
  EXPECT_EQ(status.values[0], 5);    // range valid
  EXPECT_EQ(status.values[1], 255);  // no second target
  // every ray meets the wall at 1.5 m / r.x; the signal-weighted centre, a little beyond 1.5 m
  const double expected_m = 0.5 * (L4cxHalfDistance(1.5, true) + L4cxHalfDistance(1.5, false));
  EXPECT_NEAR(d.values[0], expected_m, 1e-5);
  EXPECT_GT(d.values[0], 1.5);
  EXPECT_LT(d.values[0], 1.5 / std::cos(9.5 * std::numbers::pi / 180.0));
  // the sensor's row: its nearest target
  const auto rows = testing::ReadCsv(out / "readings.csv").rows;
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.front().at("status"), "ok");
  EXPECT_NEAR(std::stod(rows.front().at("d_m")), expected_m, 1e-4);

  // beyond its 6 m: nothing
  const fs::path far = testing::RunScenarioYaml("l4cx_far_wall", L4cxScenario(L4cxWall(6.5)));
  EXPECT_EQ(testing::LoadNpy(far / "zones" / "l4" / "target_count.npy").values[0], 0);
  EXPECT_EQ(testing::LoadNpy(far / "zones" / "l4" / "status.npy").values[0], 255);
}

TEST(Vl53l4cxRun, TwoSurfacesInItsConeAreTwoTargetsNearestFirst) {
  // a box face at 0.8 m over the left half of the cone, a wall at 2 m behind it
  const fs::path out = testing::RunScenarioYaml("l4cx_two", L4cxScenario(L4cxWall(2.0) + L4cxLeftBox(0.8)));
  const testing::NpyArray d = testing::LoadNpy(out / "zones" / "l4" / "d_m.npy");
  const testing::NpyArray status = testing::LoadNpy(out / "zones" / "l4" / "status.npy");
  const testing::NpyArray count = testing::LoadNpy(out / "zones" / "l4" / "target_count.npy");
  ASSERT_EQ(d.shape, (std::vector<long>{1, 1, 4}));
  EXPECT_EQ(count.values[0], 2);
  EXPECT_EQ(status.values[0], 5);
  EXPECT_EQ(status.values[1], 5);
  EXPECT_EQ(status.values[2], 255);
  EXPECT_NEAR(d.values[0], L4cxHalfDistance(0.8, true), 1e-5);
  EXPECT_NEAR(d.values[1], L4cxHalfDistance(2.0, false), 1e-5);
  // the sensor's row is the nearer target, the box
  const auto rows = testing::ReadCsv(out / "readings.csv").rows;
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.front().at("object"), "box");

  // 0.4 m before the wall (under the 600 mm taken as its separation): one target between them
  const fs::path merged = testing::RunScenarioYaml("l4cx_merged", L4cxScenario(L4cxWall(2.0) + L4cxLeftBox(1.6)));
  const testing::NpyArray dm = testing::LoadNpy(merged / "zones" / "l4" / "d_m.npy");
  EXPECT_EQ(testing::LoadNpy(merged / "zones" / "l4" / "target_count.npy").values[0], 1);
  EXPECT_GT(dm.values[0], L4cxHalfDistance(1.6, true));
  EXPECT_LT(dm.values[0], L4cxHalfDistance(2.0, false));

  // targets: 1 keeps the nearest only
  const fs::path one = testing::RunScenarioYaml("l4cx_one", L4cxScenario(L4cxWall(2.0) + L4cxLeftBox(0.8), ", targets: 1"));
  const testing::NpyArray d1 = testing::LoadNpy(one / "zones" / "l4" / "d_m.npy");
  ASSERT_EQ(d1.shape, (std::vector<long>{1, 1, 1}));
  EXPECT_NEAR(d1.values[0], L4cxHalfDistance(0.8, true), 1e-5);
}

TEST(Vl53l4cxRun, ItsLimitsAreRefusedNamingTheLimitAndItsSource) {
  testing::ExpectRefused("l4cx_bad",
      "proxsim: 1\nsensors:\n"
      "  - {name: a, type: vl53l4cx, rate_hz: 40}\n"
      "  - {name: b, type: vl53l4cx, zones: [4, 4]}\n"
      "  - {name: c, type: vl53l4cx, targets: 5}\n"
      "  - {name: d, type: vl53l4cx, echoes: all}\n",
      {"sensors[0].rate_hz: expected a ranging frequency of at most 30 Hz for a vl53l4cx at 1x1 zones (ST STSW-IMG029",
       "sensors[1].zones: expected [1, 1] for a vl53l4cx (ST STSW-IMG029",
       "sensors[2].targets: expected targets per zone in [1, 4]",
       "sensors[3].echoes: expected first for a multizone sensor"});
}

}  // namespace
}  // namespace proxsim
