// The gait's crouch (gait.crouch_knee_deg, docs/robots.md "The gait's shape"),
// through the CLI on the Unitree H1 (skipped, saying so, without
// ../shared/robots/h1_description): walked straight-kneed and with its knees
// bent 0.6 rad more, the H1's shin leans back by half the bend (the thigh
// takes the other half forward, the foot stays as the curves pitch it), so a
// laser fixed on the shin looks down 0.3 rad further at every sample of the
// stance (within 0.01 rad), as geometry says (less in swing, where the foot's path over the
// ground sets the knee); at every sample the laser's pitch is the shank's
// (knee joint -> ankle joint, from poses.csv) plus its mounting, to 1e-9 rad.
// Each walk's mean pitch is printed as a [ measured ] line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "cli_helpers.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::Csv;
using testing::FreshDir;
using testing::ReadCsv;
using testing::ReadFile;
using testing::RunProxsim;

using testing::kH1Dir;
constexpr double kMountPitch_rad = 15.0 * M_PI / 180.0;  // the laser's pitch down on the shin

struct Walk {
  double mean_shank_rad = 0;   // shank's lean from the downward vertical, lower end forward positive
  double mean_laser_rad = 0;   // the laser's pitch below the horizontal
  double worst_mismatch_rad = 0;  // |laser − (mount − shank)| over the samples
  double pelvis_height_m = 0;
  double amplitude = 0;  // the curves' amplitude k the gait found for the stride
  int samples = 0;
  std::map<std::string, std::pair<double, std::string>> shank_by_t;  // t_s -> (shank lean, support leg)
};

Walk WalkH1(double crouch_knee_deg) {
  const fs::path dir = FreshDir("crouch_h1_" + std::to_string(static_cast<int>(std::lround(crouch_knee_deg))));
  fs::create_directories(dir);
  {
    std::ofstream out(dir / "walk.yaml");
    out << "proxsim: 1\nseed: 1\nduration_s: 5\nrate_hz: 100\nscene: {builtin: dining_room}\nrobot:\n"
        << "  model: " << (kH1Dir / "urdf" / "h1.urdf").lexically_normal().string() << "\n"
        << "  package_paths: [" << kH1Dir.parent_path().lexically_normal().string() << "]\n"
        << "  legs:\n"
        << "    left:  {hip: left_hip_pitch_joint,  knee: left_knee_joint,  ankle: left_ankle_joint,  foot: left_ankle_link}\n"
        << "    right: {hip: right_hip_pitch_joint, knee: right_knee_joint, ankle: right_ankle_joint, foot: right_ankle_link}\n"
        << "  gait: {stride_m: 0.5, period_s: 1.1, crouch_knee_deg: " << crouch_knee_deg << "}\n"
        << "  path: {waypoints_m: [[0, 0], [2, 0]]}\n"
        << "sensors:\n  - {name: shin, type: laser, link: left_knee_link, pose: {xyz_m: [0.06, 0, -0.3], rpy_deg: [0, 15, 0]}}\n";
  }
  const auto result = RunProxsim("run " + (dir / "walk.yaml").string() + " --no-report --out " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  Walk walk;
  if (result.exit_code != 0) return walk;
  const Csv poses = ReadCsv(dir / "out" / "poses.csv");
  const Csv readings = ReadCsv(dir / "out" / "readings.csv");
  const nlohmann::json summary = nlohmann::json::parse(ReadFile(dir / "out" / "summary.json"));
  fs::remove_all(dir);
  walk.pelvis_height_m = summary["robot"]["gait"]["pelvis_height_m"].get<double>();
  walk.amplitude = summary["robot"]["gait"]["amplitude"].get<double>();
  EXPECT_EQ(summary["robot"]["collisions"].size(), 0u) << summary["robot"].dump();

  // the knee joint is the origin of left_knee_link, the ankle joint that of left_ankle_link
  std::map<std::string, std::map<std::string, Eigen::Vector3d>> at;  // t_s -> link -> position
  for (const auto& row : poses.rows) {
    at[row.at("t_s")][row.at("link")] = {std::stod(row.at("x")), std::stod(row.at("y")), std::stod(row.at("z"))};
  }
  for (const auto& row : readings.rows) {
    const auto& links = at.at(row.at("t_s"));
    const Eigen::Vector3d shank = links.at("left_ankle_link") - links.at("left_knee_link");
    const double shank_rad = std::atan2(shank.x(), -shank.z());
    const double laser_rad = std::atan2(-std::stod(row.at("dir_z")), std::stod(row.at("dir_x")));
    walk.shank_by_t[row.at("t_s")] = {shank_rad, row.at("support_leg")};
    walk.mean_shank_rad += shank_rad;
    walk.mean_laser_rad += laser_rad;
    // the shank leaning back (its lower end behind) tips the laser down by as much
    walk.worst_mismatch_rad = std::max(walk.worst_mismatch_rad, std::abs(laser_rad - (kMountPitch_rad - shank_rad)));
    ++walk.samples;
  }
  walk.mean_shank_rad /= walk.samples;
  walk.mean_laser_rad /= walk.samples;
  std::printf("[ measured ] H1, crouch %.2f deg: %d samples, mean shank lean %+.4f rad, mean laser pitch down "
              "%+.4f rad, pelvis at heel strike %.4f m, amplitude %.4f\n",
              crouch_knee_deg, walk.samples, walk.mean_shank_rad, walk.mean_laser_rad, walk.pelvis_height_m,
              walk.amplitude);
  return walk;
}

TEST(CrouchGait, AShinLaserLooksDownByHalfTheKneeBendMore) {
  if (!fs::is_regular_file(kH1Dir / "urdf" / "h1.urdf"))
    GTEST_SKIP() << "skipped: the Unitree H1 is not at " << kH1Dir.lexically_normal().string()
                 << " (the H1 tests read ../shared/robots/h1_description from beside the project)";
  const Walk straight = WalkH1(0.0);
  const Walk crouched = WalkH1(0.6 * 180.0 / M_PI);
  ASSERT_EQ(straight.samples, crouched.samples);
  ASSERT_GT(straight.samples, 400);
  EXPECT_LT(straight.worst_mismatch_rad, 1e-9);
  EXPECT_LT(crouched.worst_mismatch_rad, 1e-9);
  // half the bend, where the curves and the planted foot set the leg: at every sample both walks
  // have the left foot in stance (support leg left), the crouched shank leans back 0.3 rad more,
  // within 0.01 rad (the amplitudes, 1.03 apart, scale the curves' own lean a little). In swing
  // the knee is set by the foot's path over the ground, not by the curves' angles: less (printed)
  int stance = 0;
  double swing_sum = 0;
  int swing = 0;
  for (const auto& [t, s0] : straight.shank_by_t) {
    const auto& s1 = crouched.shank_by_t.at(t);
    if (s0.second == "left" && s1.second == "left") {
      EXPECT_NEAR(s1.first - s0.first, -0.3, 0.01) << "t = " << t;
      ++stance;
    } else if (s0.second == "right" && s1.second == "right") {
      swing_sum += s1.first - s0.first;
      ++swing;
    }
  }
  EXPECT_GT(stance, 100);
  std::printf("[ measured ] the left shank leans back %d stance samples by 0.3 rad more (checked to 0.01); "
              "in swing by %.3f rad more on average (%d samples)\n", stance, -swing_sum / std::max(swing, 1), swing);
  // lower: thigh and shank each tilted 0.3 rad more lower the hip by about
  // L_thigh (1 − cos 0.3) + L_shank (1 − cos 0.3) ≈ 0.04·(0.4 + 0.4) m
  EXPECT_LT(crouched.pelvis_height_m, straight.pelvis_height_m - 0.02);
}

}  // namespace
}  // namespace proxsim
