// One built world, many sensor rigs (sim/world.h, sim/sensor_rig.h): a
// simulation on a world shared with others in turn reads, walks and ends
// exactly as one on a world of its own, whatever ran on the world before it;
// one simulation holds a world at a time; a scenario of another scene or
// robot is refused on it; and an outcome study builds one world per room, not
// one per run.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "core/input_error.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"
#include "sim/world.h"
#include "study/outcome_config.h"
#include "study/outcome_runner.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;

// the dining room with a person crossing the robot's way: moving bodies, people waiting, a strategy
std::string SharedWorldScenario(const std::string& sensors, const std::string& stop = "0.5") {
  return "proxsim: 1\nseed: 3\nduration_s: 5.0\nrate_hz: 50\n"
         "scene:\n  builtin: dining_room\n  objects:\n"
         "    - {name: walker, person: {height_m: 1.7}, motion: {waypoints_m: [[2.1, -1.5], [2.1, 1.5]], "
         "mode: back_and_forth, speed_m_s: 0.9, start_s: 1.5}}\n"
         "    - {name: post, box: {size_m: [0.1, 0.1, 0.4]}, pose: {xyz_m: [3.5, 1.0, 0.2]}}\n"
         "robot:\n  model: builtin:biped\n  gait: {stride_m: 0.6, period_s: 1.2}\n"
         "  path: {waypoints_m: [[0, 0], [4.5, 0]]}\n  stop_distance_m: " +
         stop + "\nsensors: " + sensors + "\n";
}

const char* const kLasers =
    "[{name: a, type: laser, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 15, 0]}},"
    " {name: b, type: laser, link: right_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 8, 20]}}]";
const char* const kSonar = "[{name: s, type: hc_sr04, link: left_thigh, pose: {xyz_m: [0.07, 0, -0.2]}}]";

// every sample's readings and the pelvis's place, then the outcome
struct Walk {
  std::vector<double> d_m;
  std::vector<double> pelvis_x_m;
  std::string outcome;
  double outcome_t_s = 0;
};

Walk WalkToTheEnd(Simulation& sim) {
  Walk walk;
  while (!sim.done()) {
    const SampleFrame& frame = sim.Step();
    for (const SensorSample& sample : frame.sensors) walk.d_m.push_back(sample.reading.d_m);
    walk.pelvis_x_m.push_back(sim.robot_state()->X_WP.translation().x());
  }
  walk.outcome = sim.outcome().name();
  walk.outcome_t_s = sim.outcome().t_s;
  return walk;
}

// the same binary on the same machine: bit for bit
void ExpectSameWalk(const Walk& a, const Walk& b, const std::string& what) {
  EXPECT_EQ(a.d_m, b.d_m) << what;
  EXPECT_EQ(a.pelvis_x_m, b.pelvis_x_m) << what;
  EXPECT_EQ(a.outcome, b.outcome) << what;
  EXPECT_EQ(a.outcome_t_s, b.outcome_t_s) << what;
}

Walk OnItsOwnWorld(const std::string& text) {
  Simulation sim(LoadScenarioText(text, "own.yaml"), 1);
  return WalkToTheEnd(sim);
}

Walk OnWorld(const std::string& text, const std::shared_ptr<World>& world) {
  Simulation sim(LoadScenarioText(text, "shared.yaml"), 1, world);
  return WalkToTheEnd(sim);
}

TEST(SharedWorld, EachRigOnOneWorldWalksAsOnAWorldOfItsOwn) {
  const std::string lasers = SharedWorldScenario(kLasers), sonar = SharedWorldScenario(kSonar, "0.3");
  const std::string blind = SharedWorldScenario("[]");
  const Walk own_lasers = OnItsOwnWorld(lasers), own_sonar = OnItsOwnWorld(sonar);
  // the lasers see the walker cross (a world whose moving bodies were left
  // where the last walk put them would read otherwise), and the walker waits
  // for the robot at least once (its wait must not carry over either)
  ASSERT_LT(*std::min_element(own_lasers.d_m.begin(), own_lasers.d_m.end()), 1.5);

  // built from the blind scenario: the world has no sensors of its own
  const std::int64_t built_before = World::BuiltCount();
  const std::shared_ptr<World> world = BuildWorld(LoadScenarioText(blind, "blind.yaml"), 1);
  ExpectSameWalk(OnWorld(lasers, world), own_lasers, "lasers, first on the world");
  ExpectSameWalk(OnWorld(sonar, world), own_sonar, "the sonar, after the lasers");
  OnWorld(blind, world);
  ExpectSameWalk(OnWorld(lasers, world), own_lasers, "the lasers again, after the sonar and a blind walk");
  EXPECT_EQ(World::BuiltCount() - built_before, 1);
}

TEST(SharedWorld, OneSimulationHoldsAWorldAtATime) {
  const std::shared_ptr<World> world = BuildWorld(LoadScenarioText(SharedWorldScenario("[]"), "blind.yaml"), 1);
  {
    Simulation first(LoadScenarioText(SharedWorldScenario(kLasers), "first.yaml"), 1, world);
    EXPECT_THROW(Simulation(LoadScenarioText(SharedWorldScenario(kSonar), "second.yaml"), 1, world), std::logic_error);
  }
  // a simulation that fails to build (a link the robot lacks) hands the world back
  const std::string bad = SharedWorldScenario("[{name: x, type: laser, link: left_tibiaa}]");
  EXPECT_THROW(Simulation(LoadScenarioText(bad, "bad.yaml"), 1, world), InputError);
  Simulation after(LoadScenarioText(SharedWorldScenario(kSonar), "after.yaml"), 1, world);
  EXPECT_FALSE(after.done());
}

TEST(SharedWorld, ASimulationOfAnotherSceneOrRobotIsRefused) {
  const std::shared_ptr<World> world = BuildWorld(LoadScenarioText(SharedWorldScenario("[]"), "blind.yaml"), 1);
  const auto refusal = [&](const std::string& text) -> std::string {
    try {
      Simulation sim(LoadScenarioText(text, "other.yaml"), 1, world);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "";
  };
  std::string empty_room = SharedWorldScenario(kLasers);
  empty_room.replace(empty_room.find("dining_room"), 11, "empty");
  EXPECT_NE(refusal(empty_room).find("the scene has"), std::string::npos) << refusal(empty_room);
  std::string sphere = SharedWorldScenario(kLasers);
  sphere.replace(sphere.find("box: {size_m: [0.1, 0.1, 0.4]}"), 30, "sphere: {radius_m: 0.2}");
  EXPECT_NE(refusal(sphere).find("is 'post' (sphere), the world's 'post' (box)"), std::string::npos) << refusal(sphere);
  std::string geometry = SharedWorldScenario(kLasers);
  geometry.replace(geometry.find("model: builtin:biped"), 20, "model: builtin:biped\n  geometry: collision");
  EXPECT_NE(refusal(geometry).find("the robot differs"), std::string::npos) << refusal(geometry);
  EXPECT_EQ(refusal(SharedWorldScenario(kSonar, "0.2")), "");
}

// 2 rooms x (2 sets + blind + oracle) x 2 strategies and each room's reference walk:
// 18 runs on 2 worlds, and one more for the study's check of its sets
TEST(SharedWorld, AnOutcomeStudyBuildsOneWorldPerRoom) {
  const fs::path dir = testing::FreshDir("shared_world_study");
  fs::create_directories(dir);
  std::ofstream(dir / "walker.yaml") << "proxsim: 1\nseed: 1\nduration_s: 3.0\nrate_hz: 50\nscene: {builtin: empty}\n"
                                        "robot:\n  model: builtin:biped\n  gait: {stride_m: 0.6, period_s: 1.2}\n";
  std::ofstream(dir / "study.yaml")
      << "proxsim_study: 1\nmode: outcomes\nbase: walker.yaml\n"
      << "sets:\n  - {name: one, sensors: " << kSonar << "}\n  - {name: two, sensors: " << kLasers << "}\n"
      << "strategies: [{name: stop}, {name: stop, perception: map}]\n"
      << "worlds: {generate: {kind: room, difficulty: 0.5}, seeds: {from: 1, to: 2}}\n";
  const OutcomeStudyConfig study = LoadOutcomeStudyFile((dir / "study.yaml").string());
  const std::int64_t built_before = World::BuiltCount();
  bool writer = false;
  const OutcomeResults results =
      RunOutcomeStudy(study, {.out_dir = (dir / "out").string(), .threads = 1, .progress = false}, &writer);
  ASSERT_EQ(results.size(), 2u);
  for (const OutcomeJob& job : results) EXPECT_EQ(job.runs.size(), 8u);
  EXPECT_EQ(World::BuiltCount() - built_before, 3);
}

}  // namespace
}  // namespace proxsim
