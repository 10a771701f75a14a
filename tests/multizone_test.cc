// Multi-zone time of flight (sensors/multizone.h) through the CLI: each
// zone's distance against the closed form of its rays' geometry (written
// here, not taken from the model), targets separated in range as ST's parts
// separate them, the parts' limits refused with their source, and VL53L5CXs
// on the biped's shins feeding the map and the stop rule.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "npy_read.h"
#include "sensors/multizone.h"
#include "sensors/noise_table.h"
#include "sensors/sensor_spec.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::RunScenarioYaml;
using testing::LoadNpy;
using testing::NpyArray;
using testing::ReadFile;
using testing::RunProxsim;


// Sub-ray (a, b) of zone (column, row) for an nx × ny grid over h × v degrees,
// k × k rays per zone: the unit direction through the centre of its sub-cell
// on the image plane x = 1 (column 0 at +y, row 0 at +z).
struct Dir {
  double x, y, z;
};
Dir ZoneRay(int nx, int ny, double h_deg, double v_deg, int k, int column, int row, int a, int b) {
  const double tu = std::tan(h_deg * std::numbers::pi / 360), tv = std::tan(v_deg * std::numbers::pi / 360);
  const double u = tu - (column + (a + 0.5) / k) * 2 * tu / nx;
  const double v = tv - (row + (b + 0.5) / k) * 2 * tv / ny;
  const double norm = std::sqrt(1 + u * u + v * v);
  return {1 / norm, u / norm, v / norm};
}

// An 8x8 sensor (4 rays per zone, no noise) at the origin, facing a plane
// through (1, 0, 0) turned 20° about z: ray d meets it at t = cos20/(cos20·dx + sin20·dy)
// at incidence α, cos α = |n·d|. A ray counts when α is at most 30°
// (max_incidence_deg); a zone with none reads status 8 (signal too low), the
// others 5. A zone reads the centre of its rays' distances weighed by the
// signal each returns, cos α / t² (one surface: its albedo cancels): the
// distance along each ray (radial) or projected on the sensor's axis,
// t·dx (perpendicular), and its point lies along the zone's axis at that
// distance, over the axis's cosine for the perpendicular one.
void ExpectZonesOfATiltedPlane(const std::string& distance) {
  const fs::path out = RunScenarioYaml("multizone_plane_" + distance, R"(proxsim: 1
duration_s: 0.1
rate_hz: 10
scene:
  objects:
    - {name: wall, plane: {}, pose: {xyz_m: [1, 0, 0], rpy_deg: [0, -90, 20]}}
sensors:
  - {name: grid, type: multizone, zones: [8, 8], fov_deg: [45, 45], zone_rays: 4, max_incidence_deg: 30,
     distance: )" + distance + R"(, pose: {xyz_m: [0, 0, 1]}}
)");
  const bool perpendicular = distance == "perpendicular";
  const NpyArray d = LoadNpy(out / "zones" / "grid" / "d_m.npy");
  const NpyArray status = LoadNpy(out / "zones" / "grid" / "status.npy");
  const NpyArray count = LoadNpy(out / "zones" / "grid" / "target_count.npy");
  const NpyArray p_W = LoadNpy(out / "zones" / "grid" / "p_W.npy");
  ASSERT_EQ(d.shape, (std::vector<long>{1, 64, 1}));
  ASSERT_EQ(p_W.shape, (std::vector<long>{1, 64, 1, 3}));
  ASSERT_EQ(count.shape, (std::vector<long>{1, 64}));
  const double c = std::cos(20 * std::numbers::pi / 180), s = std::sin(20 * std::numbers::pi / 180);
  int valid = 0, too_low = 0;
  for (int zone = 0; zone < 64; ++zone) {
    double sum_weighted_m = 0, sum_weight = 0;
    for (int b = 0; b < 2; ++b) {
      for (int a = 0; a < 2; ++a) {
        const Dir r = ZoneRay(8, 8, 45, 45, 2, zone % 8, zone / 8, a, b);
        const double cos_alpha = c * r.x + s * r.y;  // |n·d|, n = −(cos20, sin20, 0)
        if (std::acos(cos_alpha) * 180 / std::numbers::pi > 30) continue;
        const double t = c / cos_alpha;
        const double weight = cos_alpha / (t * t);
        sum_weighted_m += weight * (perpendicular ? t * r.x : t);
        sum_weight += weight;
      }
    }
    if (sum_weight > 0) {
      ++valid;
      EXPECT_EQ(status.values[zone], 5) << "zone " << zone;
      EXPECT_EQ(count.values[zone], 1) << "zone " << zone;
      EXPECT_NEAR(d.values[zone], sum_weighted_m / sum_weight, 1e-5) << "zone " << zone;
      // its point: the sensor's origin (0, 0, 1) + along the zone's axis (the cell's centre)
      const Dir axis = ZoneRay(8, 8, 45, 45, 1, zone % 8, zone / 8, 0, 0);
      const double along_m = perpendicular ? d.values[zone] / axis.x : d.values[zone];
      EXPECT_NEAR(p_W.values[3 * zone + 0], along_m * axis.x, 1e-9) << "zone " << zone;
      EXPECT_NEAR(p_W.values[3 * zone + 1], along_m * axis.y, 1e-9) << "zone " << zone;
      EXPECT_NEAR(p_W.values[3 * zone + 2], 1 + along_m * axis.z, 1e-9) << "zone " << zone;
    } else {
      ++too_low;
      EXPECT_EQ(status.values[zone], 8) << "zone " << zone;
      EXPECT_EQ(count.values[zone], 0) << "zone " << zone;
      EXPECT_EQ(d.values[zone], 0.0) << "zone " << zone;
    }
  }
  // the tilt leaves both kinds of zone (the left edge of the grid is beyond 30°)
  EXPECT_GT(valid, 0);
  EXPECT_GT(too_low, 0);
  // the row of readings.csv is the nearest zone's target
  const auto csv = testing::ReadCsv(out / "readings.csv");
  ASSERT_EQ(csv.rows.size(), 1u);
}

TEST(MultizoneTest, EachZoneOfAnEightByEightReadsItsSignalWeightedRadialDistanceToATiltedPlane) {
  ExpectZonesOfATiltedPlane("radial");
}

TEST(MultizoneTest, EachZoneOfAnEightByEightReadsItsSignalWeightedPerpendicularDistanceToATiltedPlane) {
  ExpectZonesOfATiltedPlane("perpendicular");
}

// ST's parts report the perpendicular distance: a wall facing a VL53L5CX
// 1.2 m ahead reads 1.2 m in every zone (within its millimetre resolution),
// where a radial distance would read 1.2 / cos of each zone's angle (up to
// 1.12 times more in the corner zones, whose axes lie 27.1° off).
TEST(MultizoneTest, AWallFacingAnStPartReadsTheSameInEveryZone) {
  const fs::path out = RunScenarioYaml("multizone_facing_wall", R"(proxsim: 1
duration_s: 0.1
rate_hz: 10
scene:
  objects:
    - {name: wall, box: {size_m: [0.1, 6, 6]}, pose: {xyz_m: [1.25, 0, 1]}, material: {albedo: 0.88}}
sensors:
  - {name: tof, type: vl53l5cx, noise: {sigma: 0}, pose: {xyz_m: [0, 0, 1]}}
)");
  const NpyArray d = LoadNpy(out / "zones" / "tof" / "d_m.npy");
  const NpyArray status = LoadNpy(out / "zones" / "tof" / "status.npy");
  ASSERT_EQ(d.shape, (std::vector<long>{1, 64, 1}));
  for (int zone = 0; zone < 64; ++zone) {
    EXPECT_EQ(status.values[zone], 5) << "zone " << zone;
    EXPECT_NEAR(d.values[zone], 1.2, 1e-3) << "zone " << zone;
  }
  const auto summary = nlohmann::json::parse(ReadFile(out / "summary.json"));
  EXPECT_EQ(summary["inputs"]["sensors"][0]["distance"], "perpendicular") << summary["inputs"]["sensors"][0].dump();
}

// One zone of 4x4 rays: the left half sees a box's face at x = 0.8 m, the
// right half a wall at x = 2 m: two targets, nearest first, each the mean of
// its rays' d = x·|(1, u, v)|. With one target only the nearer is reported; a
// box 0.4 m before the wall (< ST's 600 mm) merges with it into one target.
// `sensor_extra`: more keys of the sensor; `box_material`: the box's, if any.
std::string BoxBeforeWall(double box_front_x_m, int targets, const std::string& sensor_extra = "",
                          const std::string& box_material = "") {
  return R"(proxsim: 1
duration_s: 0.1
rate_hz: 10
scene:
  objects:
    - {name: wall, plane: {}, pose: {xyz_m: [2, 0, 0], rpy_deg: [0, -90, 0]}}
    - {name: box, box: {size_m: [0.1, 2, 2]}, )" + box_material + R"(pose: {xyz_m: [)" +
         std::to_string(box_front_x_m + 0.05) + R"(, 1, 1], rpy_deg: [0, 0, 0]}}
sensors:
  - {name: zone, type: multizone, zones: [1, 1], fov_deg: [20, 20], zone_rays: 16, pose: {xyz_m: [0, 0, 1]}, targets: )" +
         std::to_string(targets) + sensor_extra + "}\n";
}

// A face across the zone at x_m, filling its left (or right) half.
struct HalfFace {
  double x_m;
  bool left;
};

// The zone's target distance over the faces given: the centre of its rays'
// distances weighed by the signal each returns. Ray r meets a face at
// t = x_m / r.x (radial: the generic multizone's default), at incidence
// cos α = r.x, returning cos α / t² (the faces' albedo is the same).
double WeightedDistance(std::initializer_list<HalfFace> faces) {
  double sum_weighted_m = 0, sum_weight = 0;
  for (int b = 0; b < 4; ++b) {
    for (int a = 0; a < 4; ++a) {
      const Dir r = ZoneRay(1, 1, 20, 20, 4, 0, 0, a, b);
      for (const HalfFace& face : faces) {
        if ((r.y > 0) != face.left) continue;
        const double t = face.x_m / r.x;
        sum_weighted_m += r.x / (t * t) * t;
        sum_weight += r.x / (t * t);
      }
    }
  }
  return sum_weighted_m / sum_weight;
}

double MeanDistance(double x_m, bool left) { return WeightedDistance({{x_m, left}}); }

TEST(MultizoneTest, ABoxEdgeBeforeAWallGivesTwoTargetsNearestFirst) {
  const fs::path out = RunScenarioYaml("multizone_two_targets", BoxBeforeWall(0.8, 2));
  const NpyArray d = LoadNpy(out / "zones" / "zone" / "d_m.npy");
  const NpyArray status = LoadNpy(out / "zones" / "zone" / "status.npy");
  const NpyArray count = LoadNpy(out / "zones" / "zone" / "target_count.npy");
  ASSERT_EQ(d.shape, (std::vector<long>{1, 1, 2}));
  EXPECT_EQ(count.values[0], 2);
  EXPECT_EQ(status.values[0], 5);
  EXPECT_EQ(status.values[1], 5);
  EXPECT_NEAR(d.values[0], MeanDistance(0.8, true), 1e-5);
  EXPECT_NEAR(d.values[1], MeanDistance(2.0, false), 1e-5);

  const fs::path one = RunScenarioYaml("multizone_one_target", BoxBeforeWall(0.8, 1));
  const NpyArray d1 = LoadNpy(one / "zones" / "zone" / "d_m.npy");
  ASSERT_EQ(d1.shape, (std::vector<long>{1, 1, 1}));
  EXPECT_NEAR(d1.values[0], MeanDistance(0.8, true), 1e-5);

  const fs::path merged = RunScenarioYaml("multizone_merged", BoxBeforeWall(1.6, 2));
  const NpyArray dm = LoadNpy(merged / "zones" / "zone" / "d_m.npy");
  const NpyArray cm = LoadNpy(merged / "zones" / "zone" / "target_count.npy");
  EXPECT_EQ(cm.values[0], 1);
  // merged, the target leans to the nearer box: its rays return (2/1.6)² times the wall's signal
  EXPECT_NEAR(dm.values[0], WeightedDistance({{1.6, true}, {2.0, false}}), 1e-5);
  EXPECT_LT(dm.values[0], 0.5 * (MeanDistance(1.6, true) + MeanDistance(2.0, false)));
  EXPECT_EQ(LoadNpy(merged / "zones" / "zone" / "status.npy").values[1], 255);

  // columns.json describes the arrays and names the codes
  const auto columns = nlohmann::json::parse(ReadFile(out / "zones" / "columns.json"));
  EXPECT_EQ(columns["sensors"]["zone"]["targets"], 2);
  EXPECT_EQ(columns["status_codes"]["5"], "range_valid");
  EXPECT_EQ(columns["status_codes"]["255"], "no_target_detected");
}

TEST(MultizoneTest, TheStrongestTargetOrderPutsTheTargetReturningMostSignalFirst) {
  // half the zone's rays on the box (0.8 m), half on the wall (2 m); each
  // ray an equal part, so a target's signal is its surface's IR albedo times
  // its 8 rays: a dark box (0.1) before the wall (the default albedo) is the weaker
  const std::string dark = "material: {ir_albedo: 0.1}, ";
  const fs::path closest = RunScenarioYaml("multizone_closest", BoxBeforeWall(0.8, 2, "", dark));
  const fs::path strongest =
      RunScenarioYaml("multizone_strongest", BoxBeforeWall(0.8, 2, ", target_order: strongest", dark));
  const NpyArray dc = LoadNpy(closest / "zones" / "zone" / "d_m.npy");
  const NpyArray ds = LoadNpy(strongest / "zones" / "zone" / "d_m.npy");
  ASSERT_EQ(ds.shape, (std::vector<long>{1, 1, 2}));
  EXPECT_NEAR(dc.values[0], MeanDistance(0.8, true), 1e-5);   // closest: the box first
  EXPECT_NEAR(ds.values[0], MeanDistance(2.0, false), 1e-5);  // strongest: the wall first
  EXPECT_NEAR(ds.values[1], MeanDistance(0.8, true), 1e-5);
  // one target reported: the strongest order keeps the wall, the closest the box
  const fs::path one = RunScenarioYaml("multizone_strongest_one", BoxBeforeWall(0.8, 1, ", target_order: strongest", dark));
  EXPECT_NEAR(LoadNpy(one / "zones" / "zone" / "d_m.npy").values[0], MeanDistance(2.0, false), 1e-5);
  // a box as bright as the wall: equal signals, the nearer first in either order
  const fs::path tie = RunScenarioYaml("multizone_strongest_tie",
                                       BoxBeforeWall(0.8, 2, ", target_order: strongest", ""));
  EXPECT_NEAR(LoadNpy(tie / "zones" / "zone" / "d_m.npy").values[0], MeanDistance(0.8, true), 1e-5);
  // the summary echoes the order; a wrong one is refused naming both
  EXPECT_EQ(nlohmann::json::parse(ReadFile(strongest / "summary.json"))["inputs"]["sensors"][0]["target_order"], "strongest");
  const fs::path bad_dir = FreshDir("multizone_bad_order");
  fs::create_directories(bad_dir);
  std::ofstream(bad_dir / "bad.yaml") << BoxBeforeWall(0.8, 2, ", target_order: brightest");
  const auto bad = RunProxsim("validate " + (bad_dir / "bad.yaml").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("expected closest or strongest"), std::string::npos) << bad.output;
}

TEST(MultizoneTest, APartsLimitsAreRefusedNamingTheLimitAndItsSource) {
  const fs::path dir = FreshDir("multizone_limits");
  fs::create_directories(dir);
  const auto refused = [&](const std::string& name, const std::string& sensor) {
    std::ofstream(dir / name) << "proxsim: 1\nsensors:\n  - " << sensor << "\n";
    return RunProxsim("validate " + (dir / name).string());
  };
  const auto zones = refused("zones.yaml", "{name: a, type: vl53l5cx, zones: [6, 6], rate_hz: 40}");
  EXPECT_EQ(zones.exit_code, 2) << zones.output;
  EXPECT_NE(zones.output.find("expected [4, 4] or [8, 8] for a vl53l5cx (ST UM2884"), std::string::npos) << zones.output;
  // a grid the part does not have has no rate limit to name (it once said "at most 15 Hz ... at 6x6 zones")
  EXPECT_EQ(zones.output.find("ranging frequency"), std::string::npos) << zones.output;

  const auto rate = refused("rate.yaml", "{name: a, type: vl53l7cx, rate_hz: 30}");
  EXPECT_EQ(rate.exit_code, 2) << rate.output;
  EXPECT_NE(rate.output.find("at most 15 Hz for a vl53l7cx at 8x8 zones (ST STSW-IMG036"), std::string::npos)
      << rate.output;
  const auto fast_4x4 = refused("rate4.yaml", "{name: a, type: vl53l5cx, zones: [4, 4], rate_hz: 60}");
  EXPECT_EQ(fast_4x4.exit_code, 0) << fast_4x4.output;

  const auto targets = refused("targets.yaml", "{name: a, type: vl53l8cx, targets: 5, zone_rays: 3}");
  EXPECT_EQ(targets.exit_code, 2) << targets.output;
  EXPECT_NE(targets.output.find("targets: expected targets per zone in [1, 4]"), std::string::npos) << targets.output;
  EXPECT_NE(targets.output.find("zone_rays: expected rays per zone k*k"), std::string::npos) << targets.output;

  const auto elsewhere = refused("laser.yaml", "{name: a, type: laser, zones: [4, 4]}");
  EXPECT_EQ(elsewhere.exit_code, 2) << elsewhere.output;
  EXPECT_NE(elsewhere.output.find("zones: expected only with type multizone"), std::string::npos) << elsewhere.output;
}

// A VL53L5CX (8x8, noise off) facing a 17 % grey wall 1 m away in the dark:
// ST's Table 18 gives 1.3 m for the inner zones and 1.1 m for the corner
// ones. Each zone's range, written here: its cell centre's distance r from
// the grid's centre on the image plane, t = (r − r_centre)/(r_corner −
// r_centre), range = 1.3 + t·(1.1 − 1.3); its rays meet the wall at
// 1 m·|(1, u, v)|, 1.00–1.02 m in the centre zones and 1.11–1.14 m in the
// corners: the centre zones read it (5), the corners report ST's 8, "signal
// rate too low for the current target", and every zone as the closed form says.
TEST(MultizoneTest, TheCornerZonesSeeLessFarThanTheCentreOnesAsTheDatasheetTabulates) {
  const fs::path out = RunScenarioYaml("multizone_corners", R"(proxsim: 1
duration_s: 0.1
rate_hz: 10
scene:
  objects:
    - {name: wall, plane: {}, pose: {xyz_m: [1, 0, 0], rpy_deg: [0, -90, 0]}, material: {albedo: 0.17}}
sensors:
  - {name: grid, type: vl53l5cx, noise: {sigma: 0, resolution_m: 0}, pose: {xyz_m: [0, 0, 1]}}
)");
  const NpyArray d = LoadNpy(out / "zones" / "grid" / "d_m.npy");
  const NpyArray status = LoadNpy(out / "zones" / "grid" / "status.npy");
  ASSERT_EQ(d.shape, (std::vector<long>{1, 64, 1}));
  const double t22 = std::tan(22.5 * std::numbers::pi / 180), cell = 2 * t22 / 8;
  const auto radius = [&](int column, int row) { return std::hypot((column - 3.5) * cell, (row - 3.5) * cell); };
  const double r_centre = radius(3, 3), r_corner = radius(0, 0);
  for (int zone = 0; zone < 64; ++zone) {
    const double t = (radius(zone % 8, zone / 8) - r_centre) / (r_corner - r_centre);
    const double range_m = 1.3 + t * (1.1 - 1.3);
    int counted = 0;
    for (int b = 0; b < 2; ++b) {
      for (int a = 0; a < 2; ++a) {
        const Dir r = ZoneRay(8, 8, 45, 45, 2, zone % 8, zone / 8, a, b);
        if (1.0 / r.x <= range_m) ++counted;
      }
    }
    if (counted > 0) {
      // a wall facing the part: its perpendicular distance, 1 m, in every zone
      EXPECT_EQ(status.values[zone], 5) << "zone " << zone;
      EXPECT_NEAR(d.values[zone], 1.0, 1e-6) << "zone " << zone;
    } else {
      EXPECT_EQ(status.values[zone], 8) << "zone " << zone;
    }
  }
  for (int centre : {27, 28, 35, 36}) EXPECT_EQ(status.values[centre], 5) << centre;
  for (int corner : {0, 7, 56, 63}) EXPECT_EQ(status.values[corner], 8) << corner;
}

// ST's tables for the three parts at both resolutions come back at their
// points: inner zones (range_table), corner zones (corner_range_table) and
// the ranging accuracy (noise.sigma_table, "± x %" as σ).
TEST(MultizoneTest, EachPartsDatasheetTablesComeBackAtTheirPoints) {
  const auto part = [](const char* name, int zones, double ambient_klux) {
    SensorSpec spec = *SensorSpec::PartPreset(name);
    spec.zones->nx = spec.zones->ny = zones;
    ApplyMultizonePartTables(spec);
    spec.ambient_klux = ambient_klux;
    return spec;
  };
  // VL53L5CX DS13754 Table 18 (8x8): grey 17 % inner 1.3 / corner 1.1 m dark, 0.8 / 0.65 m at 5 klux
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l5cx", 8, 0), 0.0, 0.17), 1.3, 1e-12);
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l5cx", 8, 0), 1.0, 0.17), 1.1, 1e-12);
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l5cx", 8, 5), 1.0, 0.17), 0.65, 1e-12);
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l5cx", 8, 5), 0.5, 0.17), 0.725, 1e-12);
  // Table 17 (4x4): white corner 1.4 m at 5 klux; accuracy Table 19: 8x8 grey 11 % at 5 klux
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l5cx", 4, 5), 1.0, 0.88), 1.4, 1e-12);
  EXPECT_NEAR(SigmaAt(part("vl53l5cx", 8, 5), 0.17), 0.11, 1e-15);
  EXPECT_NEAR(SigmaAt(part("vl53l5cx", 4, 0), 0.88), 0.04, 1e-15);
  // VL53L7CX DS13865 Table 18 (8x8): grey 17 % inner 0.35 / corner 0.25 m at 5 klux; Table 17 (4x4) white 3.5 m dark
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l7cx", 8, 5), 0.0, 0.17), 0.35, 1e-12);
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l7cx", 8, 5), 1.0, 0.17), 0.25, 1e-12);
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l7cx", 4, 0), 1.0, 0.88), 3.5, 1e-12);
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l7cx", 8, 0), 1.0, 0.54), 1.6, 1e-12);
  // VL53L8CX DS14161 Table 17 (8x8): grey 17 % inner 2.45 / corner 1.95 m dark; accuracy Table 18: grey 17 % 8 % at 5 klux
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l8cx", 8, 0), 0.0, 0.17), 2.45, 1e-12);
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l8cx", 8, 0), 1.0, 0.17), 1.95, 1e-12);
  EXPECT_NEAR(ZoneMaxRange_m(part("vl53l8cx", 4, 5), 1.0, 0.54), 2.5, 1e-12);
  EXPECT_NEAR(SigmaAt(part("vl53l8cx", 8, 5), 0.17), 0.08, 1e-15);
  EXPECT_NEAR(SigmaAt(part("vl53l8cx", 4, 0), 0.88), 0.03, 1e-15);
  // where a zone lies: the centre 2x2 at 0, the corners at 1, an edge's middle at 2/3
  const ZoneSpec grid = *SensorSpec::PartPreset("vl53l5cx")->zones;
  EXPECT_NEAR(ZoneCornerWeight(grid, 27), 0.0, 1e-12);
  EXPECT_NEAR(ZoneCornerWeight(grid, 63), 1.0, 1e-12);
  EXPECT_NEAR(ZoneCornerWeight(grid, 3), (std::hypot(0.5, 3.5) - std::hypot(0.5, 0.5)) / (std::hypot(3.5, 3.5) - std::hypot(0.5, 0.5)), 1e-12);
  // a corner table is a multizone sensor's only
  testing::ExpectRefused("multizone_corner_laser",
                         "proxsim: 1\nsensors:\n  - {name: a, type: laser, corner_range_table: [[0.5, 0, 1.0]]}\n",
                         {"sensors[0].corner_range_table: expected only for a multizone sensor"});
}

// The shipped scenario: a VL53L5CX on each shin, at the part's 15 Hz; the
// zones reach the map (far more cells than the paper's single rays) and the
// stop rule stops the robot before the obstacle on a zone's point.
TEST(MultizoneTest, VL53L5CXsOnTheShinsFeedTheMapAndTheStopRule) {
  const fs::path out = FreshDir("multizone_shins");
  const auto run = RunProxsim("run " + std::string(PROXSIM_SOURCE_DIR) +
                              "/data/scenarios/multizone_shins.yaml --no-report --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto summary = nlohmann::json::parse(ReadFile(out / "summary.json"));
  for (const char* name : {"tof_left_shin", "tof_right_shin"}) {
    const NpyArray t = LoadNpy(out / "zones" / name / "t_s.npy");
    const NpyArray d = LoadNpy(out / "zones" / name / "d_m.npy");
    // 15 Hz within a 100 Hz run of 5 s: the first run sample of each of its periods
    EXPECT_EQ(t.shape[0], 75);
    EXPECT_EQ(d.shape, (std::vector<long>{75, 64, 1}));
    EXPECT_EQ(summary["sensors"][name]["samples"], 75);
  }
  EXPECT_EQ(summary["robot"]["stopped"], true);
  const std::string detail = summary["robot"]["events"][0]["detail"];
  EXPECT_EQ(summary["robot"]["events"][0]["event"], "obstacle_ahead");
  EXPECT_EQ(detail.rfind("tof_", 0), 0u) << detail;
  // before the obstacle (x = 2.5 m), not on the floor's noise near the start
  EXPECT_GT(summary["robot"]["events"][0]["t_s"].get<double>(), 3.0) << detail;
  EXPECT_GT(summary["terrain"]["cells_measured"].get<int>(), 1000);
  EXPECT_NE(std::find(summary["outputs"].begin(), summary["outputs"].end(), "zones/"), summary["outputs"].end());
}

}  // namespace
}  // namespace proxsim
