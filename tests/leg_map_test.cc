// The gait on a biped that is not the built-in one: a small robot written
// here with its own joint names and chain order (hip yaw before the hip
// pitch, hip roll after it, an ankle roll after the ankle pitch), a thigh
// leaning forward at its zero pose, pitch axes of both signs and mesh feet
// (STL written by the test). The leg map reads its geometry from the URDF
// (checked against numbers computed here), its joint values reproduce the
// model's own forward kinematics, it walks with its loaded feet planted and
// nothing under the floor, default stride and period scale with its legs,
// every kind of bad map is refused with a message that says which and why,
// and `proxsim inspect` finds its map from its geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "input_error_helpers.h"
#include "stl_files.h"

#include "gait/gait_walker.h"
#include "scenario/scenario.h"
#include "gait/held_joints.h"
#include "robot/robot_model.h"
#include "scene/shape_points.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::ErrorOf;

// Dimensions of the strider, and where its sole is (foot mesh: a 0.2 m cube
// scaled to 0.24 × 0.10 × 0.06 m, centred 0.05 m ahead of and 0.06 m below the
// ankle): sole 0.09 m below the ankle, heel 0.07 m behind, toe 0.17 m ahead.
constexpr double kKneeX_m = 0.02, kKneeZ_m = 0.40, kShank_m = 0.38;
constexpr double kSoleZ_m = -0.09, kHeelX_m = -0.07, kToeX_m = 0.17;

// One leg of the strider: {S} is l or r, {Y} its hip's side (+ or −).
constexpr const char* kLegTemplate = R"(
  <link name="{S}_hip_yaw_link"/>
  <link name="{S}_hip_pitch_link"/>
  <link name="{S}_thigh"><visual><origin xyz="0.01 0 -0.2"/><geometry><cylinder radius="0.05" length="0.4"/></geometry></visual></link>
  <link name="{S}_shin"><visual><origin xyz="0 0 -0.19"/><geometry><cylinder radius="0.04" length="0.38"/></geometry></visual></link>
  <link name="{S}_ankle_link"/>
  <link name="{S}_foot"><visual><origin xyz="0.05 0 -0.06"/><geometry><mesh filename="../meshes/foot.stl" scale="1.2 0.5 0.3"/></geometry></visual></link>
  <joint name="{S}_hip_yaw" type="revolute"><parent link="base"/><child link="{S}_hip_yaw_link"/><origin xyz="0 {Y}0.12 -0.05"/><axis xyz="0 0 1"/><limit lower="-0.5" upper="0.5" effort="1" velocity="20"/></joint>
  <joint name="{S}_hip_pitch" type="revolute"><parent link="{S}_hip_yaw_link"/><child link="{S}_hip_pitch_link"/><origin xyz="0.01 0 -0.03"/><axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="20"/></joint>
  <joint name="{S}_hip_roll" type="revolute"><parent link="{S}_hip_pitch_link"/><child link="{S}_thigh"/><axis xyz="1 0 0"/><limit lower="-0.3" upper="0.3" effort="1" velocity="20"/></joint>
  <joint name="{S}_knee" type="revolute"><parent link="{S}_thigh"/><child link="{S}_shin"/><origin xyz="0.02 0 {KNEE}"/><axis xyz="0 -1 0"/><limit lower="-2.5" upper="0.1" effort="1" velocity="20"/></joint>
  <joint name="{S}_ankle_pitch" type="revolute"><parent link="{S}_shin"/><child link="{S}_ankle_link"/><origin xyz="0 0 -0.38"/><axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="1" velocity="20"/></joint>
  <joint name="{S}_ankle_roll" type="revolute"><parent link="{S}_ankle_link"/><child link="{S}_foot"/><axis xyz="1 0 0"/><limit lower="-0.3" upper="0.3" effort="1" velocity="20"/></joint>
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// The strider's URDF; `extra` is appended inside <robot>, `right_knee_z` sets the right leg's length.
std::string StriderUrdf(const std::string& extra = "", double right_knee_z = -kKneeZ_m) {
  std::string urdf = R"(<?xml version="1.0"?>
<robot name="strider">
  <link name="base"><visual><origin xyz="0 0 0.1"/><geometry><box size="0.2 0.3 0.2"/></geometry></visual></link>)";
  urdf += Replace(Replace(Replace(kLegTemplate, "{S}", "l"), "{Y}", ""), "{KNEE}", std::to_string(-kKneeZ_m));
  urdf += Replace(Replace(Replace(kLegTemplate, "{S}", "r"), "{Y}", "-"), "{KNEE}", std::to_string(right_knee_z));
  return urdf + extra + "\n</robot>\n";
}

// Writes the strider (and its foot mesh) under `dir`; returns the URDF's path.
std::string WriteStrider(const fs::path& dir, const std::string& urdf = StriderUrdf()) {
  testing::WriteBinaryStl(dir / "meshes" / "foot.stl", testing::CubeTriangles(0.1));
  testing::WriteText(dir / "urdf" / "strider.urdf", urdf);
  return (dir / "urdf" / "strider.urdf").string();
}

std::array<LegNames, 2> StriderLegs() {
  return {LegNames{"l_hip_pitch", "l_knee", "l_ankle_pitch", "l_foot"},
          LegNames{"r_hip_pitch", "r_knee", "r_ankle_pitch", "r_foot"}};
}

RobotConfig StriderConfig(const std::string& urdf) {
  RobotConfig config;
  config.model = urdf;
  config.legs = StriderLegs();
  return config;
}

class LegMapTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::FreshDir("leg_map"); }
  void TearDown() override { fs::remove_all(dir_); }
  // The message refusing a strider walked with `config` changed by `edit`, its URDF by `urdf`.
  template <typename Edit>
  std::string Refusal(Edit edit, const std::string& urdf = StriderUrdf()) {
    RobotConfig config = StriderConfig(WriteStrider(dir_, urdf));
    edit(config);
    return ErrorOf([&] { GaitWalker(RobotModel::FromUrdfFile(config.model), config); });
  }
  fs::path dir_;
};

TEST_F(LegMapTest, ReadsTheLegsFromTheUrdfNotFromNames) {
  const RobotModel model = RobotModel::FromUrdfFile(WriteStrider(dir_));
  const BipedLegs legs(model, StriderLegs(), std::vector<double>(model.joint_count(), 0.0));
  for (const Side side : {Side::kLeft, Side::kRight}) {
    const LegGeometry& g = legs.leg(side);
    // signs from the axes: hip +y, knee −y, ankle +y
    EXPECT_EQ(g.hip_sign, 1.0);
    EXPECT_EQ(g.knee_sign, -1.0);
    EXPECT_EQ(g.ankle_sign, 1.0);
    // the hip pitch joint: yaw origin + pitch origin; the thigh leans forward by atan(0.02 / 0.40)
    EXPECT_TRUE(g.p_PH.isApprox(Vec3(0.01, side == Side::kLeft ? 0.12 : -0.12, -0.08), 1e-12));
    EXPECT_NEAR(g.thigh_m, std::hypot(kKneeX_m, kKneeZ_m), 1e-12);
    EXPECT_NEAR(g.thigh0_rad, std::atan2(kKneeX_m, kKneeZ_m), 1e-12);
    EXPECT_NEAR(g.shank_m, kShank_m, 1e-12);
    EXPECT_NEAR(g.shank0_rad, 0.0, 1e-12);
    // the sole from the foot mesh's lowest vertices (floats)
    EXPECT_NEAR(g.sole_z_m, kSoleZ_m, 1e-6);
    EXPECT_NEAR(g.heel_x_m, kHeelX_m, 1e-6);
    EXPECT_NEAR(g.toe_x_m, kToeX_m, 1e-6);
    EXPECT_NEAR(g.half_width_m, 0.05, 1e-6);
    EXPECT_NEAR(g.leg_length_m, std::hypot(kKneeX_m, kKneeZ_m) + kShank_m - kSoleZ_m, 1e-6);
  }
  // standing straight, the pelvis is hip height + thigh + shank + ankle height above the floor
  EXPECT_NEAR(legs.standing_height_m(), 0.08 + std::hypot(kKneeX_m, kKneeZ_m) + kShank_m - kSoleZ_m, 1e-6);
}

TEST_F(LegMapTest, JointValuesReproduceTheModelsForwardKinematicsWithHeldJoints) {
  const RobotModel model = RobotModel::FromUrdfFile(WriteStrider(dir_));
  // hip yaw held at 4°, hip roll at 3° with the ankle roll at −3° (the foot flat again)
  const std::vector<std::pair<std::string, double>> held = {
      {"l_hip_yaw", DegToRad(4)}, {"l_hip_roll", DegToRad(3)}, {"l_ankle_roll", DegToRad(-3)}};
  const std::vector<double> q_held = HeldJointAngles(model, held, StriderLegs());
  const BipedLegs legs(model, StriderLegs(), q_held);
  double worst_m = 0, worst_planar_m = 0;
  for (const LegAnglesRad a : {LegAnglesRad{0, 0, 0}, LegAnglesRad{0.4, 0.9, 0.2}, LegAnglesRad{-0.2, 0.1, -0.3},
                               LegAnglesRad{0.7, 1.4, 0.0}}) {
    std::vector<double> q = q_held;
    legs.WriteJoints(Side::kLeft, a, q);
    const LegAnglesRad back = legs.ReadJoints(Side::kLeft, q);
    EXPECT_NEAR(back.hip, a.hip, 1e-12);
    EXPECT_NEAR(back.knee, a.knee, 1e-12);
    EXPECT_NEAR(back.pitch, a.pitch, 1e-12);
    const std::vector<Pose> X_PL = model.ForwardKinematics(Pose::Identity(), q);
    const Pose& X_PF = X_PL[legs.leg(Side::kLeft).foot_link];
    EXPECT_TRUE(legs.FootPose_P(Side::kLeft, a).isApprox(X_PF, 1e-12));
    for (const FootPoint which : {FootPoint::kHeel, FootPoint::kMid, FootPoint::kToe}) {
      const Vec3 exact = X_PF * legs.FootPoint_L(Side::kLeft, which);
      worst_m = std::max(worst_m, (legs.Point3(Side::kLeft, a, which) - exact).norm());
      // the planar model: exact on the right leg (nothing held), within the tilt's effect on the left
      worst_planar_m = std::max(worst_planar_m, (legs.Point(Side::kLeft, a, which) - Vec2xz(exact.x(), exact.z())).norm());
    }
    // the foot pitch: the sole's heel-to-toe direction, toe up positive
    const Vec3 heel_to_toe = X_PF.linear() * (legs.leg(Side::kLeft).p_L_toe - legs.leg(Side::kLeft).p_L_heel);
    EXPECT_NEAR(std::atan2(heel_to_toe.z(), std::hypot(heel_to_toe.x(), heel_to_toe.y())), a.pitch, 2e-3);
  }
  EXPECT_LT(worst_m, 1e-12);
  std::printf("[ measured ] planar model against the exact chain with 3 deg of hip roll held: %.2f mm\n",
              1e3 * worst_planar_m);
  EXPECT_LT(worst_planar_m, 0.02);
}

// The walk's guarantees on the strider, checked with the model's own FK over
// six cycles at 200 Hz: the stance pivot and the trailing toe stay where they
// were latched, no geometry goes through the floor, the stride is as asked.
void ExpectPlantedWalk(const RobotConfig& config, double stride_m) {
  GaitWalker walker(RobotModel::FromUrdfFile(config.model), config);
  const RobotModel& model = walker.model();
  const BipedLegs& legs = walker.legs();
  // every link's outline points, for the floor check
  std::vector<std::vector<Vec3>> outline_L(model.link_count());
  for (int link = 0; link < model.link_count(); ++link)
    for (const LinkShape& shape : model.link(link).shapes)
      for (const Vec3& p_O : ShapeOutlinePoints_O(shape.shape)) outline_L[link].push_back(shape.X_LO * p_O);
  const double period_s = walker.gait_cycle()->period_s;
  double pivot_slip_m = 0, toe_slip_m = 0, lowest_m = 1e9;
  std::vector<double> left_strike_x;
  Side last_stance = Side::kRight;
  const int samples = static_cast<int>(6 * period_s * 200);
  for (int i = 0; i <= samples; ++i) {
    const RobotState s = walker.Advance(i / 200.0);
    const std::vector<Pose> X_WL = model.ForwardKinematics(s.X_WP, s.q);
    const StepPlan& plan = walker.current_step();
    const double p = walker.step_phase();
    const LegGeometry& stance = legs.leg(plan.stance);
    const Vec3 pivot = p < FootFlatPhase() ? X_WL[stance.foot_link] * stance.p_L_heel
                       : p <= HeelOffPhase() ? X_WL[stance.foot_link] * stance.p_L_sole
                                             : X_WL[stance.foot_link] * stance.p_L_toe;
    const Vec3 latched = p < FootFlatPhase() ? plan.p_W_heel
                         : p <= HeelOffPhase() ? plan.X_WF * stance.p_L_sole
                                               : plan.X_WF * stance.p_L_toe;
    pivot_slip_m = std::max(pivot_slip_m, (pivot - latched).norm());
    if (p < kDoubleSupportEnd) {
      const LegGeometry& trailing = legs.leg(plan.swing);
      toe_slip_m = std::max(toe_slip_m, (X_WL[trailing.foot_link] * trailing.p_L_toe - plan.p_W_trailing_toe).norm());
    }
    for (int link = 0; link < model.link_count(); ++link)
      for (const Vec3& p_L : outline_L[link]) lowest_m = std::min(lowest_m, (X_WL[link] * p_L).z());
    if (plan.stance == Side::kLeft && last_stance == Side::kRight) left_strike_x.push_back(plan.p_W_heel.x());
    last_stance = plan.stance;
  }
  std::printf("[ measured ] %s, stride %.3f m: stance pivot slip %.3g mm, trailing toe slip %.3g mm, lowest point %.3g mm\n",
              config.joints_rad.empty() ? "strider" : "strider with hip roll held", stride_m, 1e3 * pivot_slip_m,
              1e3 * toe_slip_m, 1e3 * lowest_m);
  EXPECT_LT(pivot_slip_m, 1e-6);
  EXPECT_LT(toe_slip_m, 1e-3);
  EXPECT_GT(lowest_m, -1e-3);
  ASSERT_GE(left_strike_x.size(), 4u);
  EXPECT_NEAR(left_strike_x.back() - left_strike_x[left_strike_x.size() - 2], stride_m, 0.02 * stride_m);
}

TEST_F(LegMapTest, WalksWithItsLoadedFeetPlantedAndNothingUnderTheFloor) {
  RobotConfig config = StriderConfig(WriteStrider(dir_));
  config.gait.stride_m = 0.5;
  config.gait.period_s = 1.1;
  ExpectPlantedWalk(config, 0.5);
  // legs splayed by a held hip roll (knee and ankle axes 3° off the sagittal normal), feet made flat by the ankle roll
  config.joints_rad = {{"l_hip_roll", DegToRad(3)}, {"l_ankle_roll", DegToRad(-3)},
                       {"r_hip_roll", DegToRad(-3)}, {"r_ankle_roll", DegToRad(3)}};
  ExpectPlantedWalk(config, 0.5);
}

TEST_F(LegMapTest, DefaultStrideAndPeriodScaleWithTheLegs) {
  RobotConfig config = StriderConfig(WriteStrider(dir_));
  config.gait.derive_stride_from_legs = config.gait.derive_period_from_legs = true;
  GaitWalker walker(RobotModel::FromUrdfFile(config.model), config);
  const double ratio = walker.legs().leg_length_m() / kReferenceLegLength_m;
  EXPECT_LT(ratio, 0.95) << "the strider's legs are shorter than the built-in biped's";
  EXPECT_NEAR(walker.gait_cycle()->stride_m, kReferenceStride_m * ratio, 1e-4);
  EXPECT_DOUBLE_EQ(walker.gait_cycle()->period_s, kReferencePeriod_s * std::sqrt(ratio));
  // the built-in biped keeps its 0.6 m and 1.2 s exactly
  RobotConfig biped;
  biped.gait.derive_stride_from_legs = biped.gait.derive_period_from_legs = true;
  GaitWalker builtin(RobotModel::Builtin("biped"), biped);
  EXPECT_NEAR(builtin.gait_cycle()->stride_m, 0.6, 1e-6);
  EXPECT_EQ(builtin.gait_cycle()->period_s, 1.2);
}

TEST_F(LegMapTest, BadMapsAndHeldJointsAreRefusedSayingWhichAndWhy) {
  const auto expect_refusal = [](const std::string& message, const std::vector<std::string>& parts) {
    ASSERT_FALSE(message.empty()) << "no InputError";
    for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << part << "\nin:\n" << message;
  };
  // no map on a robot without the built-in biped's names
  expect_refusal(Refusal([](RobotConfig& c) { c.legs.reset(); }),
                 {"strider.urdf: robot.legs is not given", "left_hip_pitch", "robot.legs: {left: {hip: JOINT"});
  // a missing joint, with the nearest name; a missing foot link
  expect_refusal(Refusal([](RobotConfig& c) {
                   (*c.legs)[0].hip = "l_hip_pich";
                   (*c.legs)[1].foot = "r_toe";
                 }),
                 {"robot.legs.left.hip: no joint 'l_hip_pich' in the URDF (did you mean 'l_hip_pitch'?)",
                  "robot.legs.right.foot: no link 'r_toe' in the URDF"});
  // a joint that is not revolute
  expect_refusal(Refusal([](RobotConfig& c) { (*c.legs)[0].ankle = "l_toe_joint"; },
                         StriderUrdf(R"(<link name="l_toe"/><joint name="l_toe_joint" type="fixed"><parent link="l_foot"/><child link="l_toe"/></joint>)")),
                 {"robot.legs.left.ankle: joint 'l_toe_joint' is not revolute"});
  // joints out of order, and a joint of the other leg
  expect_refusal(Refusal([](RobotConfig& c) { std::swap((*c.legs)[0].hip, (*c.legs)[0].knee); }),
                 {"robot.legs.left: the chain from the root to the foot must pass the hip, then the knee, then the ankle"});
  expect_refusal(Refusal([](RobotConfig& c) { (*c.legs)[0].knee = "r_knee"; }),
                 {"robot.legs.left.knee: joint 'r_knee' is not on the chain from the root link to the foot 'l_foot'"});
  // a pitch axis off the sagittal normal: a roll joint mapped as the hip, or a held roll tilting the knee
  expect_refusal(Refusal([](RobotConfig& c) { (*c.legs)[0].hip = "l_hip_roll"; }),
                 {"robot.legs.left.hip: joint 'l_hip_roll''s axis is 90.0° off the sagittal normal", "within 5°"});
  expect_refusal(Refusal([](RobotConfig& c) { c.joints_rad = {{"r_hip_roll", DegToRad(8)}}; }),
                 {"robot.legs.right.knee: joint 'r_knee''s axis is 8.0° off", "robot.legs.right.ankle: joint 'r_ankle_pitch''s axis is 8.0° off"});
  // legs that cannot reach the ground: of unequal length, or another link hanging below the soles
  expect_refusal(Refusal([](RobotConfig&) {}, StriderUrdf("", -0.45)),
                 {"robot.legs: the legs cannot both reach the ground: standing straight, the left sole is"});
  expect_refusal(Refusal([](RobotConfig&) {},
                         StriderUrdf(R"(<link name="tail"><visual><geometry><sphere radius="0.05"/></geometry></visual></link>
                           <joint name="tail_joint" type="fixed"><parent link="base"/><child link="tail"/><origin xyz="-0.3 0 -1.0"/></joint>)")),
                 {"robot.legs: link 'tail' hangs 0.1", "below the soles at the reference pose, so the feet cannot reach the ground"});
  // a foot without geometry; a sole that does not reach in front of the ankle
  expect_refusal(Refusal([](RobotConfig&) {}, Replace(StriderUrdf(), R"(<link name="r_foot"><visual><origin xyz="0.05 0 -0.06"/><geometry><mesh filename="../meshes/foot.stl" scale="1.2 0.5 0.3"/></geometry></visual></link>)", R"(<link name="r_foot"/>)")),
                 {"robot.legs.right.foot: link 'r_foot' (and the links below it) has no geometry"});
  expect_refusal(Refusal([](RobotConfig&) {}, Replace(StriderUrdf(), R"(<link name="l_foot"><visual><origin xyz="0.05 0 -0.06"/>)", R"(<link name="l_foot"><visual><origin xyz="0.3 0 -0.06"/>)")),
                 {"robot.legs.left.foot: link 'l_foot' has its sole", "must reach behind and in front of the ankle"});
  // held joints: unknown (nearest suggested), driven by the gait, outside the limits
  expect_refusal(Refusal([](RobotConfig& c) {
                   c.joints_rad = {{"l_hip_yaww", 0.1}, {"l_knee", 0.2}, {"r_hip_roll", DegToRad(30)}};
                 }),
                 {"robot.joints_deg.l_hip_yaww: no joint 'l_hip_yaww' in the URDF (did you mean 'l_hip_yaw'?)",
                  "robot.joints_deg.l_knee: the gait drives this joint",
                  "robot.joints_deg.r_hip_roll: 30° is outside the joint's limits [-17.19°, 17.19°]"});
}

// `proxsim inspect` (through the binary) finds the strider's map by axes and
// heights, past the hip yaw before and the hip roll after the hip pitch, a
// knee axis of the other sign and the ankle roll; its shin's front is the
// cylinder's surface, 0.04 m ahead of the knee–ankle line, also when the
// shin's shapes hang on a fixed link below the knee's.
TEST_F(LegMapTest, InspectSuggestsTheMapByGeometry) {
  const std::string urdf = WriteStrider(dir_);
  const testing::CommandResult result = testing::RunProxsim("inspect " + urdf + " --json");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const nlohmann::json inspect = nlohmann::json::parse(result.output);
  EXPECT_TRUE(inspect["legs_accepted"].get<bool>()) << inspect["legs_problems"].dump();
  const auto legs = StriderLegs();
  for (const auto& [side, leg] : {std::pair{"left", legs[0]}, std::pair{"right", legs[1]}}) {
    EXPECT_EQ(inspect["legs"][side], (nlohmann::json{{"hip", leg.hip}, {"knee", leg.knee}, {"ankle", leg.ankle},
                                                    {"foot", leg.foot}, {"ankle_zero_deg", 0.0}}))
        << side;
  }
  EXPECT_EQ(inspect["shanks"]["left"]["link"], "l_shin");
  for (const auto& spot : inspect["shanks"]["left"]["front_surface"]) {
    // closed form in double (no ray caster): rounding only
    EXPECT_NEAR(spot["xyz_m"][0].get<double>(), 0.04 + 0.005, 1e-9);  // the shin's radius, 5 mm proud of it
    EXPECT_NEAR(spot["xyz_m"][2].get<double>(), -kShank_m * spot["fraction"].get<double>(), 1e-9);
  }
  // the shin's shapes on a fixed link below the knee's: that link is the shank
  const std::string shell = R"(<link name="l_shin_shell"><visual><origin xyz="0 0 -0.19"/><geometry><cylinder radius="0.04" length="0.38"/></geometry></visual></link>
  <joint name="l_shell_fixed" type="fixed"><parent link="l_shin"/><child link="l_shin_shell"/></joint>)";
  const std::string bare_shin = Replace(
      StriderUrdf(shell),
      R"(<link name="l_shin"><visual><origin xyz="0 0 -0.19"/><geometry><cylinder radius="0.04" length="0.38"/></geometry></visual></link>)",
      R"(<link name="l_shin"/>)");
  const testing::CommandResult moved = testing::RunProxsim("inspect " + WriteStrider(dir_, bare_shin) + " --json");
  ASSERT_EQ(moved.exit_code, 0) << moved.output;
  const nlohmann::json moved_inspect = nlohmann::json::parse(moved.output);
  EXPECT_EQ(moved_inspect["legs"]["left"]["knee"], "l_knee");
  EXPECT_EQ(moved_inspect["shanks"]["left"]["link"], "l_shin_shell");
  EXPECT_EQ(moved_inspect["shanks"]["left"]["front_surface"].size(), 3u);
}

}  // namespace
}  // namespace proxsim
