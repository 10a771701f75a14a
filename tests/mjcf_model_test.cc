// MuJoCo models (robot/mjcf_model.h): a two-leg robot written here both as
// MJCF and as its URDF twin has the same link poses (1e-9 m) at any joint
// values and walks the same under the gait's leg map; each geom type is hit by
// a ray at its closed-form distance; sites are frames a sensor mounts on;
// what proxsim cannot follow is named.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "cli_helpers.h"
#include "gait/locomotion.h"
#include "input_error_helpers.h"
#include "mjcf_twin.h"
#include "raycast/ray_caster.h"
#include "robot/mjcf_model.h"
#include "robot/robot_model.h"
#include "sim/robot_in_scene.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::ErrorOf;
using testing::FreshDir;
using testing::ReadCsv;
using testing::RunProxsim;

void WriteText(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// The same robot in URDF. The mast's hinges turn about anchors off the mast's
// origin: a link per joint on its anchor (mast.mast_yaw, mast.mast_pitch) and a
// fixed joint back, as the MJCF reader maps them; the site is a fixed link.
// Angles in radians; the mast's orientation is its quaternion's roll, pitch, yaw.
constexpr const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="twin">
  <link name="pelvis"><visual><origin xyz="0 0 0.04"/><geometry><box size="0.2 0.3 0.16"/></geometry></visual></link>
  <link name="mast.mast_yaw"/>
  <link name="mast.mast_pitch"/>
  <link name="mast"><visual><origin xyz="0 0 0.1"/><geometry><cylinder radius="0.02" length="0.2"/></geometry></visual></link>
  <link name="head"><visual><geometry><sphere radius="0.08"/></geometry></visual></link>
  <joint name="mast_yaw" type="revolute">
    <parent link="pelvis"/><child link="mast.mast_yaw"/>
    <origin xyz="%MAST_YAW_XYZ%" rpy="%MAST_RPY%"/>
    <axis xyz="0 0 1"/><limit lower="-0.7853981633974483" upper="0.7853981633974483" effort="0" velocity="0"/>
  </joint>
  <joint name="mast_pitch" type="continuous">
    <parent link="mast.mast_yaw"/><child link="mast.mast_pitch"/>
    <origin xyz="-0.01 0.01 0.03"/><axis xyz="0 1 0"/>
  </joint>
  <joint name="fixed:mast" type="fixed"><parent link="mast.mast_pitch"/><child link="mast"/><origin xyz="0 -0.01 -0.05"/></joint>
  <joint name="head_lift" type="prismatic">
    <parent link="mast"/><child link="head"/><origin xyz="0 0 0.25"/>
    <axis xyz="0 0 1"/><limit lower="-0.05" upper="0.1" effort="0" velocity="0"/>
  </joint>
%LEG:left:0.1%
%LEG:right:-0.1%
  <link name="left_shin_sensor"/>
  <joint name="site:left_shin_sensor" type="fixed">
    <parent link="left_tibia"/><child link="left_shin_sensor"/><origin xyz="0.06 0 -0.35" rpy="0 0.2617993877991494 0"/>
  </joint>
</robot>
)";

constexpr const char* kUrdfLeg = R"(  <link name="S_thigh"><visual><origin xyz="0 0 -0.225"/><geometry><cylinder radius="0.05" length="0.45"/></geometry></visual></link>
  <link name="S_tibia"><visual><origin xyz="0 0 -0.225"/><geometry><cylinder radius="0.04" length="0.45"/></geometry></visual></link>
  <link name="S_foot"><visual><origin xyz="0.07 0 -0.05"/><geometry><box size="0.26 0.1 0.06"/></geometry></visual></link>
  <joint name="S_hip_pitch" type="revolute"><parent link="pelvis"/><child link="S_thigh"/><origin xyz="0 Y 0"/>
    <axis xyz="0 -1 0"/><limit lower="-1.0471975511965976" upper="1.7453292519943295" effort="0" velocity="0"/></joint>
  <joint name="S_knee_pitch" type="revolute"><parent link="S_thigh"/><child link="S_tibia"/><origin xyz="0 0 -0.45"/>
    <axis xyz="0 1 0"/><limit lower="0" upper="2.2689280275926285" effort="0" velocity="0"/></joint>
  <joint name="S_ankle_pitch" type="revolute"><parent link="S_tibia"/><child link="S_foot"/><origin xyz="0 0 -0.45"/>
    <axis xyz="0 -1 0"/><limit lower="-0.6981317007977318" upper="0.6981317007977318" effort="0" velocity="0"/></joint>
)";

std::string ReplaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

std::string Number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// The URDF twin: the mast's quaternion as roll, pitch, yaw and its first anchor
// moved into the pelvis frame (the mast's origin + its rotation of the anchor).
std::string TwinUrdf() {
  const Eigen::Quaterniond q(0.9689124217106447, 0.04786268954660339, -0.1005403300, 0.2190535140);
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  const Vec3 rpy(std::atan2(R(2, 1), R(2, 2)), -std::asin(R(2, 0)), std::atan2(R(1, 0), R(0, 0)));
  const Vec3 anchor = Vec3(-0.05, 0, 0.12) + R * Vec3(0.01, 0, 0.02);
  std::string urdf = ReplaceAll(kUrdf, "%MAST_RPY%", Number(rpy.x()) + " " + Number(rpy.y()) + " " + Number(rpy.z()));
  urdf = ReplaceAll(urdf, "%MAST_YAW_XYZ%", Number(anchor.x()) + " " + Number(anchor.y()) + " " + Number(anchor.z()));
  urdf = ReplaceAll(urdf, "%LEG:left:0.1%", ReplaceAll(ReplaceAll(kUrdfLeg, "S_", "left_"), " Y ", " 0.1 "));
  return ReplaceAll(urdf, "%LEG:right:-0.1%", ReplaceAll(ReplaceAll(kUrdfLeg, "S_", "right_"), " Y ", " -0.1 "));
}

class MjcfModelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshDir("mjcf");
    WriteText(dir_ / "twin.xml", testing::MjcfTwin());
    WriteText(dir_ / "twin.urdf", TwinUrdf());
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(MjcfModelTest, TheMjcfAndItsUrdfTwinHaveTheSameLinksJointsAndLimits) {
  const RobotModel mjcf = RobotModel::FromFile((dir_ / "twin.xml").string());
  const RobotModel urdf = RobotModel::FromFile((dir_ / "twin.urdf").string());
  ASSERT_EQ(mjcf.link_count(), urdf.link_count());
  ASSERT_EQ(mjcf.joint_count(), urdf.joint_count());
  EXPECT_EQ(mjcf.link_name(mjcf.root_link()), "pelvis");
  for (int j = 0; j < urdf.joint_count(); ++j) {
    const RobotJoint& u = urdf.joint(j);
    const int k = mjcf.JointIndex(u.name);
    ASSERT_GE(k, 0) << u.name;
    const RobotJoint& m = mjcf.joint(k);
    EXPECT_EQ(m.type, u.type) << u.name;
    EXPECT_EQ(m.has_limits, u.has_limits) << u.name;
    EXPECT_NEAR(m.lower, u.lower, 1e-12) << u.name;  // MJCF degrees, compiled to radians
    EXPECT_NEAR(m.upper, u.upper, 1e-12) << u.name;
    EXPECT_EQ(mjcf.link_name(m.child_link), urdf.link_name(u.child_link)) << u.name;
  }
}

TEST_F(MjcfModelTest, ForwardKinematicsAgreesWithTheUrdfTwinTo1e9Metres) {
  const RobotModel mjcf = RobotModel::FromFile((dir_ / "twin.xml").string());
  const RobotModel urdf = RobotModel::FromFile((dir_ / "twin.urdf").string());
  Pose X_WRoot = Pose::Identity();
  X_WRoot.linear() = Eigen::AngleAxisd(0.4, Vec3(0.2, -0.5, 1).normalized()).toRotationMatrix();
  X_WRoot.translation() = Vec3(1.5, -0.3, 0.97);
  // joint values spread over each joint's range (or ±2 rad), three sets
  for (const double s : {0.0, 0.37, -0.81}) {
    std::vector<double> q_urdf(urdf.joint_count(), 0.0), q_mjcf(mjcf.joint_count(), 0.0);
    for (int j = 0; j < urdf.joint_count(); ++j) {
      const RobotJoint& u = urdf.joint(j);
      const double mid = u.has_limits ? 0.5 * (u.lower + u.upper) : 0.0;
      const double half = u.has_limits ? 0.5 * (u.upper - u.lower) : 2.0;
      q_urdf[j] = mid + s * half * std::cos(1.7 * j);
      q_mjcf[mjcf.JointIndex(u.name)] = q_urdf[j];
    }
    const std::vector<Pose> X_WL_urdf = urdf.ForwardKinematics(X_WRoot, q_urdf);
    const std::vector<Pose> X_WL_mjcf = mjcf.ForwardKinematics(X_WRoot, q_mjcf);
    for (int l = 0; l < urdf.link_count(); ++l) {
      const int k = mjcf.LinkIndex(urdf.link_name(l));
      ASSERT_GE(k, 0) << urdf.link_name(l);
      EXPECT_LT((X_WL_mjcf[k].translation() - X_WL_urdf[l].translation()).norm(), 1e-9) << urdf.link_name(l) << " s=" << s;
      EXPECT_LT((X_WL_mjcf[k].linear() - X_WL_urdf[l].linear()).norm(), 1e-9) << urdf.link_name(l) << " s=" << s;
    }
  }
}

TEST_F(MjcfModelTest, TheGaitsLegMapWalksItTheSameAndASensorOnTheSiteReadsTheSame) {
  const std::string scenario = R"(proxsim: 1
seed: 3
duration_s: 3
rate_hz: 50
scene:
  builtin: empty
  objects:
    - {name: floor, plane: {}, ground: true}
    - {name: block, box: {size_m: [0.3, 1.0, 0.4]}, pose: {xyz_m: [1.6, 0, 0.2]}}
robot:
  model: MODEL
  path: {waypoints_m: [[0, 0], [3, 0]]}
  gait: {period_s: 1.2}
sensors:
  - {name: shin, type: laser, link: left_shin_sensor}
)";
  std::map<std::string, testing::Csv> poses, readings;
  for (const std::string model : {"twin.xml", "twin.urdf"}) {
    WriteText(dir_ / ("walk_" + model + ".yaml"), ReplaceAll(scenario, "MODEL", model));
    const fs::path out = dir_ / ("out_" + model);
    const auto result = RunProxsim("run " + (dir_ / ("walk_" + model + ".yaml")).string() + " --no-report --out " + out.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    poses[model] = ReadCsv(out / "poses.csv");
    readings[model] = ReadCsv(out / "readings.csv");
  }
  // the same links at the same places, sample by sample; the same readings
  const auto& a = poses["twin.xml"].rows;
  const auto& b = poses["twin.urdf"].rows;
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 100u);
  std::map<std::pair<std::string, std::string>, const std::map<std::string, std::string>*> by_time_link;
  for (const auto& row : b) by_time_link[{row.at("t_s"), row.at("link")}] = &row;
  double worst_m = 0;
  for (const auto& row : a) {
    const auto other = by_time_link.find({row.at("t_s"), row.at("link")});
    ASSERT_NE(other, by_time_link.end()) << row.at("link");
    for (const char* c : {"x", "y", "z"}) worst_m = std::max(worst_m, std::abs(std::stod(row.at(c)) - std::stod(other->second->at(c))));
  }
  EXPECT_LT(worst_m, 1e-9);
  const double walked_x = std::stod(a.back().at("x"));
  EXPECT_GT(walked_x, 0.5) << "it walked";
  const auto& ra = readings["twin.xml"].rows;
  const auto& rb = readings["twin.urdf"].rows;
  ASSERT_EQ(ra.size(), rb.size());
  int detections = 0;
  for (std::size_t k = 0; k < ra.size(); ++k) {
    EXPECT_EQ(ra[k].at("status"), rb[k].at("status")) << k;
    EXPECT_NEAR(std::stod(ra[k].at("d_m")), std::stod(rb[k].at("d_m")), 1e-6) << k;
    detections += ra[k].at("detected") == "1";
  }
  EXPECT_GT(detections, 0);
}

// One body per geom type, each at x = 0 on its own height; a ray along +x from
// x = −1 at the geom's height hits it at its closed-form distance.
TEST_F(MjcfModelTest, EachGeomTypeIsHitAtItsClosedFormDistance) {
  WriteText(dir_ / "geoms.xml", R"(<mujoco model="geoms">
  <asset>
    <mesh name="tetra" vertex="0 0 0  0.2 0 0  0 0.2 0  0 0 0.2"/>
  </asset>
  <worldbody>
    <body name="base">
      <freejoint/>
      <geom name="box" type="box" size="0.1 0.2 0.05" pos="0 0 0"/>
      <geom name="sphere" type="sphere" size="0.15" pos="0 0 1"/>
      <geom name="capsule" type="capsule" size="0.05 0.2" pos="0 0 2" euler="90 0 0"/>
      <geom name="capsule_end" type="capsule" size="0.05 0.2" pos="0 0 3" euler="0 90 0"/>
      <geom name="cylinder" type="cylinder" size="0.12 0.3" pos="0 0 4"/>
      <geom name="ellipsoid" type="ellipsoid" size="0.3 0.1 0.2" pos="0 0 5"/>
      <geom name="ellipsoid_off" type="ellipsoid" size="0.3 0.1 0.2" pos="0 0 6"/>
      <geom name="mesh" type="mesh" mesh="tetra" pos="0 0 7"/>
      <geom name="hidden" type="sphere" size="0.5" pos="0 0 8" group="3"/>
    </body>
  </worldbody>
</mujoco>
)");
  const RobotModel model = RobotModel::FromFile((dir_ / "geoms.xml").string());
  RayCaster caster;
  RobotInScene robot(model, caster, 0);
  RobotState state;
  state.q.assign(model.joint_count(), 0.0);
  robot.Place(state);
  caster.Commit();
  const auto cast = [&](const Vec3& from, const Vec3& along) {
    const Ray ray{.origin_W = from.cast<float>(), .direction_W = along.normalized().cast<float>(), .max_range_m = 10.0f};
    Hit hit;
    caster.Cast(std::span(&ray, 1), std::span(&hit, 1));
    return static_cast<double>(hit.distance_m);
  };
  const Vec3 x = Vec3::UnitX();
  EXPECT_NEAR(cast(Vec3(-1, 0.05, 0.01), x), 1 - 0.1, 1e-6);                                  // box: half extent 0.1
  EXPECT_NEAR(cast(Vec3(-1, 0.06, 1), x), 1 - std::sqrt(0.15 * 0.15 - 0.06 * 0.06), 1e-6);   // sphere
  // a capsule along y (euler 90 about x): its side at x = −0.05, its round end at y = 0.25
  EXPECT_NEAR(cast(Vec3(-1, 0.1, 2), x), 1 - 0.05, 1e-6);
  EXPECT_NEAR(cast(Vec3(0.02, 1, 2), -Vec3::UnitY()), 1 - (0.2 + std::sqrt(0.05 * 0.05 - 0.02 * 0.02)), 1e-6);
  // a capsule along x (euler 90 about y): its round end towards the ray, 0.25 from its centre
  EXPECT_NEAR(cast(Vec3(-1, 0.03, 3), x), 1 - (0.2 + std::sqrt(0.05 * 0.05 - 0.03 * 0.03)), 1e-6);
  EXPECT_NEAR(cast(Vec3(-1, 0.05, 4.1), x), 1 - std::sqrt(0.12 * 0.12 - 0.05 * 0.05), 1e-6);  // cylinder side
  // an ellipsoid: on its axis the ray meets a vertex of the mesh (exact); off axis, the mesh's face lies
  // between the ellipsoid and the same shrunk by the mesh's depth (closed forms both)
  EXPECT_NEAR(cast(Vec3(-1, 0, 5), x), 1 - 0.3, 1e-6);
  const double y = 0.05, z = 0.07;
  const auto surface_distance = [&](double scale) {
    return 1 - 0.3 * std::sqrt(scale * scale - (y / 0.1) * (y / 0.1) - (z / 0.2) * (z / 0.2));
  };
  const double off_axis = cast(Vec3(-1, y, 6 + z), x);
  EXPECT_GE(off_axis, surface_distance(1.0) - 1e-6);
  EXPECT_LE(off_axis, surface_distance(1.0 - kEllipsoidMeshDepth) + 1e-6);
  // the mesh: a tetrahedron's face x = 0 at (y, z) inside it
  EXPECT_NEAR(cast(Vec3(-1, 0.05, 7.05), x), 1.0, 1e-5);
  // group 3 is left out when group 0 is chosen
  EXPECT_NEAR(cast(Vec3(-1, 0, 8), x), 1 - 0.5, 1e-6);
  const RobotModel group0 = RobotModel::FromMjcfFile((dir_ / "geoms.xml").string(), {.geom_group = 0});
  EXPECT_EQ(group0.link(0).shapes.size(), model.link(0).shapes.size() - 1);
}

TEST_F(MjcfModelTest, WhatProxsimCannotFollowIsNamed) {
  const auto error_of = [&](const std::string& name, const std::string& body) {
    WriteText(dir_ / name, "<mujoco><worldbody>" + body + "</worldbody></mujoco>");
    return ErrorOf([&] { RobotModel::FromFile((dir_ / name).string()); });
  };
  EXPECT_NE(error_of("ball.xml", R"(<body name="b"><freejoint/><geom size="0.1"/><body name="c"><joint name="shoulder" type="ball"/><geom size="0.1"/></body></body>)")
                .find("ball joint 'shoulder'"),
            std::string::npos);
  EXPECT_NE(error_of("plane.xml", R"(<body name="b"><geom name="deck" type="plane" size="1 1 0.1"/></body>)").find("geom 'deck' of body 'b' is a plane"),
            std::string::npos);
  // (a geom of the world body is not the robot's: a scene's, tests/model_scene_test.cc)
  EXPECT_EQ(error_of("world.xml", R"(<geom name="floor" type="plane" size="1 1 0.1"/><body name="b"><geom size="0.1"/></body>)"), "");
  EXPECT_NE(error_of("two.xml", R"(<body name="a"><geom size="0.1"/></body><body name="b"><geom size="0.1"/></body>)").find("found 2: 'a', 'b'"),
            std::string::npos);
  EXPECT_NE(error_of("hinge_root.xml", R"(<body name="a"><joint name="swing"/><geom size="0.1"/></body>)").find("joint 'swing' attaches the root body 'a'"),
            std::string::npos);
  // a joint coupling that holds at the reference pose is kept (a gripper's fingers: TALOS's); one that
  // does not, and any other equality (a closed chain), is named
  const auto equality = [&](const std::string& name, const std::string& refs, const std::string& eq) {
    WriteText(dir_ / name, R"(<mujoco><worldbody><body name="a"><freejoint/><geom size="0.1"/>
      <body name="b"><joint name="j1" )" + refs + R"(/><geom size="0.1"/></body><body name="c"><joint name="j2"/><geom size="0.1"/></body>
      </body></worldbody><equality>)" + eq + "</equality></mujoco>");
    return ErrorOf([&] { RobotModel::FromFile((dir_ / name).string()); });
  };
  EXPECT_EQ(equality("eq_mirror.xml", "", R"(<joint name="mirror" joint1="j1" joint2="j2" polycoef="0 -1 0 0 0"/>)"), "");
  EXPECT_NE(equality("eq_offset.xml", "", R"(<joint name="offset" joint1="j1" joint2="j2" polycoef="0.2 1 0 0 0"/>)")
                .find("joint coupling 'offset' (joint 'j1') does not hold at the reference pose"),
            std::string::npos);
  EXPECT_NE(equality("eq_connect.xml", "", R"(<connect name="loop" body1="b" body2="c" anchor="0 0 0"/>)")
                .find("equality constraint 'loop' is not supported"),
            std::string::npos);
  // MuJoCo's own refusal, with its reason
  WriteText(dir_ / "bad.xml", "<mujoco><worldbody><body><bogus/></body></worldbody></mujoco>");
  const std::string bad = ErrorOf([&] { RobotModel::FromFile((dir_ / "bad.xml").string()); });
  EXPECT_NE(bad.find("MuJoCo " PROXSIM_MUJOCO_VERSION " could not load the MJCF"), std::string::npos) << bad;
  EXPECT_NE(bad.find("bogus"), std::string::npos) << bad;
  // and through the CLI: exit 2, named
  WriteText(dir_ / "ball_run.yaml", "proxsim: 1\nduration_s: 1\nrate_hz: 10\nrobot: {model: ball.xml}\nsensors: []\n");
  const auto result = RunProxsim("validate " + (dir_ / "ball_run.yaml").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("ball joint 'shoulder'"), std::string::npos) << result.output;
  WriteText(dir_ / "group.yaml", "proxsim: 1\nduration_s: 1\nrate_hz: 10\nrobot: {model: twin.xml, geom_group: 9}\nsensors: []\n");
  const auto group = RunProxsim("validate " + (dir_ / "group.yaml").string());
  EXPECT_EQ(group.exit_code, 2) << group.output;
  EXPECT_NE(group.output.find("robot.geom_group"), std::string::npos) << group.output;
  EXPECT_NE(group.output.find("expected a whole number in [0, 5] (a MuJoCo geom group), got 9"), std::string::npos) << group.output;
}

}  // namespace
}  // namespace proxsim
