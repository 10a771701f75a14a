// The built-in strategies reading the map (perception: map) with a map
// filled from the truth (map.truth_within_m, the outcome study's oracle):
// `stop` waits for a person crossing its corridor and walks on once it has
// stayed clear (a box never clears: it stays stopped — the baseline that must
// not walk on); `circumvent` waits for the person too, and walks a route
// around a wall across the way through its gap (docs/strategies.md).
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "scenario/scenario.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

// The biped from (0, 0) to (4, 0), no sensors, its map the truth within 3 m,
// with `objects` (YAML list items) and `strategy`.
std::string WalkOnText(const std::string& objects, const std::string& strategy) {
  return "proxsim: 1\nduration_s: 20\nrate_hz: 50\nscene:\n  objects:\n"
         "    - {name: floor, plane: {}, ground: true}\n" +
         objects +
         "robot:\n  model: builtin:biped\n  path: {waypoints_m: [[0, 0], [4, 0]]}\n"
         "  strategy: " + strategy + "\n"
         "map: {sensors: [], truth_within_m: 3, max_height_m: 1.2}\nsensors: []\n";
}

// a person crossing the path slowly at x = 1.6, from y = -0.5 at 0.3 m/s:
// it reaches the corridor while the robot is still more than 0.9 m away
// (kPedestrianKeep_m: it would yield there), then yields to the robot
// coming, standing in its way; standing, the robot is passed
const char* const kCrossingPerson =
    "    - {name: walker, person: {height_m: 1.7}, motion: {waypoints_m: [[1.6, -0.5], [1.6, 2]], speed_m_s: 0.3, "
    "mode: once}}\n";

bool Logged(const Simulation& sim, const std::string& event) {
  const auto& events = sim.events();
  return std::any_of(events.begin(), events.end(), [&](const StrategyEvent& e) { return e.event == event; });
}

TEST(StrategiesWalkOn, StopWaitsForAPersonCrossingItsCorridorThenWalksOnToTheGoal) {
  const std::string stop = "{name: stop, perception: map, corridor_half_width_m: 0.22}";
  Simulation sim(LoadScenarioText(WalkOnText(kCrossingPerson, stop), "walk_on.yaml"), 1);
  while (!sim.done()) sim.Step();
  EXPECT_TRUE(Logged(sim, "obstacle_ahead")) << "the person must have stopped it, or this test shows nothing";
  EXPECT_TRUE(Logged(sim, "walking_on"));
  EXPECT_TRUE(sim.robot_outcome().collisions.empty()) << sim.robot_outcome().collisions.front().object;
  EXPECT_EQ(sim.outcome().name(), "reached_goal");
}

TEST(StrategiesWalkOn, StopForABoxNeverWalksOn) {
  const std::string stop = "{name: stop, perception: map, corridor_half_width_m: 0.22}";
  Simulation sim(LoadScenarioText(
                     WalkOnText("    - {name: box, box: {size_m: [0.3, 0.6, 0.4]}, pose: {xyz_m: [1.6, 0, 0.2]}}\n", stop),
                     "walk_on.yaml"),
                 1);
  while (!sim.done()) sim.Step();
  EXPECT_TRUE(Logged(sim, "obstacle_ahead"));
  EXPECT_FALSE(Logged(sim, "walking_on"));
  EXPECT_TRUE(sim.robot_outcome().collisions.empty());
  EXPECT_EQ(sim.outcome().name(), "stopped");
}

TEST(StrategiesWalkOn, CircumventReachesTheGoalPastAPersonCrossingItsWay) {
  Simulation sim(LoadScenarioText(WalkOnText(kCrossingPerson, "{name: circumvent, perception: map}"), "walk_on.yaml"), 1);
  while (!sim.done()) sim.Step();
  EXPECT_TRUE(sim.robot_outcome().collisions.empty()) << sim.robot_outcome().collisions.front().object;
  EXPECT_EQ(sim.outcome().name(), "reached_goal");
}

TEST(StrategiesWalkOn, CircumventWalksARouteThroughTheGapOfAWallAcrossItsWay) {
  // a wall across the way at x = 2 from y = -2 to 0.4 and from 1.4 to 3: the gap is y in [0.4, 1.4]
  const std::string walls =
      "    - {name: wall_a, box: {size_m: [0.1, 2.4, 0.8]}, pose: {xyz_m: [2.0, -0.8, 0.4]}}\n"
      "    - {name: wall_b, box: {size_m: [0.1, 1.6, 0.8]}, pose: {xyz_m: [2.0, 2.2, 0.4]}}\n";
  Simulation sim(LoadScenarioText(WalkOnText(walls, "{name: circumvent, perception: map}"), "walk_on.yaml"), 1);
  while (!sim.done()) sim.Step();
  EXPECT_TRUE(Logged(sim, "route_planned"));
  EXPECT_TRUE(sim.robot_outcome().collisions.empty()) << sim.robot_outcome().collisions.front().object;
  EXPECT_EQ(sim.outcome().name(), "reached_goal");
  // (the stop rule, the baseline, stands before the wall)
  Simulation stop(LoadScenarioText(WalkOnText(walls, "{name: stop, perception: map, corridor_half_width_m: 0.22}"),
                                   "walk_on.yaml"),
                  1);
  while (!stop.done()) stop.Step();
  EXPECT_EQ(stop.outcome().name(), "stopped");
}

}  // namespace
}  // namespace proxsim
