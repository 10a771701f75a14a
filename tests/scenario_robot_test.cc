// The robot section's keys for bringing one's own robot (io/scenario_robot.cc):
// robot.geometry, robot.package_paths (resolved against the scenario's
// folder), robot.legs, robot.joints_deg (degrees in, radians out), and which
// of stride and period the legs set when the gait section leaves them out;
// and each mistake reported at its line with its key path.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "core/input_error.h"
#include "scenario/scenario.h"

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
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:4:", "robot.geometry", "expected visual or collision, got meshes"}))
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
