// A foot link whose frame is turned (Onshape's URDFs, most MJCFs): the
// built-in biped with its ankle joints' origins at rpy (π/2, 0, 0), the axis
// and the feet's geometry re-expressed so that nothing moves in the world,
// walks exactly as the original through the CLI — every link origin where the
// original's is (1e-9 m), each foot frame the original's turned by Rx(π/2),
// the same readings and the same outcome. (The contact referee once measured
// the sole band along the foot link's own z: standing was "collided with
// floor (left_foot) at t = 0.00 s".) And a foot whose sole is pitched 10° toe
// up at joint zero (its geometry turned about the ankle) walks with its sole
// flat, exactly as the original, given `ankle_zero_deg: 10` or not (the pitch
// its geometry lies flattest at, found by a 0.1° scan); told `ankle_zero_deg:
// 0`, it is refused, naming the key and the 10.0° the geometry lies flat at.
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

const fs::path kBipedUrdf = fs::path(PROXSIM_SOURCE_DIR) / "data" / "robots" / "biped.urdf";

void ReplaceAfter(std::string& text, const std::string& from, const std::string& to, std::size_t after) {
  const std::size_t at = text.find(from, after);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

// The biped with each ankle joint's frame turned by Rx(π/2): in that frame the
// world's −y axis is +z, and the foot's box centre (0.07, 0, −0.05) is (0.07, −0.05, 0)
std::string RotatedBiped() {
  std::string urdf = ReadFile(kBipedUrdf);
  for (const std::string side : {"left", "right"}) {
    const std::size_t joint = urdf.find("<joint name=\"" + side + "_ankle_pitch\"");
    ReplaceAfter(urdf, "<origin xyz=\"0 0 -0.45\" rpy=\"0 0 0\"/>",
            "<origin xyz=\"0 0 -0.45\" rpy=\"1.5707963267948966 0 0\"/>", joint);
    ReplaceAfter(urdf, "<axis xyz=\"0 -1 0\"/>", "<axis xyz=\"0 0 1\"/>", joint);
    const std::size_t link = urdf.find("<link name=\"" + side + "_foot\">");
    for (int i = 0; i < 3; ++i) {  // inertial, visual, collision
      ReplaceAfter(urdf, "<origin xyz=\"0.07 0 -0.05\" rpy=\"0 0 0\"/>",
              "<origin xyz=\"0.07 -0.05 0\" rpy=\"-1.5707963267948966 0 0\"/>", link);
    }
  }
  return urdf;
}

struct WalkRun {
  Csv poses, readings;
  nlohmann::json robot;
  std::string output;
  int exit_code = -1;
};

// The biped with each foot's geometry turned 10° toe up about the ankle (its frame's origin)
std::string PitchedBiped() {
  std::string urdf = ReadFile(kBipedUrdf);
  const double th = -10.0 * M_PI / 180.0;  // Ry(−10°) lifts +x
  char origin[160];
  std::snprintf(origin, sizeof origin, "<origin xyz=\"%.17g 0 %.17g\" rpy=\"0 %.17g 0\"/>",
                std::cos(th) * 0.07 + std::sin(th) * -0.05, -std::sin(th) * 0.07 + std::cos(th) * -0.05, th);
  for (const std::string side : {"left", "right"}) {
    const std::size_t link = urdf.find("<link name=\"" + side + "_foot\">");
    for (int i = 0; i < 3; ++i) ReplaceAfter(urdf, "<origin xyz=\"0.07 0 -0.05\" rpy=\"0 0 0\"/>", origin, link);
  }
  return urdf;
}

WalkRun Walk(const fs::path& dir, const std::string& model, const std::string& legs = "") {
  std::ofstream(dir / "walk.yaml") << "proxsim: 1\nseed: 1\nduration_s: 6\nrate_hz: 100\nscene: {builtin: dining_room}\n"
                                   << "robot:\n  model: " << model << "\n  path: {waypoints_m: [[0, 0], [2, 0]]}\n" << legs
                                   << "sensors:\n  - {name: shin, type: laser, link: left_tibia, "
                                   << "pose: {xyz_m: [0.06, 0, -0.15], rpy_deg: [0, 20, 0]}}\n";
  const auto result = RunProxsim("run " + (dir / "walk.yaml").string() + " --no-report --out " + (dir / "out").string());
  WalkRun run;
  run.output = result.output;
  run.exit_code = result.exit_code;
  if (result.exit_code != 0) return run;
  run.poses = ReadCsv(dir / "out" / "poses.csv");
  run.readings = ReadCsv(dir / "out" / "readings.csv");
  run.robot = nlohmann::json::parse(ReadFile(dir / "out" / "summary.json"))["robot"];
  return run;
}

Eigen::Quaterniond Orientation(const std::map<std::string, std::string>& row) {
  return {std::stod(row.at("qw")), std::stod(row.at("qx")), std::stod(row.at("qy")), std::stod(row.at("qz"))};
}

// `changed` walks as `original`, its foot frames turned by `foot_turn` (X_WF_changed = X_WF_original · foot_turn)
void ExpectTheSameWalk(const WalkRun& original, const WalkRun& changed, const Eigen::Quaterniond& foot_turn) {
  ASSERT_EQ(original.exit_code, 0) << original.output;
  ASSERT_EQ(changed.exit_code, 0) << changed.output;
  ASSERT_EQ(original.poses.rows.size(), changed.poses.rows.size());
  ASSERT_GT(original.poses.rows.size(), 1000u);
  double worst_p_m = 0, worst_R = 0;
  for (std::size_t i = 0; i < original.poses.rows.size(); ++i) {
    const auto& a = original.poses.rows[i];
    const auto& b = changed.poses.rows[i];
    ASSERT_EQ(a.at("link"), b.at("link"));
    for (const char* k : {"x", "y", "z"}) worst_p_m = std::max(worst_p_m, std::abs(std::stod(a.at(k)) - std::stod(b.at(k))));
    const bool foot = a.at("link") == "left_foot" || a.at("link") == "right_foot";
    const Eigen::Matrix3d expected = (foot ? Orientation(a) * foot_turn : Orientation(a)).toRotationMatrix();
    worst_R = std::max(worst_R, (Orientation(b).toRotationMatrix() - expected).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst_p_m, 1e-9);
  EXPECT_LT(worst_R, 1e-9);
  // what the sensor read, and how the walk ended
  ASSERT_EQ(original.readings.rows.size(), changed.readings.rows.size());
  for (std::size_t i = 0; i < original.readings.rows.size(); ++i) {
    EXPECT_EQ(original.readings.rows[i].at("status"), changed.readings.rows[i].at("status"));
    EXPECT_NEAR(std::stod(original.readings.rows[i].at("d_true_m")), std::stod(changed.readings.rows[i].at("d_true_m")), 1e-9);
  }
  EXPECT_EQ(original.robot["outcome"], changed.robot["outcome"]) << changed.robot.dump();
  EXPECT_EQ(original.robot["outcome_detail"], changed.robot["outcome_detail"]);
  EXPECT_NEAR(original.robot["distance_walked_m"].get<double>(), changed.robot["distance_walked_m"].get<double>(), 1e-9);
}

TEST(RotatedFootFrame, WalksExactlyAsTheOriginal) {
  const fs::path original_dir = FreshDir("rotated_foot_original"), rotated_dir = FreshDir("rotated_foot_rotated");
  fs::create_directories(original_dir);
  fs::create_directories(rotated_dir);
  std::ofstream(rotated_dir / "biped_rotated.urdf") << RotatedBiped();
  const WalkRun original = Walk(original_dir, kBipedUrdf.string());
  const WalkRun rotated = Walk(rotated_dir, "biped_rotated.urdf");
  ExpectTheSameWalk(original, rotated, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX())));
  fs::remove_all(original_dir);
  fs::remove_all(rotated_dir);
}

TEST(PitchedSole, WalkedFlatAtThePitchItsGeometryLiesFlattestOrAtAnkleZeroDeg) {
  const fs::path original_dir = FreshDir("pitched_sole_original"), pitched_dir = FreshDir("pitched_sole_pitched");
  fs::create_directories(original_dir);
  fs::create_directories(pitched_dir);
  std::ofstream(pitched_dir / "biped_pitched.urdf") << PitchedBiped();
  const std::string legs_without =
      "  legs:\n"
      "    left:  {hip: left_hip_pitch,  knee: left_knee_pitch,  ankle: left_ankle_pitch,  foot: left_foot}\n"
      "    right: {hip: right_hip_pitch, knee: right_knee_pitch, ankle: right_ankle_pitch, foot: right_foot}\n";
  const auto with_zero = [&](const std::string& deg) {
    std::string legs = legs_without;
    for (const std::string foot : {"left_foot}", "right_foot}"})
      ReplaceAfter(legs, foot, foot.substr(0, foot.size() - 1) + ", ankle_zero_deg: " + deg + "}", 0);
    return legs;
  };
  // told the sole is flat at joint zero, it is refused, naming the key and
  // the pitch the geometry lies flattest at (a 0.1 deg scan: the 10 deg it was turned by)
  const WalkRun refused = Walk(pitched_dir, "biped_pitched.urdf", with_zero("0"));
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("the sole must reach behind and in front of the ankle"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("robot.legs.left.ankle_zero_deg gives its pitch there"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("its geometry lies flattest at 10.0 deg"), std::string::npos) << refused.output;
  fs::remove_all(pitched_dir / "out");
  const WalkRun original = Walk(original_dir, kBipedUrdf.string());
  const Eigen::Quaterniond pitched_by(Eigen::AngleAxisd(10.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()));
  // given its pitch, found from the geometry under a leg map or with no map
  // at all, it walks with its sole flat, as the original; summary.json's
  // robot.gait says the pitch the gait used for each foot (the original's 0)
  ASSERT_EQ(original.exit_code, 0) << original.output;
  for (const char* side : {"left", "right"})
    EXPECT_EQ(original.robot["gait"]["ankle_zero_deg"][side].get<double>(), 0.0) << original.robot["gait"].dump();
  for (const std::string& legs : {with_zero("10"), legs_without, std::string()}) {
    const WalkRun pitched = Walk(pitched_dir, "biped_pitched.urdf", legs);
    ExpectTheSameWalk(original, pitched, pitched_by);
    for (const char* side : {"left", "right"}) {
      // given: 10 exactly (a degree turned to radians and back); found: the 0.1 deg scan's
      EXPECT_NEAR(pitched.robot["gait"]["ankle_zero_deg"][side].get<double>(), 10.0, legs.find("ankle_zero_deg") != std::string::npos ? 1e-9 : 0.05)
          << side << ": " << pitched.robot["gait"].dump();
    }
    fs::remove_all(pitched_dir / "out");
  }
  // `proxsim inspect` says the pitch it found, as the key that would give it; the original has none
  const auto inspected = RunProxsim("inspect '" + (pitched_dir / "biped_pitched.urdf").string() + "'");
  EXPECT_EQ(inspected.exit_code, 0) << inspected.output;
  EXPECT_NE(inspected.output.find("foot: left_foot, ankle_zero_deg: 10.0}"), std::string::npos) << inspected.output;
  EXPECT_NE(inspected.output.find("foot: right_foot, ankle_zero_deg: 10.0}"), std::string::npos) << inspected.output;
  const auto inspected_json = RunProxsim("inspect --json '" + (pitched_dir / "biped_pitched.urdf").string() + "' 2>/dev/null");
  const nlohmann::json found = nlohmann::json::parse(inspected_json.output.substr(inspected_json.output.find('{')));
  EXPECT_NEAR(found["legs"]["left"]["ankle_zero_deg"].get<double>(), 10.0, 0.05);
  const auto flat = RunProxsim("inspect '" + kBipedUrdf.string() + "'");
  EXPECT_EQ(flat.output.find("ankle_zero_deg"), std::string::npos) << flat.output;
  fs::remove_all(original_dir);
  fs::remove_all(pitched_dir);
}

}  // namespace
}  // namespace proxsim
