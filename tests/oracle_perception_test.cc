// The outcome study's oracle baseline perceives perfectly (study/outcome_baselines.h):
// its map holds the scene's true heights within reach ahead of the robot
// (map.truth_within_m, sim/truth_map_feed.h), its legs plan on the true ground
// where a set's would plan on their map, and a staircase's later treads are
// steps to the strategies, not obstacles (knowledge/map_queries.h).
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "knowledge/map_queries.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"
#include "study/outcome_baselines.h"

namespace proxsim {
namespace {

// A blind robot (no sensors) whose map is fed from the truth within 3 m: a
// box on the path at x = 1.6, a table leg (a cylinder taller than the
// map's 0.6 m ceiling) beside it at (2.2, 0.5), a box behind the start and
// one 5 m ahead, out of reach.
std::string OracleWalkText(const std::string& map_extra) {
  return R"(proxsim: 1
seed: 1
duration_s: 1.0
rate_hz: 50
scene:
  objects:
    - {name: floor, plane: {}, ground: true}
    - {name: box, box: {size_m: [0.4, 0.6, 0.3]}, pose: {xyz_m: [1.6, 0, 0.15]}}
    - {name: leg, cylinder: {radius_m: 0.03, length_m: 0.75}, pose: {xyz_m: [2.2, 0.5, 0.375]}}
    - {name: behind, box: {size_m: [0.4, 0.4, 0.3]}, pose: {xyz_m: [-1.5, 0, 0.15]}}
    - {name: far, box: {size_m: [0.4, 0.4, 0.3]}, pose: {xyz_m: [5.5, 0, 0.15]}}
robot:
  model: builtin:biped
  start: {xyz_m: [0, 0, 0], yaw_deg: 0}
  gait: {stride_m: 0.6, period_s: 1.2}
  path: {waypoints_m: [[0, 0], [6, 0]]}
map: {sensors: [], truth_within_m: 3)" +
         map_extra + R"(}
sensors: []
)";
}

double MapHeightAt(const Simulation& sim, double x_m, double y_m) {
  const TerrainCell* cell = sim.terrain_map()->CellAt(x_m, y_m);
  return cell != nullptr && cell->has_elevation() ? cell->elevation_m : std::nan("");
}

TEST(OraclePerception, TheMapHoldsTheTrueHeightsWithinReachAheadAndNothingElse) {
  Simulation sim(LoadScenarioText(OracleWalkText(""), "oracle.yaml"), 1);
  sim.Step();
  // (the floor and the box's top exactly; a 12 mm cell's centre inside the box)
  EXPECT_NEAR(MapHeightAt(sim, 1.61, 0.01), 0.3, 1e-4);
  EXPECT_NEAR(MapHeightAt(sim, 1.0, 0.3), 0.0, 1e-4);
  // the leg crosses the ceiling: its column is full to the ceiling (0.6 m above the ground)
  EXPECT_NEAR(MapHeightAt(sim, 2.2, 0.5), 0.6, 1e-4);
  // behind the robot (beyond kTruthBehind_m) and beyond the reach: unknown
  EXPECT_TRUE(std::isnan(MapHeightAt(sim, -1.5, 0.0)));
  EXPECT_TRUE(std::isnan(MapHeightAt(sim, 5.5, 0.0)));
  // the box (too high to step on) is an obstacle the stop rule's corridor meets
  const Hazard* ahead = ObstacleInCorridor(*sim.terrain_map(), Vec2(0.2, 0), Vec2(1, 0), 1.6, 0.22);
  ASSERT_NE(ahead, nullptr);
  EXPECT_NEAR(ahead->height_m, 0.3, 1e-3);
  EXPECT_NEAR(ahead->min_W.x(), 1.4, 0.03);
}

TEST(OraclePerception, WithoutTruthWithinTheMapOfABlindRobotStaysEmpty) {
  std::string text = OracleWalkText("");
  text.replace(text.find(", truth_within_m: 3"), std::string(", truth_within_m: 3").size(), "");
  Simulation sim(LoadScenarioText(text, "blind.yaml"), 1);
  for (int i = 0; i < 10; ++i) sim.Step();
  EXPECT_TRUE(std::isnan(MapHeightAt(sim, 1.61, 0.01)));
  EXPECT_EQ(sim.terrain_map()->hazards().size(), 0u);
}

TEST(OraclePerception, TruthWithinOutOfRangeIsAnInputError) {
  std::string text = OracleWalkText("");
  const std::string key = "truth_within_m: 3";
  text.replace(text.find(key), key.size(), "truth_within_m: -1");
  EXPECT_THROW(LoadScenarioText(text, "bad.yaml"), std::exception);
}

// A staircase of 0.075 m risers and 0.37 m treads up to a landing 0.3 m up:
// seen from the start, the third tread and the landing are higher above the
// ground stood on than a step (map.step_max_m 0.2): obstacles by the
// classifier, but each touches the step before it within a step's rise.
TEST(OraclePerception, AStaircasesLaterTreadsAreStepsNotObstaclesToWalkAround) {
  std::string text = OracleWalkText("");
  const std::string objects = "  objects:\n    - {name: floor, plane: {}, ground: true}\n";
  std::string stairs = objects;
  for (int k = 1; k <= 4; ++k) {
    const double top = 0.075 * k, x0 = 1.0 + 0.37 * (k - 1), length = k < 4 ? 0.37 : 2.0;
    stairs += "    - {name: step_" + std::to_string(k) + ", box: {size_m: [" + std::to_string(length) + ", 2, " +
              std::to_string(top) + "]}, pose: {xyz_m: [" + std::to_string(x0 + 0.5 * length) + ", 0, " +
              std::to_string(0.5 * top) + "]}, ground: true}\n";
  }
  const std::size_t begin = text.find(objects), end = text.find("robot:");
  text.replace(begin, end - begin, stairs);
  Simulation sim(LoadScenarioText(text, "stairs.yaml"), 1);
  sim.Step();
  const TerrainMap& map = *sim.terrain_map();
  int obstacles = 0;
  for (const Hazard& hazard : map.hazards()) obstacles += hazard.hazard_class == HazardClass::kObstacle;
  EXPECT_GE(obstacles, 1) << "the classifier should call the higher treads obstacles, or this test shows nothing";
  const std::vector<bool> avoid = ObstaclesToWalkAround(map);
  for (std::size_t i = 0; i < avoid.size(); ++i) EXPECT_FALSE(avoid[i]) << "hazard " << i << " over x from " << map.hazards()[i].min_W.x();
  EXPECT_EQ(ObstacleInCorridor(map, Vec2(0.2, 0), Vec2(1, 0), 3.0, 0.22), nullptr);
}

TEST(OraclePerception, AStaircaseTooSteepForTheLegsStaysAnObstacle) {
  // the same treads with 0.25 m risers: no tread is within a step's rise of the ground or of another
  std::string text = OracleWalkText("");
  const std::string objects = "  objects:\n    - {name: floor, plane: {}, ground: true}\n";
  std::string stairs = objects;
  for (int k = 1; k <= 2; ++k) {
    const double top = 0.25 * k, x0 = 1.0 + 0.37 * (k - 1);
    stairs += "    - {name: step_" + std::to_string(k) + ", box: {size_m: [0.37, 2, " + std::to_string(top) +
              "]}, pose: {xyz_m: [" + std::to_string(x0 + 0.185) + ", 0, " + std::to_string(0.5 * top) + "]}, ground: true}\n";
  }
  const std::size_t begin = text.find(objects), end = text.find("robot:");
  text.replace(begin, end - begin, stairs);
  Simulation sim(LoadScenarioText(text, "steep.yaml"), 1);
  sim.Step();
  EXPECT_NE(ObstacleInCorridor(*sim.terrain_map(), Vec2(0.2, 0), Vec2(1, 0), 3.0, 0.22), nullptr);
}

TEST(OraclePerception, TheOraclesRunPerceivesPerfectlyAndItsLegsPlanOnTheTruth) {
  // legs on the robot's own map: the oracle's plan on the true ground and stand before what they cannot take
  YAML::Node run = YAML::Load(
      "{robot: {gait: {footholds: map, stride_m: 0.5}, strategy: {name: stop, perception: map}}, map: {resolution_m: 0.012}}");
  GiveOraclePerception(run);
  EXPECT_EQ(run["robot"]["gait"]["footholds"].as<std::string>(), "truth");
  EXPECT_EQ(run["robot"]["gait"]["unsafe_steps"].as<std::string>(), "refuse");
  EXPECT_EQ(run["robot"]["gait"]["stride_m"].as<double>(), 0.5);
  EXPECT_EQ(run["map"]["truth_within_m"].as<double>(), kOracleReach_m);
  EXPECT_EQ(run["map"]["max_height_m"].as<double>(), kOracleMapCeiling_m);
  EXPECT_EQ(run["map"]["resolution_m"].as<double>(), 0.012);
  EXPECT_EQ(run["map"]["sensors"].size(), 0u);
  // legs on the truth already: the gait is left as it was
  YAML::Node truth =
      YAML::Load("{robot: {gait: {stride_m: 0.5}, strategy: {name: stop, perception: map}}, map: {max_height_m: 2.0}}");
  GiveOraclePerception(truth);
  EXPECT_FALSE(truth["robot"]["gait"]["footholds"]);
  EXPECT_FALSE(truth["robot"]["gait"]["unsafe_steps"]);
  EXPECT_EQ(truth["map"]["max_height_m"].as<double>(), 2.0);
  // a strategy reading each reading reads the fan: no true map (nothing would read it)
  YAML::Node readings = YAML::Load("{robot: {strategy: {name: stop}}}");
  GiveOraclePerception(readings);
  EXPECT_FALSE(readings["map"]);
}

}  // namespace
}  // namespace proxsim
