// `gait.footholds: map` through the real CLI on the built-in stairs course
// (docs/terrain.md, "Footholds on the robot's own map"): with ideal sensors
// that see every tread the robot walks the course as on the truth (the same
// outcome, each foothold on the same tread, within a few millimetres along
// it); with nothing feeding its map it walks into the first riser; with the
// paper's single tibia laser, the outcome the docs report; a blind robot
// falls where the true ground is not where it stepped (a step down, a hole);
// and the keys' bad values are refused naming them.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "core/geometry.h"

namespace proxsim {
namespace {

using testing::Csv;
using testing::FreshDir;
using testing::ReadCsv;
using testing::ReadFile;
using testing::RunProxsim;

constexpr double kFirstRiser_x_m = 1.0;  // builtin_scenes.cc: floor_stair_up_1 starts here
constexpr double kGapNear_x_m = 6.5;     // the course's wide gap: x 6.5 .. 7.1
constexpr double kToeAheadOfAnkle_m = 0.2;  // biped.urdf: the foot's box, 0.26 m from 0.07 m ahead of the ankle

struct ExampleRun {
  std::string output;
  int exit_code = 0;
  Csv poses;
  nlohmann::json robot;

  std::string EventDetail(const std::string& event) const {
    for (const auto& e : robot["events"])
      if (e["event"] == event) return e["detail"].get<std::string>();
    return "";
  }
};

ExampleRun RunFile(const std::string& path, const std::string& name) {
  const auto out = FreshDir(name);
  const auto result = RunProxsim("run " + path + " --no-report --out " + out.string());
  ExampleRun run{result.output, result.exit_code, {}, {}};
  if (result.exit_code == 0) {
    run.poses = ReadCsv(out / "poses.csv");
    run.robot = nlohmann::json::parse(ReadFile(out / "summary.json"))["robot"];
  }
  std::filesystem::remove_all(out);
  return run;
}

std::string ExampleScenario(const std::string& name) { return std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/" + name + ".yaml"; }

// A scenario file: `text` written under the test's folder.
std::string WriteScenario(const std::string& name, const std::string& text) {
  const auto dir = FreshDir(name + "_yaml");
  std::filesystem::create_directories(dir);
  const auto path = dir / (name + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

// One example's text with `from` replaced by `to` (each must occur).
std::string Edited(const std::string& example, const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string text = ReadFile(ExampleScenario(example));
  for (const auto& [from, to] : edits) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return text;
}

// Where each foot stood flat, in order: its link's positions held still over
// two samples (x, z) with the foot level (a foot rising off a riser pauses in
// the air, pitched), a new one when it moved more than 1 mm.
std::vector<Vec3> FootholdPoints(const Csv& poses, const std::string& foot) {
  std::vector<Vec3> held;
  Vec3 last = Vec3::Constant(NAN);
  for (const auto& row : poses.rows) {
    if (row.at("link") != foot) continue;
    const Vec3 p(std::stod(row.at("x")), std::stod(row.at("y")), std::stod(row.at("z")));
    const bool level = std::abs(std::stod(row.at("qy"))) < 1e-6;
    if (level && (p - last).cwiseAbs().maxCoeff() < 1e-9 && (held.empty() || (p - held.back()).norm() > 1e-3))
      held.push_back(p);
    last = p;
  }
  return held;
}

TEST(FootholdsMapExamples, IdealSensorsThatSeeEveryTreadWalkTheStairsAsOnTheTruth) {
  const ExampleRun map = RunFile(ExampleScenario("stairs_footholds_map"), "footholds_map");
  const ExampleRun truth = RunFile(WriteScenario("footholds_truth", Edited("stairs_footholds_map", {{"footholds: map}", "footholds: truth}"}})),
                            "footholds_truth");
  ASSERT_EQ(map.exit_code, 0) << map.output;
  ASSERT_EQ(truth.exit_code, 0) << truth.output;
  EXPECT_EQ(truth.robot["outcome"], "reached_goal");
  EXPECT_EQ(map.robot["outcome"], truth.robot["outcome"]) << map.robot["outcome_detail"];
  EXPECT_TRUE(map.robot["collisions"].empty());
  // every foothold on the same tread as the truth's, and near it along the way
  double worst_x_m = 0;
  for (const char* foot : {"left_foot", "right_foot"}) {
    const std::vector<Vec3> a = FootholdPoints(truth.poses, foot), b = FootholdPoints(map.poses, foot);
    ASSERT_EQ(a.size(), b.size()) << foot;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_NEAR(a[i].z(), b[i].z(), 1e-6) << foot << " foothold " << i;
      worst_x_m = std::max(worst_x_m, std::abs(a[i].x() - b[i].x()));
    }
  }
  std::printf("[ measured ] footholds on the map vs on the truth: largest difference along x %.4f m; goal at %.2f s "
              "(truth %.2f s)\n",
              worst_x_m, map.robot["outcome_t_s"].get<double>(), truth.robot["outcome_t_s"].get<double>());
  EXPECT_LT(worst_x_m, 0.06);
}

TEST(FootholdsMapExamples, WithNothingFeedingTheMapItWalksIntoTheFirstRiser) {
  const ExampleRun run = RunFile(ExampleScenario("stairs_footholds_blind"), "footholds_blind");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.robot["outcome"], "collided") << run.robot["outcome_detail"];
  ASSERT_FALSE(run.robot["collisions"].empty());
  const auto& first = run.robot["collisions"][0];
  EXPECT_EQ(first["object"], "floor_stair_up_1");
  EXPECT_NEAR(first["p_W"][0].get<double>(), kFirstRiser_x_m, 0.05);
}

TEST(FootholdsMapExamples, ThePapersSingleTibiaLaserWalksIntoTheFirstRiser) {
  // measured (docs/terrain.md): the laser on the left tibia maps a strip along
  // the left foot's line only; the right foot steps level into the riser
  const ExampleRun run = RunFile(ExampleScenario("stairs_footholds_tibia"), "footholds_tibia");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.robot["outcome"], "collided") << run.robot["outcome_detail"];
  ASSERT_FALSE(run.robot["collisions"].empty());
  const auto& first = run.robot["collisions"][0];
  EXPECT_EQ(first["object"], "floor_stair_up_1");
  EXPECT_EQ(first["link"], "right_foot");
  EXPECT_NEAR(first["p_W"][0].get<double>(), kFirstRiser_x_m, 0.05);
  std::printf("[ measured ] the paper's tibia laser: %s at %.2f s: %s\n", run.robot["outcome"].get<std::string>().c_str(),
              run.robot["outcome_t_s"].get<double>(), run.robot["outcome_detail"].get<std::string>().c_str());
}

TEST(FootholdsMapExamples, SeeingTheWideGapItStandsBeforeItWhateverUnsafeStepsSays) {
  // the same robot and sensors on the course past its small hole (from x =
  // 5.4 m): the 0.6 m gap at x = 6.5 .. 7.1 is in its map before it gets
  // there; its gait, planning on that map, finds no step across, and the robot
  // stands — its own judgement from its readings, not a fall, though
  // unsafe_steps is the default `fall`
  const ExampleRun run =
      RunFile(WriteScenario("footholds_gap", Edited("stairs_footholds_map", {{"xyz_m: [0, 0, 0]", "xyz_m: [5.4, 0, 0]"},
                                                                             {"[[0, 0], [4.6, 0]]", "[[5.4, 0], [8.5, 0]]"},
                                                                             {"duration_s: 18.0", "duration_s: 6.0"}})),
              "footholds_gap");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.robot["outcome"], "stopped") << run.robot["outcome_detail"];
  EXPECT_EQ(run.robot["stop_reason"], "own_map");
  EXPECT_TRUE(run.robot["collisions"].empty());
  EXPECT_TRUE(run.robot["fall"].is_null()) << run.robot["fall"].dump();
  const std::string why = run.EventDetail("cannot_step");
  // (the gap's width as the map's 12 mm cells place its edges, from ray casts: not compared exactly)
  EXPECT_NE(why.find("a gap of "), std::string::npos) << why;
  EXPECT_NE(why.find("longer than a stride"), std::string::npos) << why;
  EXPECT_NE(run.output.find("standing before a step its own map shows it cannot take"), std::string::npos) << run.output;
  for (const char* foot : {"left_foot", "right_foot"}) {
    const std::vector<Vec3> held = FootholdPoints(run.poses, foot);
    ASSERT_FALSE(held.empty()) << foot;
    EXPECT_LT(held.back().x() + kToeAheadOfAnkle_m, kGapNear_x_m) << foot;
  }
  std::printf("[ measured ] the map-fed robot before the wide gap: %s at %.2f s: %s\n",
              run.robot["outcome"].get<std::string>().c_str(), run.robot["outcome_t_s"].get<double>(),
              run.robot["outcome_detail"].get<std::string>().c_str());
}

TEST(FootholdsMapExamples, ABlindRobotFallsWhereTheGroundIsLowerThanItStepped) {
  // from the landing (z = 0.6 m) down the stairs, a map that knows nothing:
  // the foot planned level lands on the first tread down, 0.15 m lower
  const ExampleRun down = RunFile(WriteScenario("footholds_down", Edited("stairs_footholds_blind",
                                                                   {{"xyz_m: [0, 0, 0]", "xyz_m: [2.5, 0, 0.6]"},
                                                                    {"[[0, 0], [4.6, 0]]", "[[2.5, 0], [4.6, 0]]"}})),
                           "footholds_down");
  ASSERT_EQ(down.exit_code, 0) << down.output;
  EXPECT_EQ(down.robot["outcome"], "fell");
  EXPECT_NE(down.EventDetail("fall").find("landed 0.150 m lower than planned at (3.1"), std::string::npos)
      << down.EventDetail("fall");
  // summary.json says where: the foothold it missed, planned level with the landing (z = 0.6 m)
  // above the first tread down
  const auto& fall = down.robot["fall"];
  ASSERT_TRUE(fall.is_object()) << down.robot.dump();
  EXPECT_NEAR(fall["p_W"][0].get<double>(), 3.15, 0.15);
  EXPECT_NEAR(fall["p_W"][2].get<double>(), 0.6, 0.03);
  EXPECT_DOUBLE_EQ(fall["t_s"].get<double>(), down.robot["outcome_t_s"].get<double>());
  // toward the small hole (x 5.0 .. 5.25): a heel lands over it
  const ExampleRun hole = RunFile(WriteScenario("footholds_hole", Edited("stairs_footholds_blind",
                                                                   {{"xyz_m: [0, 0, 0]", "xyz_m: [4.4, 0, 0]"},
                                                                    {"[[0, 0], [4.6, 0]]", "[[4.4, 0], [6.2, 0]]"}})),
                           "footholds_hole");
  ASSERT_EQ(hole.exit_code, 0) << hole.output;
  EXPECT_EQ(hole.robot["outcome"], "fell");
  EXPECT_NE(hole.EventDetail("fall").find("its heel over an edge"), std::string::npos) << hole.EventDetail("fall");
  // the sole's middle, at the hole's edge (x 5.0 .. 5.25), within half a sole
  ASSERT_TRUE(hole.robot["fall"].is_object());
  EXPECT_NEAR(hole.robot["fall"]["p_W"][0].get<double>(), 5.1, 0.2);
}

TEST(FootholdsMapExamples, BadValuesAreRefusedNamingTheKey) {
  const ExampleRun bad = RunFile(WriteScenario("footholds_bad", Edited("stairs_footholds_blind",
                                                                 {{"footholds: map}", "footholds: maps, touchdown_tolerance_m: 0.5}"}})),
                          "footholds_bad");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("robot.gait.footholds: expected truth"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("robot.gait.touchdown_tolerance_m"), std::string::npos) << bad.output;
  const ExampleRun off = RunFile(WriteScenario("footholds_off", Edited("stairs_footholds_blind", {{"\n  sensors: []\n", "\n  enabled: false\n"}})),
                          "footholds_off");
  EXPECT_EQ(off.exit_code, 2) << off.output;
  EXPECT_NE(off.output.find("robot.gait.footholds: map plans the footsteps on the robot's terrain map, but the map is off"),
            std::string::npos)
      << off.output;
}

}  // namespace
}  // namespace proxsim
