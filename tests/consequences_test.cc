// What happens to the robot, through the real CLI (docs/outcomes.md): the
// paper's scenario without its stop rule collides with the obstacle where the
// shapes first overlap (computed here from poses.csv and the URDF's boxes,
// not by proxsim), never standing on it; a robot whose feet overlap collides
// with itself; the circumvent example reaches its goal and its closing line
// says so; on_collision: continue logs every box of a row; bad values of the
// new keys are refused naming them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>

#include "cli_helpers.h"
#include "robot/robot_model.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadCsv;
using testing::ReadFile;
using testing::RunProxsim;

const std::string kPaper = std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/paper_dining_room.yaml";

// The paper's scenario with its stop rule removed and 9 s to walk.
std::string PaperWithoutStopRule() {
  std::string yaml = ReadFile(kPaper);
  yaml = std::regex_replace(yaml, std::regex("\n  stop_distance_m: [^\n]*"), "");
  return std::regex_replace(yaml, std::regex("duration_s: 5.0"), "duration_s: 9");
}

// An oriented box: centre, rotation (columns are its axes) and half sizes.
struct Obb {
  Vec3 c;
  Eigen::Matrix3d R;
  Vec3 h;
};

// Separating-axis test of two oriented boxes (Gottschalk's 15 axes): true
// when they overlap (touching counts as not overlapping).
bool Overlap(const Obb& a, const Obb& b) {
  std::vector<Vec3> axes;
  for (int i = 0; i < 3; ++i) axes.push_back(a.R.col(i)), axes.push_back(b.R.col(i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3 axis = a.R.col(i).cross(b.R.col(j));
      if (axis.norm() > 1e-9) axes.push_back(axis.normalized());
    }
  const Vec3 d = b.c - a.c;
  for (const Vec3& n : axes) {
    double ra = 0, rb = 0;
    for (int i = 0; i < 3; ++i) ra += a.h[i] * std::abs(n.dot(a.R.col(i))), rb += b.h[i] * std::abs(n.dot(b.R.col(i)));
    if (std::abs(d.dot(n)) >= ra + rb) return false;
  }
  return true;
}

TEST(Consequences, WithoutItsStopRuleThePaperRobotCollidesWithTheObstacleWhereTheShapesFirstOverlap) {
  const auto dir = FreshDir("consequences_paper");
  fs::create_directories(dir);
  std::ofstream(dir / "no_stop.yaml") << PaperWithoutStopRule();
  const auto out = dir / "out";
  const auto run = RunProxsim("run " + (dir / "no_stop.yaml").string() + " --no-report --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto summary = nlohmann::json::parse(ReadFile(out / "summary.json"));
  const auto& robot = summary["robot"];
  ASSERT_EQ(robot["outcome"], "collided") << robot.dump(2);
  const auto& first = robot["collisions"].at(0);
  EXPECT_EQ(first["object"], "obstacle");
  const double collided_t_s = robot["outcome_t_s"].get<double>();
  EXPECT_NE(run.output.find("collided with obstacle (" + first["link"].get<std::string>() + ") at t = "),
            std::string::npos) << run.output;

  // the test's own overlap: each foot's box (from the URDF) against the
  // obstacle (0.20 x 0.30 x 0.15 m at (2.5, 0, 0.075), builtin_scenes.cc), per sample of poses.csv
  const RobotModel biped = RobotModel::Builtin("biped");
  const Obb obstacle{Vec3(2.5, 0, 0.075), Eigen::Matrix3d::Identity(), Vec3(0.10, 0.15, 0.075)};
  double first_overlap_t_s = NAN, last_t_s = 0;
  for (const auto& row : ReadCsv(out / "poses.csv").rows) {
    const std::string& link = row.at("link");
    last_t_s = std::stod(row.at("t_s"));
    if (link != "left_foot" && link != "right_foot") continue;
    const Eigen::Quaterniond q(std::stod(row.at("qw")), std::stod(row.at("qx")), std::stod(row.at("qy")),
                               std::stod(row.at("qz")));
    Pose X_WL = Pose::Identity();
    X_WL.linear() = q.normalized().toRotationMatrix();
    X_WL.translation() = Vec3(std::stod(row.at("x")), std::stod(row.at("y")), std::stod(row.at("z")));
    const LinkShape& foot = biped.link(biped.LinkIndex(link)).shapes.at(0);
    const Pose X_WO = X_WL * foot.X_LO;
    const Obb box{X_WO.translation(), X_WO.linear(), std::get<Box>(foot.shape).size_m / 2};
    if (std::isnan(first_overlap_t_s) && Overlap(box, obstacle)) first_overlap_t_s = last_t_s;
    // never standing on the box: no sole over its footprint at or above its top
    const Vec3 sole_W = X_WL * Vec3(0.07, 0, -0.08);
    if (std::abs(sole_W.x() - 2.5) < 0.10 && std::abs(sole_W.y()) < 0.15) EXPECT_LT(sole_W.z(), 0.15) << link;
  }
  // the episode ends at the collision; the poses stop there too
  EXPECT_NEAR(last_t_s, collided_t_s, 1e-9);
  ASSERT_FALSE(std::isnan(first_overlap_t_s)) << "no overlap found by the test up to " << last_t_s;
  EXPECT_NEAR(collided_t_s, first_overlap_t_s, 0.01 + 1e-9) << "within one sample at 100 Hz";
}

TEST(Consequences, TheCircumventExampleReachesItsGoalAndItsClosingLineSaysSo) {
  const auto out = FreshDir("circumvent_goal");
  const auto run = RunProxsim("run " + std::string(PROXSIM_SOURCE_DIR) +
                              "/data/scenarios/circumvent_obstacle.yaml --no-report --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto summary = nlohmann::json::parse(ReadFile(out / "summary.json"));
  fs::remove_all(out);
  EXPECT_EQ(summary["robot"]["outcome"], "reached_goal");
  EXPECT_TRUE(summary["robot"]["collisions"].empty());
  char line[64];
  std::snprintf(line, sizeof line, "reached its goal at t = %.2f s", summary["robot"]["outcome_t_s"].get<double>());
  EXPECT_NE(run.output.find(line), std::string::npos) << run.output;
}

TEST(Consequences, FeetWiderThanTheGapBetweenThemCollideWithEachOther) {
  const auto dir = FreshDir("consequences_self");
  fs::create_directories(dir);
  // the built-in biped with feet 0.24 m wide: the legs are 0.20 m apart
  std::string urdf = ReadFile(std::string(PROXSIM_SOURCE_DIR) + "/data/robots/biped.urdf");
  urdf = std::regex_replace(urdf, std::regex("box size=\"0.26 0.10 0.06\""), "box size=\"0.26 0.24 0.06\"");
  std::ofstream(dir / "wide_feet.urdf") << urdf;
  std::ofstream(dir / "walk.yaml") << "proxsim: 1\nduration_s: 2\nrate_hz: 100\nscene: {builtin: empty}\n"
                                      "robot: {model: wide_feet.urdf, path: {waypoints_m: [[0, 0], [3, 0]]}}\n"
                                      "sensors: [{name: s, type: ideal, link: left_tibia}]\n";
  const auto out = dir / "out";
  const auto run = RunProxsim("run " + (dir / "walk.yaml").string() + " --no-report --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto robot = nlohmann::json::parse(ReadFile(out / "summary.json"))["robot"];
  ASSERT_EQ(robot["outcome"], "collided") << robot.dump(2);
  const auto& first = robot["collisions"].at(0);
  ASSERT_TRUE(first.contains("other_link")) << first.dump();
  const std::set<std::string> pair = {first["link"].get<std::string>(), first["other_link"].get<std::string>()};
  EXPECT_EQ(pair, (std::set<std::string>{"left_foot", "right_foot"}));
  EXPECT_NE(run.output.find("collided with its own"), std::string::npos) << run.output;
}

TEST(Consequences, OnCollisionContinueLogsEveryBoxOfARow) {
  const auto dir = FreshDir("consequences_row");
  fs::create_directories(dir);
  std::ofstream(dir / "row.yaml")
      << "proxsim: 1\nduration_s: 14\nrate_hz: 100\n"
         "scene:\n  objects:\n    - {name: floor, plane: {}, ground: true}\n"
         "    - {name: box_1, box: {size_m: [0.1, 0.6, 0.1]}, pose: {xyz_m: [1.0, 0, 0.05]}}\n"
         "    - {name: box_2, box: {size_m: [0.1, 0.6, 0.1]}, pose: {xyz_m: [2.0, 0, 0.05]}}\n"
         "    - {name: box_3, box: {size_m: [0.1, 0.6, 0.1]}, pose: {xyz_m: [3.0, 0, 0.05]}}\n"
         "robot:\n  path: {waypoints_m: [[0, 0], [4, 0]]}\n  on_collision: continue\n"
         "sensors: [{name: s, type: ideal, link: left_tibia}]\n";
  const auto out = dir / "out";
  const auto run = RunProxsim("run " + (dir / "row.yaml").string() + " --no-report --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto robot = nlohmann::json::parse(ReadFile(out / "summary.json"))["robot"];
  std::set<std::string> struck;
  for (const auto& c : robot["collisions"]) struck.insert(c["object"].get<std::string>());
  EXPECT_EQ(struck, (std::set<std::string>{"box_1", "box_2", "box_3"})) << robot["collisions"].dump(2);
  EXPECT_EQ(robot["outcome"], "collided");  // the first of them, though the walk went on
  EXPECT_GT(robot["distance_walked_m"].get<double>(), 3.0);
}

TEST(Consequences, BadOutcomeKeysAreRefusedNamingThem) {
  const auto dir = FreshDir("consequences_bad");
  fs::create_directories(dir);
  std::ofstream(dir / "bad.yaml") << "proxsim: 1\nscene: {builtin: empty}\n"
                                     "robot: {gait: {unsafe_steps: jump}, on_collision: ignore}\n"
                                     "sensors: [{name: s, type: ideal, link: left_tibia}]\n";
  const auto run = RunProxsim("validate " + (dir / "bad.yaml").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("unsafe_steps"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("expected fall"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("on_collision"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("expected stop"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace proxsim
