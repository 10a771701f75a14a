// The robot section's keys for bringing one's own robot (io/scenario_robot.cc):
// robot.geometry, robot.package_paths (resolved against the scenario's
// folder), robot.legs, robot.joints_deg (degrees in, radians out), and which
// of stride and period the legs set when the gait section leaves them out;
// and each mistake reported at its line with its key path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "core/input_error.h"
#include "scenario/scenario.h"
#include "sim/run_summary.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> RobotProblemsOf(const std::string& text, const std::string& source) {
  try {
    LoadScenarioText(text, source);
  } catch (const InputError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return {};
}

bool HasProblem(const std::vector<std::string>& problems, const std::vector<std::string>& fragments) {
  return std::ranges::any_of(problems, [&](const std::string& problem) {
    return std::ranges::all_of(fragments, [&](const std::string& f) { return problem.find(f) != std::string::npos; });
  });
}

std::string Join(const std::vector<std::string>& lines) {
  std::string all;
  for (const std::string& line : lines) all += line + "\n";
  return all;
}

class ScenarioRobotTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::FreshDir("scenario_robot");
    fs::create_directories(dir_ / "packages");
    std::ofstream(dir_ / "robot.urdf") << "<robot name=\"r\"><link name=\"base\"/></robot>\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Source() const { return (dir_ / "scenario.yaml").string(); }
  fs::path dir_;
};

TEST_F(ScenarioRobotTest, OwnRobotKeysParse) {
  const Scenario s = LoadScenarioText(R"(proxsim: 1
robot:
  model: robot.urdf
  geometry: collision
  package_paths: [packages, /tmp]
  legs:
    left:  {hip: lh, knee: lk, ankle: la, foot: lf}
    right: {hip: rh, knee: rk, ankle: ra, foot: rf}
  joints_deg: {shoulder: 10, elbow: -45.5}
  gait: {stride_m: 0.5}
)",
                                      Source());
  const RobotConfig& r = *s.robot;
  EXPECT_EQ(r.geometry, LinkGeometryKind::kCollision);
  ASSERT_EQ(r.package_paths.size(), 2u);
  EXPECT_EQ(fs::path(r.package_paths[0]), dir_ / "packages");
  EXPECT_EQ(r.package_paths[1], "/tmp");
  ASSERT_TRUE(r.legs);
  EXPECT_EQ((*r.legs)[0].hip, "lh");
  EXPECT_EQ((*r.legs)[0].foot, "lf");
  EXPECT_EQ((*r.legs)[1].knee, "rk");
  EXPECT_EQ((*r.legs)[1].ankle, "ra");
  ASSERT_EQ(r.joints_rad.size(), 2u);
  EXPECT_EQ(r.joints_rad[0].first, "shoulder");
  EXPECT_DOUBLE_EQ(r.joints_rad[0].second, DegToRad(10));
  EXPECT_DOUBLE_EQ(r.joints_rad[1].second, DegToRad(-45.5));
  // the stride given, the period left to the legs
  EXPECT_FALSE(r.gait.derive_stride_from_legs);
  EXPECT_TRUE(r.gait.derive_period_from_legs);
  EXPECT_DOUBLE_EQ(r.gait.stride_m, 0.5);
}

// summary.json's `inputs.robot` echoes every robot key the scenario gave,
// the ones that change an outcome included (issue 37: `unsafe_steps`,
// `footholds`, `on_collision` and eight more were missing): a key given here
// that the echo leaves out, or echoes with another value, fails.
TEST_F(ScenarioRobotTest, TheSummaryEchoesEveryRobotKeyAScenarioGave) {
  const Scenario s = LoadScenarioText(R"(proxsim: 1
scene:
  objects: [{name: crate, box: {size_m: [0.6, 0.6, 0.1]}, pose: {xyz_m: [0, 0, 0.05]}}]
robot:
  model: robot.urdf
  model_scene: ignore
  geometry: collision
  geom_group: 3
  package_paths: [/tmp]
  legs:
    left:  {hip: lh, knee: lk, ankle: la, foot: lf, ankle_zero_deg: 10}
    right: {hip: rh, knee: rk, ankle: ra, foot: rf}
  joints_deg: {shoulder: 10}
  on_collision: continue
  start: {xyz_m: [0, 0, 0.1], yaw_deg: 5, on: crate}
  gait: {stride_m: 0.5, period_s: 1.1, max_step_m: 0.15, unsafe_steps: refuse, footholds: map,
         touchdown_tolerance_m: 0.03, crouch_knee_deg: 20}
  path: {waypoints_m: [[2, 0]]}
  stop_distance_m: 0.3
)",
                                      Source());
  const nlohmann::json robot = InputsJson(s)["robot"];
  EXPECT_EQ(robot["model_scene"], "ignore");
  EXPECT_EQ(robot["geometry"], "collision");
  EXPECT_EQ(robot["geom_group"], 3);
  EXPECT_EQ(robot["package_paths"], nlohmann::json::array({"/tmp"}));
  EXPECT_EQ(robot["legs"]["left"]["hip"], "lh");
  EXPECT_EQ(robot["legs"]["right"]["foot"], "rf");
  EXPECT_NEAR(robot["legs"]["left"]["ankle_zero_deg"].get<double>(), 10.0, 1e-12);
  EXPECT_NEAR(robot["joints_deg"]["shoulder"].get<double>(), 10.0, 1e-12);
  EXPECT_EQ(robot["on_collision"], "continue");
  EXPECT_EQ(robot["start"]["on"], "crate");
  EXPECT_NEAR(robot["start"]["yaw_deg"].get<double>(), 5.0, 1e-12);
  const nlohmann::json& gait = robot["gait"];
  EXPECT_EQ(gait["stride_m"], 0.5);
  EXPECT_EQ(gait["period_s"], 1.1);
  EXPECT_EQ(gait["max_step_m"], 0.15);
  EXPECT_EQ(gait["unsafe_steps"], "refuse");
  EXPECT_EQ(gait["footholds"], "map");
  EXPECT_EQ(gait["touchdown_tolerance_m"], 0.03);
  EXPECT_NEAR(gait["crouch_knee_deg"].get<double>(), 20.0, 1e-12);
  EXPECT_EQ(robot["path"]["waypoints_m"], nlohmann::json::parse("[[2.0, 0.0]]"));
  EXPECT_EQ(robot["strategy"]["name"], "stop");
  EXPECT_EQ(robot["strategy"]["stop_distance_m"], 0.3);
  // the defaults are echoed as such, not left out
  const nlohmann::json plain = InputsJson(LoadScenarioText("proxsim: 1\nrobot: {model: robot.urdf}\n", Source()))["robot"];
  EXPECT_EQ(plain["on_collision"], "stop");
  EXPECT_EQ(plain["model_scene"], "include");
  EXPECT_EQ(plain["gait"]["unsafe_steps"], "fall");
  EXPECT_EQ(plain["gait"]["footholds"], "truth");
  EXPECT_TRUE(plain["gait"]["max_step_m"].is_null());  // from the legs
  EXPECT_TRUE(plain["legs"].is_null());                // found by the gait
  EXPECT_TRUE(plain["start"]["on"].is_null());
}

TEST_F(ScenarioRobotTest, DefaultsVisualGeometryBuiltinLegsAndAGaitScaledToTheLegs) {
  const Scenario s = LoadScenarioText("proxsim: 1\nrobot: {model: robot.urdf}\n", Source());
  EXPECT_EQ(s.robot->geometry, LinkGeometryKind::kVisual);
  EXPECT_TRUE(s.robot->package_paths.empty());
  EXPECT_FALSE(s.robot->legs);
  EXPECT_TRUE(s.robot->joints_rad.empty());
  EXPECT_TRUE(s.robot->gait.derive_stride_from_legs);
  EXPECT_TRUE(s.robot->gait.derive_period_from_legs);
  // a RobotConfig built in code walks the stride it holds
  EXPECT_FALSE(RobotConfig{}.gait.derive_stride_from_legs);
}

TEST_F(ScenarioRobotTest, MistakesAreReportedAtTheirKeys) {
  const std::vector<std::string> problems = RobotProblemsOf(R"(proxsim: 1
robot:
  model: robot.urdf
  geometry: meshes
  package_paths: [packages, no_such_folder]
  legs:
    left:  {hip: lh, knee: lk, ankle: la, fot: lf}
  joints_deg: [10, 20]
)",
                                                       Source());
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:4:", "robot.geometry", "expected visual or collision, got 'meshes'"}))
      << Join(problems);
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "robot.package_paths[1]", "expected a folder",
                                    (dir_ / "no_such_folder").string() + "' is not one"}))
      << Join(problems);
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:7:", "robot.legs.left.fot", "did you mean 'foot'?"})) << Join(problems);
  EXPECT_TRUE(HasProblem(problems, {"robot.legs.left.foot: missing"})) << Join(problems);
  EXPECT_TRUE(HasProblem(problems, {"robot.legs.right: missing"})) << Join(problems);
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:8:", "robot.joints_deg", "expected a map {JOINT_NAME: angle in degrees"}))
      << Join(problems);
  // an angle that is not a number
  const std::vector<std::string> more =
      RobotProblemsOf("proxsim: 1\nrobot:\n  model: robot.urdf\n  joints_deg:\n    a: 1\n    b: wide\n", Source());
  EXPECT_TRUE(HasProblem(more, {"scenario.yaml:6:", "robot.joints_deg.b", "expected a finite number, got wide"})) << Join(more);
}

}  // namespace
}  // namespace proxsim
