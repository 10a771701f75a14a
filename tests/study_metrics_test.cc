// A study's per-run metrics on tiny scenes whose answers are known by hand:
// a wall at a known distance (the lead distance is the wall's face minus the
// leading toe, taken from the run's own poses.csv and the biped's foot
// geometry), a non-hazard wall inside the stop rule's look-ahead (every
// detection is a false alarm), and a sensor looking straight down between the
// legs (the floor seen at every stretch, no self echo).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_helpers.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::Csv;
using testing::FreshDir;
using testing::ReadCsv;
using testing::RunProxsim;

constexpr double kWallFaceX_m = 1.5;  // the hazard wall's near face
constexpr double kNearFaceX_m = 0.6;  // the other wall's: within 0.5 m (the stop rule's look-ahead) of the toe

void Write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

// A 0.05 s walk (5 samples at 100 Hz) before a wall named `wall_name` whose near face is at face_x_m.
std::string WallScenario(const std::string& wall_name, double face_x_m) {
  return "proxsim: 1\nseed: 1\nduration_s: 0.05\nrate_hz: 100\n"
         "scene:\n  objects:\n    - {name: floor, plane: {}}\n"
         "    - {name: " + wall_name + ", box: {size_m: [0.1, 3.0, 2.0]}, pose: {xyz_m: [" +
         std::to_string(face_x_m + 0.05) + ", 0, 1.0]}}\n"
         "robot:\n  model: builtin:biped\n  start: {xyz_m: [0, 0, 0], yaw_deg: 0}\n"
         "  gait: {stride_m: 0.6, period_s: 1.2}\n  path: {waypoints_m: [[0, 0], [4, 0]]}\n"
         "sensors:\n  - {name: s, type: ideal, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.2]}}\n";
}

const std::string kStudy =
    "proxsim_study: 1\nbase: far.yaml\n"
    "candidates:\n  list:\n"
    "    - {type: ideal, link: left_tibia, xyz_m: [0.06, 0, -0.2], rpy_deg: [0, 0, 0]}   # forward: the wall\n"
    "    - {type: ideal, link: pelvis, xyz_m: [0.15, 0, -0.05], rpy_deg: [0, 90, 0]}    # straight down, ahead of the pelvis, between the legs\n"
    "scenes:\n  - {name: far_hazard, scenario: far.yaml}\n  - {name: near_wall, scenario: near.yaml}\n"
    "seeds: [1]\nhazards: [obstacle]\n";

// The foremost toe at t = 0 from poses.csv: each foot's toe is 0.20 m ahead
// of its ankle and 0.08 m below it (data/robots/biped.urdf).
double FrontToeX0_m(const fs::path& poses_csv) {
  const Csv poses = ReadCsv(poses_csv);
  double front = -1e9;
  for (const auto& row : poses.rows) {
    if (std::stod(row.at("t_s")) != 0.0 || (row.at("link") != "left_foot" && row.at("link") != "right_foot")) continue;
    const Eigen::Quaterniond q(std::stod(row.at("qw")), std::stod(row.at("qx")), std::stod(row.at("qy")),
                               std::stod(row.at("qz")));
    const Eigen::Vector3d p(std::stod(row.at("x")), std::stod(row.at("y")), std::stod(row.at("z")));
    front = std::max(front, (p + q * Eigen::Vector3d(0.20, 0, -0.08)).x());
  }
  return front;
}

const std::map<std::string, std::string>& RowOf(const Csv& csv, const std::string& candidate_prefix,
                                                const std::string& scene) {
  for (const auto& row : csv.rows) {
    if (row.at("candidate").starts_with(candidate_prefix) && row.at("scene") == scene) return row;
  }
  ADD_FAILURE() << "no row for " << candidate_prefix << " in " << scene;
  static const std::map<std::string, std::string> none;
  return none;
}

class StudyMetricsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshDir("study_metrics");
    fs::create_directories(dir_);
    Write(dir_ / "far.yaml", WallScenario("obstacle_wall", kWallFaceX_m));
    Write(dir_ / "near.yaml", WallScenario("wall", kNearFaceX_m));
    Write(dir_ / "study.yaml", kStudy);
    const auto study = RunProxsim("study " + (dir_ / "study.yaml").string() + " --out " + (dir_ / "out").string() +
                                  " --no-report");
    ASSERT_EQ(study.exit_code, 0) << study.output;
    const auto run = RunProxsim("run " + (dir_ / "far.yaml").string() + " --out " + (dir_ / "run").string() +
                                " --no-report");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    results_ = ReadCsv(dir_ / "out" / "results.csv");
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  Csv results_;
};

TEST_F(StudyMetricsTest, LeadDistanceIsTheWallFaceAheadOfTheLeadingToe) {
  const auto& row = RowOf(results_, "ideal@left_tibia", "far_hazard");
  ASSERT_EQ(row.at("obstacle_detected"), "1");
  EXPECT_EQ(std::stod(row.at("obstacle_first_t_s")), 0.0);  // in range from the first sample
  const double toe_x_m = FrontToeX0_m(dir_ / "run" / "poses.csv");
  EXPECT_NEAR(std::stod(row.at("obstacle_lead_m")), kWallFaceX_m - toe_x_m, 1e-6) << "toe at x = " << toe_x_m;
  EXPECT_EQ(row.at("false_alarms"), "0");  // 1.2 m ahead of the toe: beyond the stop rule's 0.5 m
}

TEST_F(StudyMetricsTest, EveryDetectionOfANonHazardWallInsideTheLookAheadIsAFalseAlarm) {
  const auto& row = RowOf(results_, "ideal@left_tibia", "near_wall");
  EXPECT_EQ(row.at("samples"), "5");
  EXPECT_EQ(row.at("false_alarms"), "5");
  EXPECT_EQ(row.at("obstacle_detected"), "");  // this variant has no hazard: not applicable
}

TEST_F(StudyMetricsTest, ASensorLookingDownBetweenTheLegsCoversTheFloorWithoutSelfEchoes) {
  for (const std::string scene : {"far_hazard", "near_wall"}) {
    const auto& row = RowOf(results_, "ideal@pelvis", scene);
    EXPECT_EQ(std::stod(row.at("floor_coverage")), 1.0) << scene;
    EXPECT_EQ(std::stod(row.at("self_share")), 0.0) << scene;
    EXPECT_EQ(row.at("false_alarms"), "0") << scene;  // the floor is no obstacle
  }
  EXPECT_EQ(RowOf(results_, "ideal@pelvis", "far_hazard").at("obstacle_detected"), "0");
  EXPECT_EQ(std::stod(RowOf(results_, "ideal@left_tibia", "far_hazard").at("floor_coverage")), 0.0);
}

TEST_F(StudyMetricsTest, EveryRowSaysHowItsEpisodeEnded) {
  // the candidates of a run ride together: one outcome per run, within its duration
  for (const std::string scene : {"far_hazard", "near_wall"}) {
    const auto& a = RowOf(results_, "ideal@pelvis", scene);
    const auto& b = RowOf(results_, "ideal@left_tibia", scene);
    EXPECT_NE(std::ranges::find(kOutcomeNames, a.at("outcome")), kOutcomeNames.end())
        << a.at("outcome");
    EXPECT_EQ(a.at("outcome"), b.at("outcome"));
    EXPECT_EQ(a.at("outcome_t_s"), b.at("outcome_t_s"));
    EXPECT_GE(std::stod(a.at("outcome_t_s")), 0.0);
  }
}

}  // namespace
}  // namespace proxsim
