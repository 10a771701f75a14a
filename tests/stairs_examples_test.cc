// The shipped uneven-ground examples through the real CLI (docs/terrain.md):
// stairs_walk.yaml climbs to the landing, descends, and its stop rule stands
// it before the first hole from its readings, each of its tibia sensors
// detecting the steps and the hole's far wall; stairs_walk_no_strategy.yaml,
// without the rule, steps over the small hole and falls into the wide one,
// and with `unsafe_steps: refuse` stands before it with `cannot_step`;
// stairs_hole.yaml walks on over the small hole; hole_stop_rule.yaml is
// stopped before it by the built-in stop rule from the readings alone.
// Positions come from poses.csv, detections from readings.csv; the course's
// geometry is builtin_scenes.cc's.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace proxsim {
namespace {

using testing::Csv;
using testing::FreshDir;
using testing::ReadCsv;
using testing::ReadFile;
using testing::RowsOf;
using testing::RunProxsim;

constexpr double kLandingZ_m = 0.60;
constexpr double kSmallHoleFar_x_m = 5.25;  // the small hole: x 5.0 .. 5.25
constexpr double kWideHoleNear_x_m = 6.5;   // the wide hole: x 6.5 .. 7.1

struct Example {
  std::string cli_output;
  Csv readings;
  Csv poses;
  nlohmann::json summary;

  double Max(const std::string& link, const std::string& column) const {
    double v = -1e9;
    for (const auto& row : poses.rows)
      if (row.at("link") == link) v = std::max(v, std::stod(row.at(column)));
    return v;
  }
  double Last(const std::string& link, const std::string& column) const {
    double v = 0;
    for (const auto& row : poses.rows)
      if (row.at("link") == link) v = std::stod(row.at(column));
    return v;
  }
  bool Logged(const std::string& event) const {
    for (const auto& e : summary["robot"]["events"])
      if (e["event"] == event) return true;
    return false;
  }
  std::string Detail(const std::string& event) const {
    for (const auto& e : summary["robot"]["events"])
      if (e["event"] == event) return e["detail"].get<std::string>();
    return "";
  }
  double LoggedAt(const std::string& event) const {
    for (const auto& e : summary["robot"]["events"])
      if (e["event"] == event) return e["t_s"].get<double>();
    return NAN;
  }
};

Example RunScenarioFile(const std::filesystem::path& scenario, const std::string& name) {
  const auto out = FreshDir(name);
  const auto result = RunProxsim("run " + scenario.string() + " --no-report --out " + out.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  Example example{result.output, ReadCsv(out / "readings.csv"), ReadCsv(out / "poses.csv"),
                  nlohmann::json::parse(ReadFile(out / "summary.json"))};
  std::filesystem::remove_all(out);
  return example;
}

std::filesystem::path ShippedScenario(const std::string& name) {
  return std::filesystem::path(PROXSIM_SOURCE_DIR) / "data/scenarios" / (name + ".yaml");
}

Example RunExample(const std::string& name) { return RunScenarioFile(ShippedScenario(name), name); }

constexpr double kSmallHoleNear_x_m = 5.0;
constexpr double kStairsEnd_x_m = 4.0;  // the last step down ends here

TEST(StairsExamples, StairsWalkClimbsDescendsAndItsStopRuleStandsItBeforeTheFirstHole) {
  const Example run = RunExample("stairs_walk");
  // on the landing (the pelvis stands about 0.9 m above its feet's tread)
  EXPECT_GT(run.Max("pelvis", "z"), kLandingZ_m + 0.9);
  // down the stairs, back on the floor, the toes (0.2 m ahead of the ankles at most) short of the first hole
  EXPECT_GT(run.Last("pelvis", "x"), kStairsEnd_x_m);
  for (const char* foot : {"left_foot", "right_foot"}) {
    EXPECT_LT(run.Last(foot, "x") + 0.2, kSmallHoleNear_x_m) << foot;
    EXPECT_LT(run.Last(foot, "z"), 0.15) << foot;  // the ankle, 0.08 m above a sole on the floor (z = 0)
  }
  // stopped by its rule, from a knee laser's reading of the hole's depth; the legs never had to refuse
  ASSERT_TRUE(run.Logged("drop_ahead"));
  EXPECT_EQ(run.Detail("drop_ahead").rfind("laser_", 0), 0u) << run.Detail("drop_ahead");
  EXPECT_NE(run.Detail("drop_ahead").find("below the ground"), std::string::npos) << run.Detail("drop_ahead");
  EXPECT_FALSE(run.Logged("cannot_step"));
  EXPECT_FALSE(run.Logged("fall"));
  EXPECT_FALSE(run.Logged("obstacle_ahead"));  // no riser taken for an obstacle
  EXPECT_TRUE(run.summary["robot"]["stopped"].get<bool>());
  EXPECT_EQ(run.summary["robot"]["stop_reason"], "strategy");
  EXPECT_EQ(run.summary["robot"]["outcome"], "stopped");
  EXPECT_NE(run.cli_output.find("stopped by its strategy"), std::string::npos) << run.cli_output;

  // every tibia sensor detects the steps (a riser or a tread) and the first hole's far wall
  for (const std::string sensor : {"ideal", "laser", "ultrasonic", "reflectance"}) {
    bool steps = false, hole_wall = false;
    for (const auto& row : RowsOf(run.readings, sensor)) {
      if (row.at("status") != "ok") continue;
      const std::string& object = row.at("object");
      steps |= object.rfind("floor_stair_", 0) == 0 || object == "floor_landing";
      hole_wall |= object == "floor_between_holes" && std::stod(row.at("hit_z_m")) < -0.02;
    }
    EXPECT_TRUE(steps) << sensor;
    EXPECT_TRUE(hole_wall) << sensor;
  }
}

TEST(StairsExamples, StairsWalkWithoutItsStrategyFallsIntoTheGap) {
  const Example run = RunExample("stairs_walk_no_strategy");
  EXPECT_GT(run.Max("pelvis", "z"), kLandingZ_m + 0.9);
  EXPECT_GT(run.Last("pelvis", "x"), kSmallHoleFar_x_m);  // over the small hole
  EXPECT_FALSE(run.Logged("drop_ahead"));
  ASSERT_TRUE(run.Logged("fall"));
  EXPECT_NE(run.Detail("fall").find("a gap of 0.60 m"), std::string::npos) << run.Detail("fall");
  EXPECT_EQ(run.summary["robot"]["outcome"], "fell");
  EXPECT_NE(run.cli_output.find("fell at t = "), std::string::npos) << run.cli_output;
  // a step the legs could not take has no landing, and still a place: the
  // pelvis's point on the ground it stood on (it once was null)
  const auto& p_W = run.summary["robot"]["fall"]["p_W"];
  ASSERT_TRUE(p_W.is_array()) << run.summary["robot"]["fall"].dump();
  EXPECT_NEAR(p_W[0].get<double>(), run.Last("pelvis", "x"), 0.05);
  EXPECT_NEAR(p_W[1].get<double>(), run.Last("pelvis", "y"), 0.05);
  EXPECT_LT(p_W[2].get<double>(), run.Last("pelvis", "z") - 0.5);  // on the ground, not at the pelvis
}

TEST(StairsExamples, StairsWalkWithoutItsStrategyRefusingUnsafeStepsStandsBeforeTheGap) {
  // the shipped variant with `unsafe_steps: refuse` added to its gait
  std::string text = ReadFile(ShippedScenario("stairs_walk_no_strategy"));
  const std::string gait = "gait: {stride_m: 0.6, period_s: 1.2}";
  const auto at = text.find(gait);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, gait.size(), "gait: {stride_m: 0.6, period_s: 1.2, unsafe_steps: refuse}");
  const auto dir = FreshDir("stairs_walk_refuse_scenario");
  std::filesystem::create_directories(dir);
  const auto scenario = dir / "stairs_walk_refuse.yaml";
  std::ofstream(scenario) << text;
  const Example run = RunScenarioFile(scenario, "stairs_walk_refuse");
  std::filesystem::remove_all(dir);

  // past the small hole, short of the wide one, back on the floor
  EXPECT_GT(run.Last("pelvis", "x"), kSmallHoleFar_x_m);
  for (const char* foot : {"left_foot", "right_foot"}) {
    EXPECT_LT(run.Last(foot, "x"), kWideHoleNear_x_m) << foot;
    EXPECT_LT(run.Last(foot, "z"), 0.15) << foot;
  }
  ASSERT_TRUE(run.Logged("cannot_step"));
  EXPECT_FALSE(run.Logged("fall"));
  EXPECT_NE(run.Detail("cannot_step").find("a gap of 0.60 m"), std::string::npos) << run.Detail("cannot_step");
  EXPECT_NE(run.cli_output.find("standing before a step its legs cannot take"), std::string::npos) << run.cli_output;
  // standing for good, and summary.json says why
  EXPECT_TRUE(run.summary["robot"]["stopped"].get<bool>());
  EXPECT_EQ(run.summary["robot"]["stop_reason"], "cannot_step");
  EXPECT_GE(run.summary["robot"]["stop_t_s"].get<double>(), run.LoggedAt("cannot_step"));
  EXPECT_EQ(run.summary["robot"]["outcome"], "refused");
}

TEST(StairsExamples, StairsHoleWalksOnOverTheSmallHole) {
  const Example run = RunExample("stairs_hole");
  EXPECT_GT(run.Last("pelvis", "x"), kSmallHoleFar_x_m);
  EXPECT_LT(std::max(run.Last("left_foot", "x"), run.Last("right_foot", "x")), kWideHoleNear_x_m);
  // no strategy stops it before the wide hole: under unsafe_steps: fall (the
  // default) the step its legs cannot take is taken, and the episode ends there
  EXPECT_FALSE(run.Logged("cannot_step"));
  ASSERT_TRUE(run.Logged("fall"));
  EXPECT_NE(run.Detail("fall").find("a gap of 0.60 m"), std::string::npos) << run.Detail("fall");
  EXPECT_EQ(run.summary["robot"]["outcome"], "fell");
  EXPECT_DOUBLE_EQ(run.summary["robot"]["outcome_t_s"].get<double>(), run.LoggedAt("fall"));
  EXPECT_NE(run.cli_output.find("robot: walked"), std::string::npos);
  EXPECT_NE(run.cli_output.find("fell at t = "), std::string::npos) << run.cli_output;
}

TEST(StairsExamples, HoleStopRuleStopsBeforeTheSmallHoleFromTheReadings) {
  const Example run = RunExample("hole_stop_rule");
  EXPECT_TRUE(run.Logged("drop_ahead"));
  EXPECT_FALSE(run.Logged("cannot_step"));
  EXPECT_TRUE(run.summary["robot"]["stopped"].get<bool>());
  EXPECT_EQ(run.summary["robot"]["stop_reason"], "strategy");
  EXPECT_EQ(run.summary["robot"]["outcome"], "stopped");
  // the ankles (the toes are 0.2 m ahead of them at most) short of the edge at x = 5
  EXPECT_LT(std::max(run.Last("left_foot", "x"), run.Last("right_foot", "x")) + 0.2, 5.0);
}

}  // namespace
}  // namespace proxsim
