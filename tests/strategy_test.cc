// Strategies in the closed loop, on small scenes written here: what a
// strategy receives carries no truth (checked on the types), the built-in
// stop rule stops before a box, circumvent walks around a box on either side
// to its goal and stops before a wall it cannot pass, a user's strategy is
// injected and commands the robot, and Reset() gives a fresh simulation's
// episode sample for sample.
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "scenario/scenario.h"
#include "sim/simulation.h"
#include "strategy/circumvent_strategy.h"
#include "strategy/stop_strategy.h"

namespace proxsim {
namespace {

// the truth's names: none may be reachable from what a strategy is given
template <typename T> concept HasStatus = requires(T t) { t.status; };
template <typename T> concept HasTrueDistance = requires(T t) { t.d_true_m; };
template <typename T> concept HasEcho = requires(T t) { t.echo; };
template <typename T> concept HasHitPoint = requires(T t) { t.p_WH; };
template <typename T> concept HasObject = requires(T t) { t.object_id; };
template <typename T> concept HasReading = requires(T t) { t.reading; };
template <typename T> concept HasClearance = requires(T t) { t.min_clearance_m; };

template <typename T>
constexpr bool CarriesTruth() {
  return HasStatus<T> || HasTrueDistance<T> || HasEcho<T> || HasHitPoint<T> || HasObject<T> || HasReading<T> ||
         HasClearance<T>;
}

TEST(StrategyTypes, WhatAStrategyReceivesHasNoTruth) {
  // the check works: the simulation's own sample does carry the truth
  EXPECT_TRUE(CarriesTruth<SensorSample>());
  EXPECT_FALSE(CarriesTruth<SensorOutput>());
  EXPECT_FALSE(CarriesTruth<SensorInfo>());
  EXPECT_FALSE(CarriesTruth<RobotKnowledge>());
  EXPECT_FALSE(CarriesTruth<FootKnowledge>());
  EXPECT_FALSE(CarriesTruth<Observation>());
  EXPECT_FALSE(CarriesTruth<StrategySetup>());
}

// A room of its own: a floor, a box of the given size at (x, y), four lasers on the tibias.
std::string Scene(const std::string& box_size, double box_x, double box_y, const std::string& strategy,
                  double duration_s = 14.0) {
  return "proxsim: 1\nseed: 1\nduration_s: " + std::to_string(duration_s) +
         "\nrate_hz: 100\n"
         "scene:\n  objects:\n"
         "    - {name: floor, plane: {}}\n"
         "    - {name: obstacle, box: {size_m: " + box_size + "}, pose: {xyz_m: [" + std::to_string(box_x) + ", " +
         std::to_string(box_y) + ", 0.075]}}\n"
         "robot:\n  model: builtin:biped\n  gait: {stride_m: 0.6, period_s: 1.2}\n"
         "  path: {waypoints_m: [[0, 0], [4.5, 0]]}\n"
         "  strategy: " + strategy + "\n"
         "sensors:\n"
         "  - {name: la, type: laser, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 8, 0]}}\n"
         "  - {name: ra, type: laser, link: right_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 8, 0]}}\n"
         "  - {name: lo, type: laser, link: left_tibia, pose: {xyz_m: [0.06, 0.02, -0.35], rpy_deg: [0, 8, 30]}}\n"
         "  - {name: ro, type: laser, link: right_tibia, pose: {xyz_m: [0.06, -0.02, -0.35], rpy_deg: [0, 8, -30]}}\n";
}

struct StrategyWalk {
  double max_abs_y_m = 0;  // the pelvis's largest distance from the path line
  double sum_y_m = 0;      // signed: which side it went round
  std::vector<std::string> events;
  Simulation::RobotOutcome outcome;
};

StrategyWalk RunToEnd(Simulation& sim) {
  StrategyWalk walk;
  while (!sim.done()) {
    sim.Step();
    const double y = sim.robot_state()->X_WP.translation().y();
    walk.max_abs_y_m = std::max(walk.max_abs_y_m, std::abs(y));
    walk.sum_y_m += y;
  }
  for (const StrategyEvent& event : sim.events()) walk.events.push_back(event.event);
  walk.outcome = sim.robot_outcome();
  return walk;
}

bool Logged(const StrategyWalk& walk, const std::string& event) {
  return std::find(walk.events.begin(), walk.events.end(), event) != walk.events.end();
}

TEST(StopStrategy, StopsBeforeABoxFromTheReadingsAlone) {
  Simulation sim(LoadScenarioText(Scene("[0.2, 0.3, 0.15]", 2.5, 0.0, "{name: stop, stop_distance_m: 0.5}", 6.0),
                                  "stop.yaml"),
                 1);
  const StrategyWalk walk = RunToEnd(sim);
  ASSERT_TRUE(walk.outcome.stopped);
  EXPECT_TRUE(Logged(walk, "obstacle_ahead"));
  EXPECT_GT(walk.outcome.min_clearance_m, 0.0);
  // the box's near face is at x = 2.4 m: the robot stands short of it
  EXPECT_LT(sim.robot_state()->X_WP.translation().x(), 2.4);
  EXPECT_FALSE(walk.outcome.reached_goal);
}

// Circumvent, with the box off the path: the robot passes on the side with more room.
struct SideCase {
  double box_y_m;
  int expected_side;  // +1 left, -1 right
};
class CircumventSides : public ::testing::TestWithParam<SideCase> {};

TEST_P(CircumventSides, WalksAroundTheBoxToItsGoal) {
  const SideCase c = GetParam();
  const CircumventConfig config;
  Simulation sim(LoadScenarioText(Scene("[0.2, 0.3, 0.15]", 2.5, c.box_y_m, "{name: circumvent}"), "c.yaml"), 1);
  const StrategyWalk walk = RunToEnd(sim);
  EXPECT_TRUE(walk.outcome.reached_goal);
  EXPECT_FALSE(walk.outcome.stop_requested);
  EXPECT_GT(walk.outcome.min_clearance_m, config.margin_m / 2);
  EXPECT_TRUE(Logged(walk, "obstacle_seen"));
  EXPECT_TRUE(Logged(walk, "detour_planned"));
  EXPECT_TRUE(Logged(walk, "obstacle_passed"));
  EXPECT_TRUE(Logged(walk, "rejoined"));
  EXPECT_TRUE(Logged(walk, "goal_reached"));
  EXPECT_EQ(walk.sum_y_m > 0 ? 1 : -1, c.expected_side);
  // a detour, not a wander: the pelvis went aside by at least the box's overlap with its path
  EXPECT_GT(walk.max_abs_y_m, 0.2);
  EXPECT_LT(walk.max_abs_y_m, config.max_detour_m);
}

INSTANTIATE_TEST_SUITE_P(BoxBesideThePath, CircumventSides,
                         ::testing::Values(SideCase{-0.1, +1}, SideCase{+0.1, -1}));

TEST(CircumventStrategy, StopsBeforeAWallItCannotPass) {
  // 4 m wide: more than max_detour_m each side
  Simulation sim(LoadScenarioText(Scene("[0.2, 4.0, 0.15]", 2.5, 0.0, "{name: circumvent}", 8.0), "wall.yaml"), 1);
  const StrategyWalk walk = RunToEnd(sim);
  EXPECT_TRUE(walk.outcome.stopped);
  EXPECT_FALSE(walk.outcome.reached_goal);
  EXPECT_GT(walk.outcome.min_clearance_m, 0.0);
  EXPECT_TRUE(Logged(walk, "no_way_around") || Logged(walk, "blocked"));
  EXPECT_LT(sim.robot_state()->X_WP.translation().x(), 2.4);
}

// A user's strategy, injected: it stops the robot after a second and makes it walk on at three.
class PauseStrategy : public Strategy {
 public:
  std::string name() const override { return "pause"; }
  void Reset(const StrategySetup& setup) override {
    sensors_ = setup.sensors.size();
    decisions_ = 0;
  }
  void Decide(const Observation& observation, RobotCommands& robot, EventLog& events) override {
    ++decisions_;
    EXPECT_EQ(observation.sensors.size(), sensors_);
    ASSERT_NE(observation.robot, nullptr);
    if (observation.sample == 100) {
      robot.Stop();
      events.Log("pause", "one second in");
    }
    if (observation.sample == 300) robot.Resume();
  }
  std::size_t sensors_ = 0;
  int decisions_ = 0;
};

TEST(UserStrategy, IsInjectedAndCommandsTheRobot) {
  auto strategy = std::make_unique<PauseStrategy>();
  PauseStrategy* pause = strategy.get();
  Simulation sim(LoadScenarioText(Scene("[0.2, 0.3, 0.15]", 9.0, 0.0, "{name: stop}", 5.0), "u.yaml"), 1, nullptr,
                 std::move(strategy));
  double x_at_2s = 0, x_at_3s = 0;
  while (!sim.done()) {
    const SampleFrame& frame = sim.Step();
    if (frame.sample == 200) x_at_2s = sim.robot_state()->X_WP.translation().x();
    if (frame.sample == 300) x_at_3s = sim.robot_state()->X_WP.translation().x();
  }
  EXPECT_EQ(pause->decisions_, 500);
  EXPECT_EQ(sim.strategy()->name(), "pause");
  EXPECT_DOUBLE_EQ(x_at_2s, x_at_3s);  // standing between the stop and the resume
  EXPECT_GT(sim.robot_state()->X_WP.translation().x(), x_at_3s + 0.5);
  EXPECT_EQ(sim.events().front().event, "pause");
}

TEST(SimulationReset, GivesAFreshSimulationsEpisodeSampleForSample) {
  const Scenario scenario = LoadBuiltinScenario("paper");
  Scenario seeded = scenario;
  seeded.seed = 11;
  Simulation fresh(seeded, 1);
  Simulation reused(scenario, 1);
  for (int k = 0; k < 250; ++k) reused.Step();
  reused.commands()->SetStride(0.4);
  reused.Reset(11);
  while (!fresh.done()) {
    ASSERT_FALSE(reused.done());
    const SampleFrame& a = fresh.Step();
    const SampleFrame& b = reused.Step();
    ASSERT_EQ(a.sample, b.sample);
    for (std::size_t i = 0; i < a.sensors.size(); ++i) {
      ASSERT_EQ(a.sensors[i].reading.d_m, b.sensors[i].reading.d_m) << "sample " << a.sample;
      ASSERT_EQ(a.sensors[i].reading.status, b.sensors[i].reading.status);
      ASSERT_EQ(a.sensors[i].p_WS, b.sensors[i].p_WS);
    }
  }
  EXPECT_TRUE(reused.done());
  EXPECT_EQ(fresh.robot_outcome().stop_t_s, reused.robot_outcome().stop_t_s);
  EXPECT_EQ(fresh.robot_outcome().min_clearance_m, reused.robot_outcome().min_clearance_m);
  ASSERT_EQ(fresh.events().size(), reused.events().size());
  for (std::size_t i = 0; i < fresh.events().size(); ++i) EXPECT_EQ(fresh.events()[i].detail, reused.events()[i].detail);
}

}  // namespace
}  // namespace proxsim
