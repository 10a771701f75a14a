// The URDF's joint limits as the gait reads them (gait/joint_limits.h,
// gait/leg_kinematics.h): the velocity and effort limits are read, the
// two-link IK bends each knee the way its limits allow, a leg pose outside a
// range or a motion beyond a top speed is named with the joint, the value
// needed and the limit. Expected values are the URDF's numbers and
// trigonometry written here.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/embedded_files.h"
#include "gait/joint_limits.h"
#include "gait/leg_kinematics.h"
#include "robot/robot_model.h"

namespace proxsim {
namespace {

TEST(JointLimits, TheBipedsUrdfLimitsAreRead) {
  const RobotModel m = RobotModel::Builtin("biped");
  const RobotJoint& knee = m.joint(m.JointIndex("left_knee_pitch"));
  // data/robots/biped.urdf: <limit lower="0.0" upper="2.4" effort="300" velocity="12"/>
  EXPECT_EQ(knee.lower, 0.0);
  EXPECT_EQ(knee.upper, 2.4);
  EXPECT_EQ(knee.velocity, 12.0);
  EXPECT_EQ(m.joint(m.JointIndex("left_ankle_pitch")).velocity, 8.0);
  EXPECT_EQ(knee.effort, 300.0);
  EXPECT_EQ(m.joint(m.JointIndex("left_ankle_pitch")).effort, 200.0);
}

TEST(JointLimits, KneeBendsTheWayItsLimitsAllow) {
  const RobotModel human = RobotModel::Builtin("biped");
  const BipedLegs legs(human);
  // a target 0.8 m below the hip, straight down: thigh and shank of 0.45 m
  const Vec2xz hip(legs.leg(Side::kLeft).p_PH.x(), legs.leg(Side::kLeft).p_PH.z());
  const LegAnglesRad a = legs.SolveAnkle(Side::kLeft, hip + Vec2xz(0, -0.8), 0.0);
  const double knee = std::acos((0.8 * 0.8 - 2 * 0.45 * 0.45) / (2 * 0.45 * 0.45));
  EXPECT_NEAR(a.knee, knee, 1e-9);  // flexion: the URDF allows 0 to 2.4 rad
  EXPECT_NEAR(legs.Ankle(Side::kLeft, a).y(), hip.y() - 0.8, 1e-9);

  // the same robot whose knees bend the other way only
  std::string urdf(EmbeddedFiles().at("data/robots/biped.urdf"));
  for (std::size_t at = 0; (at = urdf.find("lower=\"0.0\" upper=\"2.4\"", at)) != std::string::npos;)
    urdf.replace(at, 23, "lower=\"-2.4\" upper=\"0.0\"");
  const RobotModel bird = RobotModel::FromUrdfText(urdf, "bird.urdf");
  const BipedLegs bird_legs(bird);
  EXPECT_EQ(bird_legs.leg(Side::kLeft).knee_bend, -1);
  const LegAnglesRad b = bird_legs.SolveAnkle(Side::kLeft, hip + Vec2xz(0, -0.8), 0.0);
  EXPECT_NEAR(b.knee, -knee, 1e-9);
  EXPECT_NEAR(bird_legs.Ankle(Side::kLeft, b).y(), hip.y() - 0.8, 1e-9);
  EXPECT_FALSE(LegLimits(bird_legs).AngleExcess(Side::kLeft, b).has_value());
}

TEST(JointLimits, ExcessNamesTheJointTheValueAndTheLimit) {
  const RobotModel m = RobotModel::Builtin("biped");
  const BipedLegs legs(m);
  const LegLimits limits(legs);
  LegAnglesRad a;
  a.hip = 0.5;
  a.knee = 2.5;  // the knee's upper limit is 2.4 rad
  a.pitch = (a.hip - a.knee);  // the ankle at 0: foot along the shank
  const auto excess = limits.AngleExcess(Side::kRight, a);
  ASSERT_TRUE(excess.has_value());
  EXPECT_EQ(excess->joint, "right_knee_pitch");
  EXPECT_NEAR(excess->needed, 2.5, 1e-12);
  EXPECT_EQ(excess->limit, 2.4);
  EXPECT_EQ(excess->Describe(), "joint 'right_knee_pitch' needs 143.2 deg, beyond its limit 137.5 deg");

  // 0.1 rad of ankle in 10 ms: 10 rad/s against 8
  LegAnglesRad from, to;
  to.pitch = 0.1;  // hip and knee still: the ankle alone turns
  const auto fast = limits.SpeedExcess(Side::kLeft, from, to, 0.01);
  ASSERT_TRUE(fast.has_value());
  EXPECT_EQ(fast->joint, "left_ankle_pitch");
  EXPECT_NEAR(fast->needed, 10.0, 1e-9);
  EXPECT_EQ(fast->Describe(), "joint 'left_ankle_pitch' needs 10.00 rad/s, beyond its velocity limit 8.00 rad/s");
  EXPECT_FALSE(limits.SpeedExcess(Side::kLeft, from, to, 0.02).has_value());  // 5 rad/s
}

}  // namespace
}  // namespace proxsim
