// RobotModel: forward kinematics against closed-form trigonometry on a planar
// two-link leg written here, the shipped biped's shape and size, and broken
// URDFs refused with the file named.
#include <chrono>
#include <cmath>

#include <gtest/gtest.h>

#include "input_error_helpers.h"

#include "core/input_error.h"
#include "robot/robot_model.h"

namespace proxsim {
namespace {

// A hip at the base origin, thigh L1 and shank L2 hanging along −z; hip flexion
// about −y and knee flexion about +y as in the biped; a fixed "ankle" marker.
constexpr double kL1 = 0.4, kL2 = 0.35;
const char* kTwoLink = R"(<?xml version="1.0"?>
<robot name="two_link">
  <link name="base"/>
  <link name="thigh"><collision><origin xyz="0 0 -0.2"/><geometry><cylinder radius="0.05" length="0.4"/></geometry></collision></link>
  <link name="shank"><visual><origin xyz="0 0 -0.175"/><geometry><box size="0.1 0.1 0.35"/></geometry></visual></link>
  <link name="ankle"/>
  <link name="slider"/>
  <link name="wheel"/>
  <joint name="hip" type="revolute"><parent link="base"/><child link="thigh"/><axis xyz="0 -1 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="knee" type="revolute"><parent link="thigh"/><child link="shank"/><origin xyz="0 0 -0.4"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="2.5" effort="1" velocity="1"/></joint>
  <joint name="ankle_fixed" type="fixed"><parent link="shank"/><child link="ankle"/><origin xyz="0 0 -0.35"/></joint>
  <joint name="slide" type="prismatic"><parent link="base"/><child link="slider"/><origin xyz="0 0 0" rpy="0 0 1.5707963267948966"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="spin" type="continuous"><parent link="slider"/><child link="wheel"/><axis xyz="0 0 1"/></joint>
</robot>)";

using testing::ErrorOf;

TEST(RobotModel, TwoLinkLegForwardKinematicsMatchesTrigonometry) {
  const RobotModel m = RobotModel::FromUrdfText(kTwoLink, "two_link.urdf");
  ASSERT_EQ(m.link_count(), 6);
  ASSERT_EQ(m.joint_count(), 5);
  EXPECT_EQ(m.link_name(m.root_link()), "base");
  EXPECT_EQ(m.LinkIndex("nope"), -1);
  EXPECT_EQ(m.JointIndex("nope"), -1);
  // geometry: collision on the thigh, the visual box as fallback on the shank
  ASSERT_EQ(m.link(m.LinkIndex("thigh")).shapes.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Cylinder>(m.link(m.LinkIndex("thigh")).shapes[0].shape));
  ASSERT_EQ(m.link(m.LinkIndex("shank")).shapes.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Box>(m.link(m.LinkIndex("shank")).shapes[0].shape));
  EXPECT_NEAR(m.link(m.LinkIndex("shank")).shapes[0].X_LO.translation().z(), -0.175, 1e-12);

  const double H = 0.9;
  const Pose X_WRoot = PoseFromXyzRpy(Vec3(0.3, -0.1, H), Vec3::Zero());
  for (const auto& [t1, t2] : {std::pair{0.0, 0.0}, std::pair{0.4, 0.9}, std::pair{-0.3, 0.2}, std::pair{1.1, 2.0}}) {
    std::vector<double> q(m.joint_count(), 0.0);
    q[m.JointIndex("hip")] = t1;
    q[m.JointIndex("knee")] = t2;
    q[m.JointIndex("slide")] = 0.25;
    q[m.JointIndex("spin")] = 0.7;
    const std::vector<Pose> X_WL = m.ForwardKinematics(X_WRoot, q);
    // ankle = hip + L1 (sin θ1, −cos θ1) + L2 (sin(θ1−θ2), −cos(θ1−θ2)) in x-z
    const Vec3 p_W_ankle = X_WL[m.LinkIndex("ankle")].translation();
    EXPECT_NEAR(p_W_ankle.x(), 0.3 + kL1 * std::sin(t1) + kL2 * std::sin(t1 - t2), 1e-12);
    EXPECT_NEAR(p_W_ankle.y(), -0.1, 1e-12);
    EXPECT_NEAR(p_W_ankle.z(), H - kL1 * std::cos(t1) - kL2 * std::cos(t1 - t2), 1e-12);
    // the shank's pitch: its −z axis points along (sin(θ1−θ2), −cos(θ1−θ2))
    const Vec3 down = X_WL[m.LinkIndex("shank")].linear() * Vec3(0, 0, -1);
    EXPECT_NEAR(down.x(), std::sin(t1 - t2), 1e-12);
    // prismatic along the slider's x, which is yawed to world +y; continuous spin about z
    EXPECT_NEAR(X_WL[m.LinkIndex("slider")].translation().y(), -0.1 + 0.25, 1e-12);
    EXPECT_NEAR(RpyFromRotation(X_WL[m.LinkIndex("wheel")].linear()).z(), kPi / 2 + 0.7, 1e-12);
  }
}

TEST(RobotModel, BuiltinBipedShapeSizeAndStandingSoles) {
  const RobotModel m = RobotModel::Builtin("biped");
  for (const char* link : {"pelvis", "torso", "head", "left_thigh", "left_tibia", "left_foot", "right_thigh",
                           "right_tibia", "right_foot"})
    EXPECT_GE(m.LinkIndex(link), 0) << link;
  for (const char* joint : {"left_hip_pitch", "left_knee_pitch", "left_ankle_pitch", "right_hip_pitch",
                            "right_knee_pitch", "right_ankle_pitch"}) {
    ASSERT_GE(m.JointIndex(joint), 0) << joint;
    EXPECT_EQ(m.joint(m.JointIndex(joint)).type, JointType::kRevolute);
  }
  EXPECT_EQ(m.link_name(m.root_link()), "pelvis");
  EXPECT_NEAR(m.TotalMass_kg(), 100.0, 5.0);

  // standing at q = 0 with the pelvis at its nominal 0.98 m
  const std::vector<double> q(m.joint_count(), 0.0);
  const std::vector<Pose> X_WL = m.ForwardKinematics(PoseFromXyzRpy(Vec3(0, 0, 0.98), Vec3::Zero()), q);
  // top of the head: the head sphere's centre plus its radius
  const LinkShape& head = m.link(m.LinkIndex("head")).shapes.at(0);
  const double top = (X_WL[m.LinkIndex("head")] * head.X_LO).translation().z() + std::get<Sphere>(head.shape).radius_m;
  EXPECT_NEAR(top, 1.80, 0.02);
  // soles: the bottom face of each foot box at z = 0
  for (const char* foot : {"left_foot", "right_foot"}) {
    const LinkShape& sole = m.link(m.LinkIndex(foot)).shapes.at(0);
    const Pose X_WO = X_WL[m.LinkIndex(foot)] * sole.X_LO;
    EXPECT_NEAR(X_WO.translation().z() - std::get<Box>(sole.shape).size_m.z() / 2, 0.0, 1e-12) << foot;
  }
  EXPECT_NEAR(X_WL[m.LinkIndex("left_foot")].translation().y(), 0.10, 1e-12);
  EXPECT_NEAR(X_WL[m.LinkIndex("right_foot")].translation().y(), -0.10, 1e-12);
  // flexing the left hip swings the thigh forward (+x): the documented sign
  std::vector<double> q_flex = q;
  q_flex[m.JointIndex("left_hip_pitch")] = 0.3;
  EXPECT_GT(m.ForwardKinematics(Pose::Identity(), q_flex)[m.LinkIndex("left_tibia")].translation().x(), 0.1);
}

TEST(RobotModel, BrokenUrdfsAreInputErrorsNamingTheFile) {
  // a cycle: each link the other's parent, so no root
  const std::string cycle = ErrorOf([] { RobotModel::FromUrdfFile(PROXSIM_TEST_DATA_DIR "/robots/planar_cycle.urdf"); });
  EXPECT_NE(cycle.find("planar_cycle.urdf"), std::string::npos) << cycle;
  EXPECT_NE(cycle.find("urdfdom could not parse"), std::string::npos) << cycle;
  // a joint naming a missing link
  const std::string missing = ErrorOf([] {
    RobotModel::FromUrdfText(R"(<robot name="r"><link name="a"/>
      <joint name="j" type="fixed"><parent link="a"/><child link="ghost"/></joint></robot>)", "missing.urdf");
  });
  EXPECT_NE(missing.find("missing.urdf"), std::string::npos) << missing;
  // a separate cycle next to a valid root: urdfdom accepts it, we do not
  const std::string island = ErrorOf([] {
    RobotModel::FromUrdfText(R"(<robot name="r"><link name="root"/><link name="a"/><link name="b"/>
      <joint name="ab" type="fixed"><parent link="a"/><child link="b"/></joint>
      <joint name="ba" type="fixed"><parent link="b"/><child link="a"/></joint></robot>)", "island.urdf");
  });
  EXPECT_NE(island.find("island.urdf"), std::string::npos) << island;
  // not XML at all
  const std::string not_xml = ErrorOf([] { RobotModel::FromUrdfText("this is not xml <", "junk.urdf"); });
  EXPECT_NE(not_xml.find("junk.urdf"), std::string::npos) << not_xml;
  // a mesh that is not there (robot_mesh_test.cc has the rest), a missing file, an unknown built-in
  const std::string mesh = ErrorOf([] {
    RobotModel::FromUrdfText(R"(<robot name="r"><link name="a"><visual><geometry><mesh filename="a.stl"/></geometry></visual></link></robot>)",
                             "/nonexistent/mesh.urdf");
  });
  EXPECT_NE(mesh.find("/nonexistent/mesh.urdf: link 'a' (visual): mesh 'a.stl' not found"), std::string::npos) << mesh;
  EXPECT_NE(ErrorOf([] { RobotModel::FromUrdfFile("/nonexistent/robot.urdf"); }).find("/nonexistent/robot.urdf"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] { RobotModel::Builtin("quadruped"); }).find("builtin:quadruped"), std::string::npos);
}

}  // namespace
}  // namespace proxsim

namespace proxsim {
namespace {

TEST(RobotModel, XacroIsRecognisedByItsContentNotItsName) {
  // as text (no file for xacro to run on), an element of xacro's, or its namespace with a
  // substitution: "this is xacro", one problem (a file is expanded: tests/xacro_test.cc)
  for (const char* text :
       {R"(<robot name="r"><xacro:macro name="m"/><link name="base"/></robot>)",
        R"(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="base">
             <visual><geometry><box size="${w} 0.1 0.1"/></geometry></visual></link></robot>)"}) {
    // the whole message: one line, nothing else
    EXPECT_EQ(ErrorOf([&] { RobotModel::FromUrdfText(text, "r.urdf"); }),
              "r.urdf: this is xacro, given as text: expand it first (`xacro in.urdf.xacro > out.urdf`), or give "
              "its file (proxsim runs xacro on a file)");
  }
  // xacro's output may keep the namespace on a URDF with nothing left to expand: it loads
  const RobotModel expanded = RobotModel::FromUrdfText(
      R"(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="base">
           <visual><geometry><box size="0.2 0.1 0.1"/></geometry></visual></link></robot>)",
      "expanded.urdf");
  EXPECT_EQ(expanded.link_count(), 1);
}

TEST(RobotModel, JointLimitsKeepVelocityAndEffort) {
  const RobotModel m = RobotModel::FromUrdfText(kTwoLink, "two_link.urdf");
  const RobotJoint& knee = m.joint(m.JointIndex("knee"));
  EXPECT_TRUE(knee.has_limits);
  EXPECT_EQ(knee.upper, 2.5);
  EXPECT_EQ(knee.velocity, 1.0);
  EXPECT_EQ(knee.effort, 1.0);
  EXPECT_FALSE(m.joint(m.JointIndex("ankle_fixed")).has_limits);
}

// Issue 23 (n): a 100,000-link URDF took 224 s (name lookups by linear scan,
// and a joint-by-link double loop); the loader is now linear in links. Both
// shapes a generator might produce: one long chain, and a wide tree.
std::string GeneratedUrdf(int links, bool chain) {
  std::string urdf = "<robot name=\"many\">\n";
  for (int i = 0; i < links; ++i) urdf += "<link name=\"l" + std::to_string(i) + "\"/>\n";
  for (int i = 1; i < links; ++i) {
    const int parent = chain ? i - 1 : (i - 1) / 8;
    urdf += "<joint name=\"j" + std::to_string(i) + "\" type=\"revolute\"><parent link=\"l" + std::to_string(parent) +
            "\"/><child link=\"l" + std::to_string(i) + "\"/><axis xyz=\"0 0 1\"/>"
            "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n";
  }
  return urdf + "</robot>\n";
}

TEST(RobotModel, AHundredThousandLinksLoad) {
  for (const bool chain : {false, true}) {
    SCOPED_TRACE(chain ? "a chain" : "a tree of fan-out 8");
    const std::string urdf = GeneratedUrdf(100000, chain);
    // (how long it takes is not asserted here: no test depends on timing; the
    // quadratic loader would have made this test run for minutes)
    const RobotModel model = RobotModel::FromUrdfText(urdf, "generated.urdf");
    EXPECT_EQ(model.link_count(), 100000);
    EXPECT_EQ(model.joint_count(), 99999);
    EXPECT_EQ(model.LinkIndex("l99999"), 99999);
    EXPECT_EQ(model.joint(model.JointIndex("j77")).child_link, model.LinkIndex("l77"));
  }
}

}  // namespace
}  // namespace proxsim
