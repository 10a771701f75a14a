// A foot link whose frame is turned (Onshape's URDFs, most MJCFs): the
// built-in biped with its ankle joints' origins at rpy (π/2, 0, 0), the axis
// and the feet's geometry re-expressed so that nothing moves in the world,
// walks exactly as the original through the CLI — every link origin where the
// original's is (1e-9 m), each foot frame the original's turned by Rx(π/2),
// the same readings and the same outcome. (The contact referee once measured
// the sole band along the foot link's own z: standing was "collided with
// floor (left_foot) at t = 0.00 s".)
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_helpers.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::Csv;
using testing::FreshDir;
using testing::ReadCsv;
using testing::ReadFile;
using testing::RunProxsim;

const fs::path kBiped = fs::path(PROXSIM_SOURCE_DIR) / "data" / "robots" / "biped.urdf";

void Replace(std::string& text, const std::string& from, const std::string& to, std::size_t after) {
  const std::size_t at = text.find(from, after);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

// The biped with each ankle joint's frame turned by Rx(π/2): in that frame the
// world's −y axis is +z, and the foot's box centre (0.07, 0, −0.05) is (0.07, −0.05, 0)
std::string RotatedBiped() {
  std::string urdf = ReadFile(kBiped);
  for (const std::string side : {"left", "right"}) {
    const std::size_t joint = urdf.find("<joint name=\"" + side + "_ankle_pitch\"");
    Replace(urdf, "<origin xyz=\"0 0 -0.45\" rpy=\"0 0 0\"/>",
            "<origin xyz=\"0 0 -0.45\" rpy=\"1.5707963267948966 0 0\"/>", joint);
    Replace(urdf, "<axis xyz=\"0 -1 0\"/>", "<axis xyz=\"0 0 1\"/>", joint);
    const std::size_t link = urdf.find("<link name=\"" + side + "_foot\">");
    for (int i = 0; i < 3; ++i) {  // inertial, visual, collision
      Replace(urdf, "<origin xyz=\"0.07 0 -0.05\" rpy=\"0 0 0\"/>",
              "<origin xyz=\"0.07 -0.05 0\" rpy=\"-1.5707963267948966 0 0\"/>", link);
    }
  }
  return urdf;
}

struct WalkRun {
  Csv poses, readings;
  nlohmann::json robot;
};

WalkRun Walk(const fs::path& dir, const std::string& model) {
  std::ofstream(dir / "walk.yaml") << "proxsim: 1\nseed: 1\nduration_s: 6\nrate_hz: 100\nscene: {builtin: dining_room}\n"
                                   << "robot:\n  model: " << model << "\n  path: {waypoints_m: [[0, 0], [2, 0]]}\n"
                                   << "sensors:\n  - {name: shin, type: laser, link: left_tibia, "
                                   << "pose: {xyz_m: [0.06, 0, -0.15], rpy_deg: [0, 20, 0]}}\n";
  const auto result = RunProxsim("run " + (dir / "walk.yaml").string() + " --no-report --out " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  WalkRun run;
  if (result.exit_code != 0) return run;
  run.poses = ReadCsv(dir / "out" / "poses.csv");
  run.readings = ReadCsv(dir / "out" / "readings.csv");
  run.robot = nlohmann::json::parse(ReadFile(dir / "out" / "summary.json"))["robot"];
  return run;
}

Eigen::Quaterniond Orientation(const std::map<std::string, std::string>& row) {
  return {std::stod(row.at("qw")), std::stod(row.at("qx")), std::stod(row.at("qy")), std::stod(row.at("qz"))};
}

TEST(RotatedFootFrame, WalksExactlyAsTheOriginal) {
  const fs::path original_dir = FreshDir("rotated_foot_original"), rotated_dir = FreshDir("rotated_foot_rotated");
  fs::create_directories(original_dir);
  fs::create_directories(rotated_dir);
  std::ofstream(rotated_dir / "biped_rotated.urdf") << RotatedBiped();
  const WalkRun original = Walk(original_dir, kBiped.string());
  const WalkRun rotated = Walk(rotated_dir, "biped_rotated.urdf");
  ASSERT_EQ(original.poses.rows.size(), rotated.poses.rows.size());
  ASSERT_GT(original.poses.rows.size(), 1000u);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  double worst_p_m = 0, worst_R = 0;
  for (std::size_t i = 0; i < original.poses.rows.size(); ++i) {
    const auto& a = original.poses.rows[i];
    const auto& b = rotated.poses.rows[i];
    ASSERT_EQ(a.at("link"), b.at("link"));
    for (const char* k : {"x", "y", "z"}) worst_p_m = std::max(worst_p_m, std::abs(std::stod(a.at(k)) - std::stod(b.at(k))));
    const bool foot = a.at("link") == "left_foot" || a.at("link") == "right_foot";
    const Eigen::Matrix3d expected = (foot ? Orientation(a) * turn : Orientation(a)).toRotationMatrix();
    worst_R = std::max(worst_R, (Orientation(b).toRotationMatrix() - expected).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst_p_m, 1e-9);
  EXPECT_LT(worst_R, 1e-9);
  // what the sensor read, and how the walk ended
  ASSERT_EQ(original.readings.rows.size(), rotated.readings.rows.size());
  for (std::size_t i = 0; i < original.readings.rows.size(); ++i) {
    EXPECT_EQ(original.readings.rows[i].at("status"), rotated.readings.rows[i].at("status"));
    EXPECT_NEAR(std::stod(original.readings.rows[i].at("d_true_m")), std::stod(rotated.readings.rows[i].at("d_true_m")), 1e-9);
  }
  EXPECT_EQ(original.robot["outcome"], rotated.robot["outcome"]) << rotated.robot.dump();
  EXPECT_EQ(original.robot["outcome_detail"], rotated.robot["outcome_detail"]);
  EXPECT_EQ(original.robot["distance_walked_m"], rotated.robot["distance_walked_m"]);
  fs::remove_all(original_dir);
  fs::remove_all(rotated_dir);
}

}  // namespace
}  // namespace proxsim
