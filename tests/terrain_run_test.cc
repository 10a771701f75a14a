// The terrain map on scenes: an ideal sensor's sweep over small scenes made
// in the test (through the real ray caster) recovers a box's top and a hole's
// depth within 1 cm and classifies each kind of hazard; the paper's run maps
// the floor and the obstacle and finds it before the robot stops; the stairs
// course's map holds its landing and finds every step up and hole ahead; a flat
// floor read by the paper's noisy sensors holds no hazard over 20 seeds; a
// 60-second walk's map grows in proportion to the metres walked; the files
// and the OctoMap tree are written as the contract says; the scenario's
// `map` section is read and every mistake in it reported.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <octomap/OcTree.h>

#include "core/input_error.h"
#include "scenario/scenario.h"
#include "raycast/ray_caster.h"
#include "run/run.h"
#include "sim/simulation.h"
#include "output/octomap_recorder.h"
#include "output/terrain_files.h"
#include "knowledge/terrain_map.h"
#include "sim/truth_field.h"

namespace proxsim {
namespace {

constexpr double kR = 0.02;

BodyShape BoxShape(const Vec3& min_W, const Vec3& max_W, int id) {
  Pose X = Pose::Identity();
  X.translation() = 0.5 * (min_W + max_W);
  return BodyShape{Box{max_W - min_W}, X, id};
}

// An ideal sensor's sweep: a fan of rays from 0.5 m up, moved along x from
// x0 to x1, every ray an ideal reading (the true distance, or silence over 2 m).
class TerrainSweep {
 public:
  explicit TerrainSweep(std::vector<BodyShape> shapes) {
    caster_.AddBody(std::move(shapes), BodyKind::kWorld);
    caster_.Commit();
    for (double pitch_deg = 35; pitch_deg <= 90; pitch_deg += 5) {
      for (double yaw_deg = -40; yaw_deg <= 40; yaw_deg += 4) {
        const double p = DegToRad(pitch_deg), y = DegToRad(yaw_deg);
        fan_.push_back(Vec3(std::cos(p) * std::cos(y), std::cos(p) * std::sin(y), -std::sin(p)));
      }
    }
  }

  void Run(TerrainMap& map, double x0, double x1, double height_m = 0.5) {
    std::vector<Ray> rays(fan_.size());
    std::vector<Hit> hits(fan_.size());
    outputs_.resize(fan_.size());
    std::vector<SensorOutput>& outputs = outputs_;
    double t_s = 0;
    for (double x = x0; x <= x1; x += 0.01, t_s += 0.01) {
      const Vec3 p_WS(x, 0.003, height_m);
      for (std::size_t i = 0; i < fan_.size(); ++i) {
        rays[i] = Ray{p_WS.cast<float>(), fan_[i].cast<float>(), 2.0f, true};
      }
      caster_.Cast(rays, hits);
      for (std::size_t i = 0; i < fan_.size(); ++i) {
        SensorOutput& out = outputs[i];
        out.fresh = true;
        out.detected = hits[i].is_hit();
        out.d_m = out.detected ? hits[i].distance_m : 2.0;
        out.p_WS = p_WS;
        out.dir_W = fan_[i];
      }
      RobotKnowledge robot;
      robot.X_WP.translation() = Vec3(x, 0, 0.9);
      robot.p_W_front = Vec3(x, 0, 0);
      robot.ground_z_m = 0;
      map.Update(Observation{.t_s = t_s, .sensors = outputs, .robot = &robot});
    }
  }

  TerrainMap MakeMap() const {
    return TerrainMap(TerrainMapConfig{}, std::vector<SensorSpec>(fan_.size(), SensorSpec::Preset(SensorType::kIdeal)),
                      std::vector<bool>(fan_.size(), true));
  }
  const RayCaster& caster() const { return caster_; }

 private:
  RayCaster caster_;
  std::vector<Vec3> fan_;
  std::vector<SensorOutput> outputs_;  // the fan's outputs, reused sweep after sweep
};

std::vector<BodyShape> FloorWith(std::vector<BodyShape> more) {
  more.push_back(BodyShape{Plane{}, Pose::Identity(), 0});
  return more;
}

std::string ReadText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The hazards whose extent holds (x, y).
std::vector<Hazard> HazardsAt(const TerrainMap& map, double x, double y) {
  std::vector<Hazard> found;
  for (const Hazard& h : map.hazards()) {
    if (h.DistanceTo({x, y}) == 0) found.push_back(h);
  }
  return found;
}

TEST(TerrainSweepTest, ABoxTopIsRecoveredWithinOneCentimetreAndIsAnObstacle) {
  // the paper's obstacle: 0.20 × 0.30 × 0.15 m at x = 1.5
  TerrainSweep sweep(FloorWith({BoxShape({1.4, -0.15, 0}, {1.6, 0.15, 0.15}, 1)}));
  TerrainMap map = sweep.MakeMap();
  sweep.Run(map, 0.0, 1.2);
  int top_cells = 0;
  for (double x = 1.41; x < 1.6; x += kR) {
    for (double y = -0.13; y < 0.15; y += kR) {
      const TerrainCell* cell = map.CellAt(x, y);
      if (cell == nullptr || !cell->has_elevation()) continue;
      ++top_cells;
      EXPECT_NEAR(cell->elevation_m, 0.15, 0.01) << "at " << x << ", " << y;
    }
  }
  EXPECT_GT(top_cells, 100) << "most of the top's 150 cells are seen";
  // the floor before it, flat
  for (double x = 0.51; x < 1.3; x += kR) {
    const TerrainCell* cell = map.CellAt(x, 0.01);
    ASSERT_NE(cell, nullptr);
    ASSERT_TRUE(cell->has_elevation());
    EXPECT_NEAR(cell->elevation_m, 0.0, 1e-4);
  }
  const auto at_box = HazardsAt(map, 1.5, 0.0);
  ASSERT_EQ(at_box.size(), 1u);
  EXPECT_EQ(at_box[0].hazard_class, HazardClass::kObstacle);
  EXPECT_NEAR(at_box[0].height_m, 0.15, 0.01);
  EXPECT_EQ(map.hazards().size(), 1u);
  // first seen from afar: the leading point 0.1 m behind the sensor's x, a fan reaching ~0.7 m ahead
  EXPECT_GT(at_box[0].distance_at_detection_m, 0.3);
}

// A floor 0.3 m thick around a pit (x0..x1, y0..y1) whose bottom is `depth` down.
std::vector<BodyShape> PitScene(double x0, double x1, double y0, double y1, double depth) {
  const double t = 0.5;
  return {BoxShape({-1, -2, -t}, {x0, 2, 0}, 0), BoxShape({x1, -2, -t}, {4, 2, 0}, 0),
          BoxShape({x0, y1, -t}, {x1, 2, 0}, 0),  BoxShape({x0, -2, -t}, {x1, y0, 0}, 0),
          BoxShape({x0, y0, -depth - 0.1}, {x1, y1, -depth}, 2)};
}

TEST(TerrainSweepTest, AHolesDepthIsRecoveredWithinOneCentimetreAndIsAHole) {
  TerrainSweep sweep(PitScene(1.3, 1.7, -0.5, 0.5, 0.3));
  TerrainMap map = sweep.MakeMap();
  sweep.Run(map, 0.0, 2.0);
  int bottom_cells = 0;
  for (double x = 1.33; x < 1.68; x += kR) {
    for (double y = -0.47; y < 0.48; y += kR) {
      const TerrainCell* cell = map.CellAt(x, y);
      if (cell == nullptr || !cell->has_elevation()) continue;
      ++bottom_cells;
      EXPECT_NEAR(cell->elevation_m, -0.3, 0.01) << "at " << x << ", " << y;
    }
  }
  EXPECT_GT(bottom_cells, 200);
  const auto at_pit = HazardsAt(map, 1.5, 0.0);
  ASSERT_EQ(at_pit.size(), 1u);
  EXPECT_EQ(at_pit[0].hazard_class, HazardClass::kHole);
  EXPECT_NEAR(at_pit[0].height_m, -0.3, 0.01);
  EXPECT_EQ(map.hazards().size(), 1u);
}

TEST(TerrainSweepTest, AStepUpAStepDownAndATallObstacleAreClassifiedSo) {
  {
    TerrainSweep sweep(FloorWith({BoxShape({1.0, -1.0, 0}, {3.0, 1.0, 0.12}, 1)}));  // a platform 0.12 up
    TerrainMap map = sweep.MakeMap();
    sweep.Run(map, 0.0, 0.8);
    const auto found = HazardsAt(map, 1.05, 0.0);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].hazard_class, HazardClass::kStepUp);
    EXPECT_NEAR(found[0].height_m, 0.12, 0.01);
  }
  {
    TerrainSweep sweep(PitScene(1.0, 3.0, -1.0, 1.0, 0.12));  // a lower floor 0.12 down
    TerrainMap map = sweep.MakeMap();
    sweep.Run(map, 0.0, 0.8);
    const auto found = HazardsAt(map, 1.1, 0.0);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].hazard_class, HazardClass::kStepDown);
    EXPECT_NEAR(found[0].height_m, -0.12, 0.01);
  }
  {
    TerrainSweep sweep(FloorWith({BoxShape({1.0, -1.0, 0}, {3.0, 1.0, 0.35}, 1)}));  // too high to step on
    TerrainMap map = sweep.MakeMap();
    sweep.Run(map, 0.0, 0.8);
    const auto found = HazardsAt(map, 1.0, 0.0);  // its face: the top is above the fan's reach
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].hazard_class, HazardClass::kObstacle);
    EXPECT_GT(found[0].height_m, 0.2);
  }
}

TEST(TerrainSweepTest, TheTruthFieldIsTheHighestSurfaceBelowTheCeiling) {
  TerrainSweep sweep(FloorWith({BoxShape({1.0, -0.1, 0}, {1.2, 0.1, 0.15}, 1), BoxShape({2.0, -0.1, 0}, {2.2, 0.1, 1.5}, 2),
                         BoxShape({3.0, -0.1, 0.7}, {3.2, 0.1, 0.75}, 3)}));
  const CellBox row{0, 0, 199, 0};
  const std::vector<float> truth = TrueHeights(sweep.caster(), row, kR, 0.6);
  // heights are the ceiling less a ray's hit distance: Embree's SSE4.2, AVX2
  // and AVX-512 paths differ in its last bits, a float ulp at the ceiling's
  // 0.6 m being 6e-8 m; 1e-6 m is a few ulps of the scene's metre scale
  constexpr float kUlps_m = 1e-6f;
  EXPECT_NEAR(truth[20], 0.0f, kUlps_m);      // the floor
  EXPECT_NEAR(truth[55], 0.15f, kUlps_m);     // the box's top
  EXPECT_NEAR(truth[105], 0.6f, kUlps_m);     // a tall cupboard: full to the ceiling
  EXPECT_NEAR(truth[155], 0.0f, kUlps_m);     // under a table top at 0.75 m: the floor
  const TerrainSweep nothing({BoxShape({0, -1, -0.1}, {1, 1, 0}, 0)});
  const std::vector<float> void_row = TrueHeights(nothing.caster(), CellBox{40, 0, 60, 0}, kR, 0.6);
  EXPECT_NEAR(void_row[0], 0.0f, kUlps_m);
  EXPECT_TRUE(std::isnan(void_row[20]));      // beyond the floor's edge: no surface
}

// ------------------------------------------------------------ whole runs

Scenario FloorWalk(double duration_s, std::uint64_t seed) {
  return LoadScenarioText(R"(proxsim: 1
seed: )" + std::to_string(seed) + R"(
duration_s: )" + std::to_string(duration_s) + R"(
rate_hz: 100
scene: {objects: [{name: floor, plane: {}}]}
robot:
  model: builtin:biped
  gait: {stride_m: 0.6, period_s: 1.2}
  path: {waypoints_m: [[0, 0], [100, 0]]}
sensors:
  - {name: ideal, type: ideal, link: left_tibia, pose: &m {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 15, 0]}}
  - {name: laser, type: laser, link: left_tibia, pose: *m}
  - {name: ultrasonic, type: ultrasonic, link: left_tibia, pose: *m}
  - {name: reflectance, type: reflectance, link: left_tibia, pose: *m}
  - {name: laser_down, type: laser, link: right_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 40, 0]}}
)",
                          "floor_walk.yaml");
}

TEST(TerrainRunTest, AFlatFloorReadByThePapersNoisySensorsHoldsNoHazardOverTwentySeeds) {
  Simulation sim(FloorWalk(5.0, 1));
  std::size_t measured_total = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    sim.Reset(seed);
    while (!sim.done()) sim.Step();
    const TerrainMap& map = *sim.terrain_map();
    EXPECT_TRUE(map.hazards().empty()) << "seed " << seed << ": " << map.hazards().size() << " hazards, the first a "
                                       << HazardClassName(map.hazards().front().hazard_class) << " at "
                                       << map.hazards().front().centroid_W.transpose();
    // and the floor it measured is flat within the noise
    map.grid().ForEachTile([&](const ElevationGrid::Tile& tile) {
      for (const TerrainCell& cell : tile.cells) {
        if (!cell.has_elevation()) continue;
        ++measured_total;
        EXPECT_LT(std::abs(cell.elevation_m), 0.01f);
        EXPECT_FALSE(cell.upper_bound_m < -0.01f) << "free space below the floor";
      }
    });
  }
  EXPECT_GT(measured_total, 20u * 100u);
}

// A strategy that only watches the map, as a strategy would.
class MapWatcher : public Strategy {
 public:
  std::string name() const override { return "map_watcher"; }
  void Reset(const StrategySetup&) override { first_seen_t_s = -1; }
  void Decide(const Observation& observation, RobotCommands&, EventLog&) override {
    if (observation.map != nullptr && first_seen_t_s < 0 && !observation.map->hazards().empty()) {
      first_seen_t_s = observation.t_s;
    }
  }
  double first_seen_t_s = -1;
};

TEST(TerrainRunTest, ThePapersRunMapsTheFloorAndFindsTheObstacleBeforeTheRobotStops) {
  Simulation sim(LoadBuiltinScenario("paper"));
  while (!sim.done()) sim.Step();
  const TerrainMap& map = *sim.terrain_map();
  // the floor: measured cells along the walk, flat
  int floor_cells = 0;
  for (double x = 0.01; x < 2.3; x += kR) {
    for (double y = -0.3; y < 0.3; y += kR) {
      const TerrainCell* cell = map.CellAt(x, y);
      if (cell == nullptr || !cell->has_elevation()) continue;
      ++floor_cells;
      EXPECT_LT(std::abs(cell->elevation_m), 0.01f) << "at " << x << ", " << y;
    }
  }
  EXPECT_GT(floor_cells, 60);
  // the obstacle (x 2.4–2.6, y ±0.15, 0.15 high): found, before the robot stood still
  ASSERT_FALSE(map.hazards().empty());
  const Hazard& obstacle = map.hazards().front();
  EXPECT_EQ(obstacle.hazard_class, HazardClass::kObstacle);
  EXPECT_LT(obstacle.DistanceTo({2.4, 0.1}), 0.03);
  EXPECT_GT(obstacle.height_m, 0.04);
  ASSERT_TRUE(sim.robot_outcome().stopped);
  EXPECT_LT(obstacle.first_detection_t_s, sim.robot_outcome().stop_t_s);
  EXPECT_GT(obstacle.distance_at_detection_m, 0.25);

  // a strategy sees the same map, at the same sample
  Simulation watched(LoadBuiltinScenario("paper"), 1, nullptr, std::make_unique<MapWatcher>());
  while (!watched.done()) watched.Step();
  EXPECT_DOUBLE_EQ(static_cast<const MapWatcher*>(watched.strategy())->first_seen_t_s,
                   watched.terrain_map()->hazards().front().first_detection_t_s);
}

TEST(TerrainRunTest, TheStairsCoursesMapHoldsTheStepsAndTheLandingAndFindsEveryStepUpAndHoleAhead) {
  const auto out = std::filesystem::temp_directory_path() / ("proxsim_terrain_stairs_" + std::to_string(getpid()));
  std::filesystem::remove_all(out);
  RunOptions options;
  options.out_dir = out.string();
  const RunResult result =
      RunScenario(LoadScenarioFile(std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/terrain_stairs_course.yaml"), options);
  // the landing, 0.6 m up, is in the map (its ceiling rides with the robot), within a centimetre
  const auto meta = nlohmann::json::parse(ReadText(out / "terrain" / "meta.json"));
  EXPECT_NEAR(meta["truth_ceiling_z_m"].get<double>(), 1.2, 1e-6);
  std::filesystem::remove_all(out);
  const nlohmann::json& terrain = result.summary["terrain"];
  EXPECT_GT(terrain["cells_measured"].get<int>(), 400);
  EXPECT_LT(terrain["elevation_error"]["p95_m"].get<double>(), 0.015);
  // every true hazard in the corridor (the four steps up, each from the
  // tread before it; the two holes) is found before the toe reaches it
  int steps_up = 0, holes = 0;
  for (const auto& truth : terrain["true_hazards"]) {
    const std::string kind = truth["class"];
    steps_up += kind == "step_up";
    holes += kind == "hole";
    EXPECT_TRUE(truth["detected"].get<bool>()) << kind << " at x = " << truth["x_m"];
    if (!truth["detected"].get<bool>()) continue;
    // (the first riser, seen from the floor, is the latest: 0.04 m ahead of the toe)
    EXPECT_GT(truth["lead_distance_m"].get<double>(), 0.02) << kind << " at x = " << truth["x_m"];
    if (kind == "hole") {
      EXPECT_NEAR(truth["height_m"].get<double>(), -0.5, 1e-3);
      EXPECT_EQ(truth["found_as"], "hole");
    }
  }
  EXPECT_EQ(steps_up, 4);
  EXPECT_EQ(holes, 2);
  EXPECT_EQ(terrain["hazards"]["classes"]["hole"]["recall"], 1.0);
}

TEST(TerrainRunTest, ASixtySecondWalksMapHoldsConstantMemoryPerMetreWalked) {
  // a map that never retires a tile: what each metre walked costs it (the
  // rolling window's test is terrain_window_test.cc)
  Scenario scenario = FloorWalk(60.0, 3);
  scenario.map.window_m = 1e9;
  Simulation sim(scenario);
  std::vector<std::pair<double, double>> bytes_per_metre;  // at 20, 40, 60 s
  while (!sim.done()) {
    sim.Step();
    const std::int64_t k = sim.samples_taken();
    if (k == 2000 || k == 4000 || k == 6000) {
      const double walked_m = sim.robot_state()->distance_walked_m;
      bytes_per_metre.emplace_back(walked_m, static_cast<double>(sim.terrain_map()->grid().memory_bytes()) / walked_m);
    }
  }
  ASSERT_EQ(bytes_per_metre.size(), 3u);
  EXPECT_GT(bytes_per_metre[2].first, 25.0);
  for (const auto& [walked_m, per_metre] : bytes_per_metre) {
    std::printf("[ measured ] %.1f m walked: %.0f bytes of map per metre\n", walked_m, per_metre);
    EXPECT_NEAR(per_metre / bytes_per_metre[2].second, 1.0, 0.15);
  }
}

// ------------------------------------------------------------ files


TEST(TerrainFilesTest, TheRunWritesTheContractsFilesAndTheSummaryScoresTheMap) {
  const auto out = std::filesystem::temp_directory_path() / ("proxsim_terrain_files_" + std::to_string(getpid()));
  std::filesystem::remove_all(out);
  RunOptions options;
  options.out_dir = out.string();
  const RunResult result = RunScenario(LoadBuiltinScenario("paper"), options);
  const auto dir = out / "terrain";
  for (const char* name : {"meta.json", "elevation.npy", "variance.npy", "upper_bound.npy", "truth.npy", "hits.npy",
                           "first_update_t_s.npy", "last_update_t_s.npy", "hazards.csv", "map.bt"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / name)) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(out / "terrain.tmp"));
  const auto meta = nlohmann::json::parse(ReadText(dir / "meta.json"));
  EXPECT_EQ(meta["resolution_m"], 0.02);
  const long ny = meta["shape"][0], nx = meta["shape"][1];
  // each array: a .npy header naming its shape, then ny·nx values of 4 bytes
  for (const char* name : {"elevation.npy", "variance.npy", "upper_bound.npy", "truth.npy", "hits.npy"}) {
    const std::string npy = ReadText(dir / name);
    ASSERT_EQ(npy.substr(1, 5), "NUMPY");
    const std::size_t header = 10 + static_cast<unsigned char>(npy[8]) + 256 * static_cast<unsigned char>(npy[9]);
    EXPECT_EQ(header % 64, 0u);
    EXPECT_NE(npy.find("'shape': (" + std::to_string(ny) + ", " + std::to_string(nx) + ")"), std::string::npos) << name;
    EXPECT_NE(npy.find(std::string(name) == "hits.npy" ? "'<u4'" : "'<f4'"), std::string::npos);
    EXPECT_EQ(npy.size(), header + 4u * static_cast<std::size_t>(ny * nx)) << name;
  }
  const std::string hazards = ReadText(dir / "hazards.csv");
  EXPECT_EQ(hazards.substr(0, hazards.find('\n')),
            "class,x_m,y_m,size_x_m,size_y_m,height_m,first_detection_t_s,distance_at_detection_m");
  EXPECT_EQ(hazards.substr(hazards.find('\n') + 1, 9), "obstacle,");
  EXPECT_EQ(ReadText(dir / "map.bt").substr(0, 28), "# Octomap OcTree binary file");
  // the summary's score
  const nlohmann::json& terrain = result.summary["terrain"];
  EXPECT_GT(terrain["cells_measured"].get<int>(), 60);
  EXPECT_LT(terrain["elevation_error"]["p95_m"].get<double>(), 0.01);
  EXPECT_EQ(terrain["hazards"]["classes"]["obstacle"]["recall"], 1.0);
  ASSERT_EQ(terrain["true_hazards"].size(), 1u);
  EXPECT_TRUE(terrain["true_hazards"][0]["detected"].get<bool>());
  EXPECT_LT(terrain["true_hazards"][0]["first_detection_t_s"].get<double>(), result.summary["robot"]["stop_t_s"].get<double>());
  std::filesystem::remove_all(out);
}

TEST(OctomapRecorderTest, ADetectionMarksItsPointOccupiedAndItsRayFree) {
  OctomapRecorder octomap(0.02);
  RayEvidence hit;
  hit.p_WS = Vec3(0.01, 0.01, 0.5);
  hit.dir_W = -Vec3::UnitZ();
  hit.detected = true;
  hit.d_m = 0.5;
  hit.free_end_m = 0.48;
  hit.bounds_height = hit.proves_empty = true;
  octomap.Add(hit);
  EXPECT_TRUE(octomap.IsOccupied({0.01, 0.01, 0.0}));
  EXPECT_TRUE(octomap.IsFree({0.01, 0.01, 0.25}));
  RayEvidence silent = hit;  // too shallow for a floor to echo: says nothing
  silent.detected = false;
  silent.bounds_height = false;
  silent.p_WS = Vec3(1.01, 0.01, 0.5);
  octomap.Add(silent);
  EXPECT_FALSE(octomap.IsFree({1.01, 0.01, 0.25}));
  const auto path = std::filesystem::temp_directory_path() / ("proxsim_octomap_" + std::to_string(getpid()) + ".bt");
  octomap.WriteBinary(path.string());
  // octovis's reader (OctoMap's own) gets the same voxels back
  octomap::OcTree tree(0.1);
  ASSERT_TRUE(tree.readBinary(path.string()));
  EXPECT_DOUBLE_EQ(tree.getResolution(), 0.02);
  EXPECT_EQ(tree.getNumLeafNodes(), octomap.leaf_count());
  const octomap::OcTreeNode* hit_voxel = tree.search(0.01, 0.01, 0.0);
  ASSERT_NE(hit_voxel, nullptr);
  EXPECT_TRUE(tree.isNodeOccupied(hit_voxel));
  const octomap::OcTreeNode* free_voxel = tree.search(0.01, 0.01, 0.25);
  ASSERT_NE(free_voxel, nullptr);
  EXPECT_FALSE(tree.isNodeOccupied(free_voxel));
  EXPECT_EQ(tree.search(1.01, 0.01, 0.25), nullptr);
  std::filesystem::remove(path);
}

// ------------------------------------------------------------ the scenario's map section

std::vector<std::string> TerrainProblemsOf(const std::string& text) {
  try {
    LoadScenarioText(text, "s.yaml");
  } catch (const InputError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

TEST(TerrainScenarioTest, TheMapSectionIsReadAndEveryMistakeInItListed) {
  const std::string robot = "proxsim: 1\nrobot: {model: builtin:biped}\nsensors: [{name: a, type: laser, link: left_tibia}, {name: b, type: reflectance, link: left_tibia}]\n";
  const Scenario s = LoadScenarioText(robot + "map: {resolution_m: 0.05, max_height_m: 0.4, obstacle_min_m: 0.03, sensors: [b]}\n", "s.yaml");
  EXPECT_DOUBLE_EQ(s.map.resolution_m, 0.05);
  EXPECT_DOUBLE_EQ(s.map.max_height_m, 0.4);
  EXPECT_DOUBLE_EQ(s.map.obstacle_min_m, 0.03);
  EXPECT_DOUBLE_EQ(s.map.drop_min_m, 0.05);
  EXPECT_EQ(s.map.sensors, std::vector<std::string>{"b"});
  Simulation sim(s);
  EXPECT_FALSE(sim.terrain_map()->feeds_map(0));
  EXPECT_TRUE(sim.terrain_map()->feeds_map(1));
  // by default every sensor but the reflectance ones
  Simulation by_default(LoadScenarioText(robot, "s.yaml"));
  EXPECT_TRUE(by_default.terrain_map()->feeds_map(0));
  EXPECT_FALSE(by_default.terrain_map()->feeds_map(1));
  EXPECT_EQ(Simulation(LoadScenarioText(robot + "map: {enabled: false}\n", "s.yaml")).terrain_map(), nullptr);

  const auto problems = TerrainProblemsOf(robot + R"(map:
  resolution_m: 0
  step_max_m: 0.01
  sensors: [a, c, a]
  colour: red
)");
  ASSERT_EQ(problems.size(), 5u);
  EXPECT_EQ(problems[0], "s.yaml:5: map.resolution_m: expected a number in [0.005, 1] m, got 0");
  EXPECT_EQ(problems[1], "s.yaml:6: map.step_max_m: expected at least obstacle_min_m (0.04) and drop_min_m (0.05), got 0.01");
  EXPECT_EQ(problems[2], "s.yaml:7: map.sensors[1]: unknown sensor 'c' (did you mean 'a'?); expected one of a, b");
  EXPECT_EQ(problems[3], "s.yaml:7: map.sensors[2]: sensor 'a' is listed twice");
  EXPECT_NE(problems[4].find("s.yaml:8: map.colour: unknown key 'colour'"), std::string::npos) << problems[4];
  const auto no_robot = TerrainProblemsOf("proxsim: 1\nmap: {resolution_m: 0.02}\n");
  ASSERT_EQ(no_robot.size(), 1u);
  EXPECT_EQ(no_robot[0], "s.yaml:2: map: the terrain map is built by a walking robot; expected a robot section with it");
}

}  // namespace
}  // namespace proxsim
