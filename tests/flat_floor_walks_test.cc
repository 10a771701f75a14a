// On a flat floor nothing should end a walk but its goal or its time: over
// 500 episodes per robot — the built-in biped and the Unitree H1 — each with
// a random path of turns up to ±90°, a stride changed at random every
// second (0.3 to 0.9 m) and a stop-and-resume now and then, 30 s long, no
// episode falls (a joint-limit excess the gait's own planner makes is not a fall:
// the gait takes the step within its limits, issue 36) and none collides.
// The randomness is the test's own (a seeded 64-bit Mersenne twister, its
// bits scaled by hand: the same draws with any standard library).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <string>

#include "cli_helpers.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::kH1Dir;

constexpr int kFlatFloorEpisodes = 500;

double FlatFloorUniform(std::mt19937_64& rng, double low, double high) {
  return low + (high - low) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// A path from the origin: four legs of 0.8 to 2 m, each turned up to 90° from the last.
std::vector<Vec2> FlatFloorRandomPath(std::mt19937_64& rng) {
  std::vector<Vec2> path{Vec2::Zero()};
  double yaw = 0;
  for (int leg = 0; leg < 4; ++leg) {
    yaw += FlatFloorUniform(rng, -M_PI / 2, M_PI / 2);
    path.push_back(path.back() + FlatFloorUniform(rng, 0.8, 2.0) * Vec2(std::cos(yaw), std::sin(yaw)));
  }
  return path;
}

std::map<std::string, int> FlatFloorWalkEpisodes(const std::string& robot_yaml) {
  const Scenario scenario = LoadScenarioText(
      "proxsim: 1\nduration_s: 30\nrate_hz: 50\n"
      "scene: {builtin: empty, objects: [{name: floor, plane: {}}]}\n"
      "robot:\n" + robot_yaml + "  path: {waypoints_m: [[0, 0], [1, 0]]}\nsensors: []\n",
      "flat.yaml");
  Simulation sim(scenario, 1);
  std::map<std::string, int> outcomes;
  for (int episode = 0; episode < kFlatFloorEpisodes; ++episode) {
    std::mt19937_64 rng(1000 + static_cast<std::uint64_t>(episode));
    sim.Reset(static_cast<std::uint64_t>(episode));
    sim.commands()->SetPath(FlatFloorRandomPath(rng));
    for (int sample = 0; !sim.done(); ++sample) {
      if (sample % 50 == 0) sim.commands()->SetStride(FlatFloorUniform(rng, 0.3, 0.9));
      // now and then a stop, and a second later the walk resumes
      if (sample % 50 == 25 && FlatFloorUniform(rng, 0, 1) < 0.1) sim.commands()->Stop();
      if (sample % 50 == 24) sim.commands()->Resume();
      sim.Step();
    }
    ++outcomes[std::string(sim.outcome().name())];
    // (not a vacuous walk: every episode covers ground)
    const double walked_m = sim.observation().robot->distance_walked_m;
    EXPECT_GT(walked_m, 1.0) << "episode " << episode << ": " << sim.outcome().detail;
    outcomes["metres walked"] += static_cast<int>(walked_m);
    EXPECT_NE(sim.outcome().name(), "fell") << "episode " << episode << ": " << sim.outcome().detail;
    EXPECT_NE(sim.outcome().name(), "collided") << "episode " << episode << ": " << sim.outcome().detail;
  }
  return outcomes;
}

TEST(FlatFloorWalks, TheBuiltInBipedNeverFallsOverRandomStridesAndTurns) {
  const auto outcomes = FlatFloorWalkEpisodes("  model: builtin:biped\n");
  EXPECT_EQ(outcomes.count("fell"), 0u);
  EXPECT_GT(outcomes.at("metres walked"), kFlatFloorEpisodes * 3);
}

TEST(FlatFloorWalks, TheH1NeverFallsOverRandomStridesAndTurns) {
  if (!fs::is_regular_file(kH1Dir / "urdf" / "h1.urdf")) GTEST_SKIP() << "the Unitree H1 is not at " << kH1Dir;
  const auto outcomes = FlatFloorWalkEpisodes(
      "  model: " + (kH1Dir / "urdf" / "h1.urdf").string() + "\n  package_paths: [" +
      kH1Dir.parent_path().string() +
      "]\n  legs:\n"
      "    left:  {hip: left_hip_pitch_joint,  knee: left_knee_joint,  ankle: left_ankle_joint,  foot: left_ankle_link}\n"
      "    right: {hip: right_hip_pitch_joint, knee: right_knee_joint, ankle: right_ankle_joint, foot: right_ankle_link}\n");
  EXPECT_EQ(outcomes.count("fell"), 0u);
  EXPECT_GT(outcomes.at("metres walked"), kFlatFloorEpisodes * 3);
}

// A stride beyond the legs, asked on level ground with gait.unsafe_steps:
// fall: where no gentler step (half the turn, 0.7, 0.5 or 0.35 of the
// stride) fits its legs either, the robot stands before the step — its own
// limits (a refusal), never a fall. (Before: "fell".)
struct FlatFloorWalked {
  Simulation::Outcome outcome;
  double distance_m;
};

FlatFloorWalked FlatFloorAskedStride(double stride_m) {
  Simulation sim(LoadScenarioText("proxsim: 1\nduration_s: 8\nrate_hz: 50\n"
                                  "scene: {builtin: empty, objects: [{name: floor, plane: {}}]}\n"
                                  "robot:\n  model: builtin:biped\n  gait: {unsafe_steps: fall}\n"
                                  "  path: {waypoints_m: [[0, 0], [20, 0]]}\nsensors: []\n",
                                  "flat.yaml"),
                 1);
  for (int sample = 0; !sim.done(); ++sample) {
    if (sample == 50) sim.commands()->SetStride(stride_m);
    sim.Step();
  }
  return {sim.outcome(), sim.observation().robot->distance_walked_m};
}

TEST(FlatFloorWalks, AStrideBeyondTheLegsOnLevelGroundIsStoodNeverFallen) {
  for (const double stride_m : {3.0, 30.0}) {
    const FlatFloorWalked walked = FlatFloorAskedStride(stride_m);
    EXPECT_EQ(walked.outcome.name(), "refused") << stride_m << ": " << walked.outcome.detail;
    EXPECT_GT(walked.distance_m, 0.3) << stride_m << ": the steps before it were walked";
  }
}

}  // namespace
}  // namespace proxsim
