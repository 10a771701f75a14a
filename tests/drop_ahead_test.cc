// The stop rule on drops (docs/terrain.md): a drop deeper than the legs step down,
// seen from the readings alone.
//  - SeeDropAhead on outputs written here, for a sensor 0.3 m above the
//    ground looking down at a known angle: the deep point, the beam's highest
//    ray, the floor missing where it was expected, each against the
//    trigonometry written in the test, and every reason a reading is no sign.
//  - The stop strategy needs the floor missing on two fresh readings in a row
//    (one lost echo does not stop the robot); a deep point stops it at once.
//  - In the closed loop, with sensors just below the knees looking 35 degrees
//    down: the robot stops before a 0.6 m step down, before a 0.6 m hole and
//    before the built-in course's small hole, with `drop_ahead` and without
//    the legs having to refuse a step; it walks down a 0.2 m step. The rule is
//    run through a test strategy that keeps a copy of everything it was
//    given; a fresh rule fed those copies alone, away from the simulation,
//    stops at the same sample.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scenario/scenario.h"
#include "sim/simulation.h"
#include "strategy/drop_ahead.h"
#include "strategy/stop_strategy.h"

namespace proxsim {
namespace {

constexpr double kSensorZ_m = 0.3;
constexpr double kMaxDrop_m = 0.32;

// The robot: standing on z = 0, heading +x, its leading toe at x = toe_x.
RobotKnowledge Self(double toe_x_m) {
  RobotKnowledge self;
  self.ground_z_m = 0;
  self.heading_W = Vec3::UnitX();
  self.p_W_front = Vec3(toe_x_m, 0, 0);
  return self;
}

SensorInfo Info(double max_range_m, double max_incidence_deg, double aperture_deg = 0) {
  return SensorInfo{.name = "s", .type = SensorType::kIdeal, .min_range_m = 0, .max_range_m = max_range_m,
                    .link = "left_tibia", .max_incidence_deg = max_incidence_deg, .aperture_deg = aperture_deg};
}

// A fresh output of a sensor at (0, y, 0.3) looking down by depression_deg along +x.
SensorOutput Output(double depression_deg, double d_m, bool detected, double y_m = 0) {
  const double a = DegToRad(depression_deg);
  SensorOutput out;
  out.fresh = true;
  out.detected = detected;
  out.d_m = d_m;
  out.p_WS = Vec3(0, y_m, kSensorZ_m);
  out.dir_W = Vec3(std::cos(a), 0, -std::sin(a));
  return out;
}

StopConfig Rule(double stop_distance_m = 0.5) {
  StopConfig rule;
  rule.stop_distance_m = stop_distance_m;
  return rule;
}

TEST(DropAhead, APointDeeperThanTheLegsStepIsADrop) {
  // looking 60 degrees down, a surface met 0.5 m below the ground:
  // d = 0.8 / sin 60, ahead of the sensor by 0.8 / tan 60
  const double d = 0.8 / std::sin(DegToRad(60));
  const auto sign = SeeDropAhead(Output(60, d, true), Info(2, 90), Self(0.2), Rule(), kMaxDrop_m);
  ASSERT_TRUE(sign.has_value());
  EXPECT_FALSE(sign->floor_missing);
  EXPECT_NEAR(sign->below_m, 0.5, 1e-12);
  EXPECT_NEAR(sign->ahead_m, 0.8 / std::tan(DegToRad(60)) - 0.2, 1e-12);
  EXPECT_NEAR(sign->p_W.z(), -0.5, 1e-12);
  // the same depth seen at 40 degrees lies 0.953 m ahead of the sensor: beyond the look-ahead
  EXPECT_FALSE(SeeDropAhead(Output(40, 0.8 / std::sin(DegToRad(40)), true), Info(2, 90), Self(0.2), Rule(),
                            kMaxDrop_m));
  // a step of 0.2 m, and the floor itself, are no drop
  EXPECT_FALSE(SeeDropAhead(Output(60, 0.5 / std::sin(DegToRad(60)), true), Info(2, 90), Self(0.2), Rule(), kMaxDrop_m));
  EXPECT_FALSE(SeeDropAhead(Output(60, 0.3 / std::sin(DegToRad(60)), true), Info(2, 90), Self(0.2), Rule(), kMaxDrop_m));
}

TEST(DropAhead, ABeamCountsItsHighestRay) {
  // the axis meets z = -0.5; a ray 15 degrees above it, at the same distance,
  // is at 0.3 - d sin 45: 0.353 m below the ground, still deeper than 0.32 m
  const double d = 0.8 / std::sin(DegToRad(60));
  const auto sign = SeeDropAhead(Output(60, d, true), Info(2, 90, 30), Self(0.2), Rule(), kMaxDrop_m);
  ASSERT_TRUE(sign.has_value());
  EXPECT_NEAR(sign->below_m, d * std::sin(DegToRad(45)) - kSensorZ_m, 1e-12);
  // 20 degrees above it: 0.3 - d sin 40 = -0.294, the echo may come from a surface that high
  EXPECT_FALSE(SeeDropAhead(Output(60, d, true), Info(2, 90, 40), Self(0.2), Rule(), kMaxDrop_m));
}

TEST(DropAhead, TheFloorMissingWhereItWasExpected) {
  // 45 degrees down: the axis crosses the ground 0.3 m ahead of the sensor and
  // passes 0.32 m below it 0.62 m ahead; nothing echoes within 2 m
  const auto sign = SeeDropAhead(Output(45, 2.0, false), Info(2, 90), Self(0.15), Rule(), kMaxDrop_m);
  ASSERT_TRUE(sign.has_value());
  EXPECT_TRUE(sign->floor_missing);
  EXPECT_NEAR(sign->p_W.x(), kSensorZ_m + kMaxDrop_m, 1e-12);
  EXPECT_NEAR(sign->p_W.z(), -kMaxDrop_m, 1e-12);
  EXPECT_NEAR(sign->ahead_m, kSensorZ_m + kMaxDrop_m - 0.15, 1e-12);
  EXPECT_NEAR(sign->below_m, kMaxDrop_m, 1e-12);
  // a laser's floor at 45 degrees of incidence would not echo either (window 45, 3 degrees inside it) ...
  EXPECT_FALSE(SeeDropAhead(Output(45, 2.0, false), Info(2, 45), Self(0.15), Rule(), kMaxDrop_m));
  // ... at 40 degrees (50 degrees down) the floor would, but a riser across
  // the axis would be met at 50 degrees and echo nothing: silence proves nothing
  EXPECT_FALSE(SeeDropAhead(Output(50, 2.0, false), Info(2, 45), Self(0.05), Rule(), kMaxDrop_m));
  // with a 60-degree window both the floor (40) and a riser (50) would echo
  EXPECT_TRUE(SeeDropAhead(Output(50, 2.0, false), Info(2, 60), Self(0.05), Rule(), kMaxDrop_m));
  // 85 degrees down, the toe 0.2 m behind the sensor: the floor at 5 degrees
  // would echo, a riser at 85 degrees would not with a 60-degree window
  EXPECT_TRUE(SeeDropAhead(Output(85, 2.0, false), Info(2, 90), Self(-0.2), Rule(), kMaxDrop_m));
  EXPECT_FALSE(SeeDropAhead(Output(85, 2.0, false), Info(2, 60), Self(-0.2), Rule(), kMaxDrop_m));
}

TEST(DropAhead, NothingReportedIsNoSignUnlessTheFreeSpaceIsDeepAndNear) {
  const SensorInfo ideal = Info(2, 90);
  // a range of 0.8 m ends at 0.3 - 0.8 sin 45 = -0.266 m: not deep enough
  EXPECT_FALSE(SeeDropAhead(Output(45, 0.8, false), Info(0.8, 90), Self(0.15), Rule(), kMaxDrop_m));
  // a self echo reports a distance: the floor was hidden, not missing
  EXPECT_FALSE(SeeDropAhead(Output(45, 0.3, false), ideal, Self(0.15), Rule(), kMaxDrop_m));
  // no news
  SensorOutput stale = Output(45, 2.0, false);
  stale.fresh = false;
  EXPECT_FALSE(SeeDropAhead(stale, ideal, Self(0.15), Rule(), kMaxDrop_m));
  // where the floor was expected is within 0.1 m of the toe (the feet hide it): 0.3 - 0.25
  EXPECT_FALSE(SeeDropAhead(Output(45, 2.0, false), ideal, Self(0.25), Rule(), kMaxDrop_m));
  // the deep point 0.47 m ahead of the toe, beyond a 0.4 m look-ahead
  EXPECT_FALSE(SeeDropAhead(Output(45, 2.0, false), ideal, Self(0.15), Rule(0.4), kMaxDrop_m));
  // beside the corridor (0.30 m)
  EXPECT_FALSE(SeeDropAhead(Output(45, 2.0, false, 0.35), ideal, Self(0.15), Rule(), kMaxDrop_m));
  // looking up, or level
  EXPECT_FALSE(SeeDropAhead(Output(-10, 2.0, false), ideal, Self(0.15), Rule(), kMaxDrop_m));
  EXPECT_FALSE(SeeDropAhead(Output(0, 2.0, false), ideal, Self(0.15), Rule(), kMaxDrop_m));
  // no step limit known: no drop rule
  EXPECT_FALSE(SeeDropAhead(Output(45, 2.0, false), ideal, Self(0.15), Rule(), std::nan("")));
}

struct RecordingCommands : RobotCommands {
  int stops = 0;
  void Stop() override { ++stops; }
  void Resume() override {}
  void SetStride(double) override {}
  void SetPath(std::vector<Vec2>) override {}
};
struct RecordingLog : EventLog {
  std::vector<std::string> events;
  std::vector<std::string> details;
  void Log(std::string event, std::string detail) override {
    events.push_back(std::move(event));
    details.push_back(std::move(detail));
  }
};

TEST(StopStrategyOnDrops, TheFloorMissingTwiceInARowStopsADeepPointAtOnce) {
  const std::vector<SensorInfo> infos = {Info(2, 90)};
  StopStrategy rule(StopConfig{});
  StrategySetup setup;
  setup.sensors = infos;
  setup.max_step_m = kMaxDrop_m;
  rule.Reset(setup);
  const RobotKnowledge self = Self(0.15);
  RecordingCommands robot;
  RecordingLog log;
  const auto decide = [&](const SensorOutput& out) {
    const Observation observation{.t_s = 0, .sample = 0, .sensors = std::span(&out, 1), .robot = &self};
    rule.Decide(observation, robot, log);
  };
  const SensorOutput missing = Output(45, 2.0, false);
  SensorOutput stale = missing;
  stale.fresh = false;
  const SensorOutput floor = Output(45, kSensorZ_m / std::sin(DegToRad(45)), true);
  // missing, floor (resets), missing, no news (keeps), missing: the stop
  decide(missing);
  decide(floor);
  decide(missing);
  decide(stale);
  EXPECT_EQ(robot.stops, 0);
  decide(missing);
  EXPECT_EQ(robot.stops, 1);
  ASSERT_EQ(log.events.size(), 1u);
  EXPECT_EQ(log.events[0], "drop_ahead");
  EXPECT_NE(log.details[0].find("nothing where the floor should be"), std::string::npos) << log.details[0];

  // a deep point: at once
  rule.Reset(setup);
  decide(Output(60, 0.8 / std::sin(DegToRad(60)), true));
  EXPECT_EQ(robot.stops, 2);
  EXPECT_NE(log.details.back().find("0.500 m below the ground"), std::string::npos) << log.details.back();
}

// The built-in stop rule behind a test strategy that keeps a copy of every
// observation it is given, to be replayed away from the simulation.
class CopyingStop : public Strategy {
 public:
  explicit CopyingStop(StopConfig config) : rule_(config) {}
  std::string name() const override { return "copying_stop"; }
  void Reset(const StrategySetup& setup) override {
    infos_.assign(setup.sensors.begin(), setup.sensors.end());
    path_ = setup.path_m;
    rate_hz_ = setup.rate_hz;
    max_step_m_ = setup.max_step_m;
    outputs_.clear();
    selves_.clear();
    rule_.Reset(setup);
  }
  void Decide(const Observation& observation, RobotCommands& robot, EventLog& events) override {
    outputs_.emplace_back(observation.sensors.begin(), observation.sensors.end());
    selves_.push_back(*observation.robot);
    rule_.Decide(observation, robot, events);
  }

  /// The sample at which a fresh rule, fed the copies alone, first stops; -1 if never.
  int Replay(const StopConfig& config) const {
    StopStrategy fresh(config);
    StrategySetup setup;
    setup.sensors = infos_;
    setup.path_m = path_;
    setup.rate_hz = rate_hz_;
    setup.max_step_m = max_step_m_;
    fresh.Reset(setup);
    RecordingCommands robot;
    RecordingLog log;
    for (std::size_t k = 0; k < outputs_.size(); ++k) {
      fresh.Decide(Observation{.t_s = k / rate_hz_, .sample = static_cast<std::int64_t>(k),
                               .sensors = outputs_[k], .robot = &selves_[k]},
                   robot, log);
      if (robot.stops > 0) return static_cast<int>(k);
    }
    return -1;
  }

 private:
  StopStrategy rule_;
  std::vector<SensorInfo> infos_;
  std::vector<Vec2> path_;
  double rate_hz_ = 0;
  double max_step_m_ = 0;
  std::vector<std::vector<SensorOutput>> outputs_;
  std::vector<RobotKnowledge> selves_;
};

// The four sensor types just below each knee, looking 35 degrees down the tibia's front.
std::string Sensors() {
  std::string text = "sensors:\n";
  for (const char* side : {"left", "right"}) {
    for (const char* type : {"ideal", "laser", "ultrasonic", "reflectance"}) {
      text += std::string("  - {name: ") + type + "_" + side + ", type: " + type + ", link: " + side +
              "_tibia, pose: {xyz_m: [0.08, 0, -0.08], rpy_deg: [0, 35, 0]}}\n";
    }
  }
  return text;
}

// Floor (ground) from x = -1 to 2 (top z = 0), then `after` (scene objects), walking to x = 5.
std::string DropScene(const std::string& after) {
  return "proxsim: 1\nseed: 2\nduration_s: 8\nrate_hz: 100\n"
         "scene:\n  objects:\n"
         "    - {name: floor, box: {size_m: [3.0, 3.0, 0.5]}, ground: true, pose: {xyz_m: [0.5, 0, -0.25]}}\n" +
         after +
         "robot:\n  model: builtin:biped\n  gait: {stride_m: 0.6, period_s: 1.2}\n"
         "  path: {waypoints_m: [[0, 0], [5, 0]]}\n" +
         Sensors();
}

struct DropWalk {
  std::vector<StrategyEvent> events;
  Simulation::RobotOutcome outcome;
  double front_toe_x_m = 0;  // the foremost toe where the walk ended
  int stop_sample = -1;      // when the rule asked to stop
  int replayed_stop_sample = -1;
};

DropWalk WalkWithTheRule(const std::string& yaml, const std::string& name) {
  auto strategy = std::make_unique<CopyingStop>(StopConfig{});
  const CopyingStop* copying = strategy.get();
  Simulation sim(LoadScenarioText(yaml, name), 1, nullptr, std::move(strategy));
  DropWalk walk;
  while (!sim.done()) {
    sim.Step();
    if (walk.stop_sample < 0 && !sim.events().empty() && sim.events().back().event == "drop_ahead")
      walk.stop_sample = static_cast<int>(sim.observation().sample);
  }
  walk.events = sim.events();
  walk.outcome = sim.robot_outcome();
  walk.front_toe_x_m = sim.observation().robot->p_W_front.x();
  walk.replayed_stop_sample = copying->Replay(StopConfig{});
  for (const StrategyEvent& e : walk.events)
    std::printf("[ measured ] %s: %.2f s %s: %s\n", name.c_str(), e.t_s, e.event.c_str(), e.detail.c_str());
  std::printf("[ measured ] %s: front toe at x = %.3f m\n", name.c_str(), walk.front_toe_x_m);
  return walk;
}

bool Logged(const DropWalk& walk, const std::string& event) {
  for (const StrategyEvent& e : walk.events)
    if (e.event == event) return true;
  return false;
}

void ExpectStoppedBeforeTheEdgeAt(const DropWalk& walk, double edge_x_m) {
  EXPECT_TRUE(Logged(walk, "drop_ahead"));
  EXPECT_FALSE(Logged(walk, "cannot_step"));  // the rule stopped it, not the legs
  EXPECT_TRUE(walk.outcome.stopped);
  EXPECT_LT(walk.front_toe_x_m, edge_x_m - 0.05);
  EXPECT_GE(walk.stop_sample, 0);
  EXPECT_EQ(walk.replayed_stop_sample, walk.stop_sample);
}

TEST(StopStrategyOnDrops, StopsBeforeADeepStepDown) {
  // the floor beyond x = 2 is 0.6 m lower
  const DropWalk walk = WalkWithTheRule(
      DropScene("    - {name: floor_below, box: {size_m: [4.0, 3.0, 0.5]}, ground: true, pose: {xyz_m: [4.0, 0, -0.85]}}\n"),
      "step_down.yaml");
  ExpectStoppedBeforeTheEdgeAt(walk, 2.0);
}

TEST(StopStrategyOnDrops, StopsBeforeAWideHole) {
  // a hole 0.6 m wide and 0.5 m deep at x = 2 .. 2.6
  const DropWalk walk = WalkWithTheRule(
      DropScene("    - {name: hole_bottom, box: {size_m: [0.6, 3.0, 0.1]}, pose: {xyz_m: [2.3, 0, -0.55]}}\n"
                "    - {name: floor_after, box: {size_m: [3.0, 3.0, 0.5]}, ground: true, pose: {xyz_m: [4.1, 0, -0.25]}}\n"),
      "hole.yaml");
  ExpectStoppedBeforeTheEdgeAt(walk, 2.0);
}

TEST(StopStrategyOnDrops, StopsBeforeTheCoursesSmallHole) {
  // the built-in course from x = 4.3 (the rear foot clear of the last step,
  // which ends at x = 4.0): its 0.25 m hole (0.5 m deep) begins at x = 5
  const std::string yaml =
      "proxsim: 1\nseed: 13\nduration_s: 8\nrate_hz: 100\nscene: {builtin: stairs}\n"
      "robot:\n  model: builtin:biped\n  start: {xyz_m: [4.3, 0, 0], yaw_deg: 0}\n"
      "  gait: {stride_m: 0.5, period_s: 1.2}\n  path: {waypoints_m: [[4.3, 0], [8.5, 0]]}\n" +
      Sensors();
  ExpectStoppedBeforeTheEdgeAt(WalkWithTheRule(yaml, "course.yaml"), 5.0);
}

TEST(StopStrategyOnDrops, WalksDownAShallowStep) {
  // 0.2 m lower beyond x = 2: the legs take it
  const DropWalk walk = WalkWithTheRule(
      DropScene("    - {name: floor_below, box: {size_m: [4.0, 3.0, 0.5]}, ground: true, pose: {xyz_m: [4.0, 0, -0.45]}}\n"),
      "shallow.yaml");
  EXPECT_FALSE(Logged(walk, "drop_ahead"));
  EXPECT_FALSE(Logged(walk, "cannot_step"));
  EXPECT_FALSE(walk.outcome.stopped);
  EXPECT_GT(walk.front_toe_x_m, 3.0);  // a metre past the edge
}

}  // namespace
}  // namespace proxsim
