// Meshes on robot links, on small robots whose URDF and STL files the tests
// write themselves: a ray against a cube link at a known joint angle gives the
// closed-form distance and normal; robot.geometry switches what is hit
// (visual cube or collision tetrahedron); a file is read once however many
// links use it; package:// URIs are found in the documented order, each step
// on its own; a mesh that cannot be found is refused with a message naming
// the URDF, the link, the URI and every folder searched.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "cli_helpers.h"
#include "input_error_helpers.h"
#include "stl_files.h"

#include "raycast/ray_caster.h"
#include "robot/mesh_uri.h"
#include "robot/robot_model.h"
#include "scene/mesh_loader.h"
#include "sim/robot_in_scene.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::ErrorOf;

constexpr double kHalf_m = 0.1;   // the cube's half side
constexpr double kTetra_m = 0.2;  // the tetrahedron's edge along the axes

// base ── spin (revolute about z, 1 m ahead) ── block: a cube mesh (visual,
// binary STL with a "solid" header, relative path) and a tetrahedron mesh
// (collision, ASCII STL, package:// URI), both 0.5 m up in the block's frame;
// `bare` has collision geometry only; `twin` and `big` use the cube's file
// again, `big` at twice the size.
constexpr const char* kMeshyUrdf = R"(<?xml version="1.0"?>
<robot name="meshy">
  <link name="base"/>
  <link name="block">
    <visual><origin xyz="0 0 0.5"/><geometry><mesh filename="../meshes/cube.stl"/></geometry></visual>
    <collision><origin xyz="0 0 0.5"/><geometry><mesh filename="package://meshy/meshes/tetra.stl"/></geometry></collision>
  </link>
  <link name="bare"><collision><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="twin"><visual><geometry><mesh filename="../meshes/cube.stl" scale="1 1 1"/></geometry></visual></link>
  <link name="big"><visual><geometry><mesh filename="../meshes/cube.stl" scale="2 2 2"/></geometry></visual></link>
  <joint name="spin" type="revolute"><parent link="base"/><child link="block"/><origin xyz="1 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="bare_joint" type="fixed"><parent link="base"/><child link="bare"/><origin xyz="0 5 0"/></joint>
  <joint name="twin_joint" type="fixed"><parent link="base"/><child link="twin"/><origin xyz="0 -5 0"/></joint>
  <joint name="big_joint" type="fixed"><parent link="base"/><child link="big"/><origin xyz="0 -9 0"/></joint>
</robot>
)";

// The package folder `meshy/` (urdf/, meshes/, package.xml) under `root`; returns the URDF's path.
fs::path WriteMeshyPackage(const fs::path& root) {
  const fs::path package = root / "meshy";
  testing::WriteBinaryStl(package / "meshes" / "cube.stl", testing::CubeTriangles(kHalf_m));
  testing::WriteAsciiStl(package / "meshes" / "tetra.stl", testing::TetrahedronTriangles(kTetra_m));
  testing::WriteText(package / "package.xml", "<package format=\"2\">\n  <name>meshy</name>\n</package>\n");
  testing::WriteText(package / "urdf" / "meshy.urdf", kMeshyUrdf);
  return package / "urdf" / "meshy.urdf";
}

// One ray from p_W along d_W against the robot posed with `spin` at q_rad.
Hit CastAtRobot(const RobotModel& model, double q_rad, const Vec3& p_W, const Vec3& d_W) {
  RayCaster caster;
  constexpr std::int32_t kFirstId = 100;
  RobotInScene robot(model, caster, kFirstId);
  RobotState state;
  state.q.assign(model.joint_count(), 0.0);
  state.q[model.JointIndex("spin")] = q_rad;
  robot.Place(state);
  caster.Commit();
  const Ray ray{.origin_W = p_W.cast<float>(), .direction_W = d_W.normalized().cast<float>(), .max_range_m = 10.0f};
  Hit hit;
  caster.Cast(std::span(&ray, 1), std::span(&hit, 1));
  return hit;
}

// A guard that sets ROS_PACKAGE_PATH (or unsets it) for one test and puts it back.
class RosPackagePath {
 public:
  explicit RosPackagePath(const std::optional<std::string>& value) {
    if (const char* old = std::getenv("ROS_PACKAGE_PATH")) old_ = old;
    if (value) setenv("ROS_PACKAGE_PATH", value->c_str(), 1);
    else unsetenv("ROS_PACKAGE_PATH");
  }
  ~RosPackagePath() {
    if (old_) setenv("ROS_PACKAGE_PATH", old_->c_str(), 1);
    else unsetenv("ROS_PACKAGE_PATH");
  }

 private:
  std::optional<std::string> old_;
};

TEST(RobotMeshTest, RayAgainstACubeLinkMovedByItsJointMatchesTheClosedForm) {
  const fs::path dir = testing::FreshDir("robot_mesh_ray");
  const RobotModel model = RobotModel::FromUrdfFile(WriteMeshyPackage(dir).string());
  ASSERT_TRUE(std::holds_alternative<Mesh>(model.link(model.LinkIndex("block")).shapes.at(0).shape));
  // a ray along +x through the cube's centre (1, 0, 0.5): with the block
  // turned by q about z, it meets the turned −x face, whose plane lies kHalf_m
  // from the centre along n = (−cos q, −sin q, 0): at d = 1 − kHalf_m / cos q
  for (const double q_deg : {0.0, 20.0, 30.0, -35.0}) {
    SCOPED_TRACE(q_deg);
    const double q = DegToRad(q_deg);
    const Hit hit = CastAtRobot(model, q, Vec3(0, 0, 0.5), Vec3::UnitX());
    ASSERT_TRUE(hit.is_hit());
    EXPECT_NEAR(hit.distance_m, 1 - kHalf_m / std::cos(q), 1e-5);
    const Vec3 n_expected(-std::cos(q), -std::sin(q), 0);
    EXPECT_NEAR(std::abs(hit.normal_W.cast<double>().dot(n_expected)), 1.0, 1e-5);
    EXPECT_EQ(hit.object_id, 100 + model.LinkIndex("block"));
  }
  fs::remove_all(dir);
}

TEST(RobotMeshTest, GeometryChoiceSwitchesWhatIsHitAndFallsBackToTheOtherKind) {
  const fs::path dir = testing::FreshDir("robot_mesh_geometry");
  const fs::path urdf = WriteMeshyPackage(dir);
  const RobotModel visual = RobotModel::FromUrdfFile(urdf.string());
  const RobotModel collision =
      RobotModel::FromUrdfFile(urdf.string(), {.geometry = LinkGeometryKind::kCollision, .package_paths = {}});
  // a ray along +x, 2 cm left of and 5 cm above the centre line: the cube's
  // −x face is at x = 1 − kHalf_m; the tetrahedron's x = 0 face (it spans
  // y, z ≥ 0 from its corner at the block's origin) at x = 1
  const Vec3 p_W(0, 0.02, 0.55);
  const Hit on_cube = CastAtRobot(visual, 0.0, p_W, Vec3::UnitX());
  const Hit on_tetra = CastAtRobot(collision, 0.0, p_W, Vec3::UnitX());
  EXPECT_NEAR(on_cube.distance_m, 1 - kHalf_m, 1e-5);
  EXPECT_NEAR(on_tetra.distance_m, 1.0, 1e-5);
  // a link with collision geometry only keeps it when visual is asked for, and the other way round
  const int bare = visual.LinkIndex("bare"), twin = collision.LinkIndex("twin");
  EXPECT_EQ(visual.link(bare).shapes_kind, LinkGeometryKind::kCollision);
  EXPECT_TRUE(std::holds_alternative<Sphere>(visual.link(bare).shapes.at(0).shape));
  EXPECT_EQ(collision.link(twin).shapes_kind, LinkGeometryKind::kVisual);
  EXPECT_EQ(visual.link(visual.LinkIndex("block")).shapes_kind, LinkGeometryKind::kVisual);
  EXPECT_EQ(collision.link(collision.LinkIndex("block")).shapes_kind, LinkGeometryKind::kCollision);
  fs::remove_all(dir);
}

TEST(RobotMeshTest, AFileIsReadOnceHoweverManyLinksUseItAndScaledCopiesShareIt) {
  const fs::path dir = testing::FreshDir("robot_mesh_once");
  const RobotModel model = RobotModel::FromUrdfFile(WriteMeshyPackage(dir).string());
  const auto data = [&](const char* link) { return std::get<Mesh>(model.link(model.LinkIndex(link)).shapes.at(0).shape).data; };
  EXPECT_EQ(data("block"), data("twin")) << "the same file at the same scale is one mesh in memory";
  EXPECT_NE(data("block"), data("big"));
  EXPECT_EQ(model.MeshFileCount(), 1u) << "visual geometry: cube.stl only, read once";
  EXPECT_EQ(model.MeshTriangleCount(), 36u);
  // the scale multiplies the file's vertices
  float largest = 0;
  for (const Vec3f& v : data("big")->vertices_O) largest = std::max(largest, v.cwiseAbs().maxCoeff());
  EXPECT_FLOAT_EQ(largest, static_cast<float>(2 * kHalf_m));
  fs::remove_all(dir);
}

TEST(RobotMeshTest, BinaryStlWhoseHeaderStartsWithSolidAndAsciiStlBothLoad) {
  const fs::path dir = testing::FreshDir("robot_mesh_stl");
  testing::WriteBinaryStl(dir / "binary.stl", testing::CubeTriangles(kHalf_m), "solid cube exported by a CAD tool");
  testing::WriteAsciiStl(dir / "ascii.stl", testing::TetrahedronTriangles(kTetra_m));
  EXPECT_EQ(LoadMeshFile((dir / "binary.stl").string(), Vec3::Ones())->triangles.size(), 12u);
  EXPECT_EQ(LoadMeshFile((dir / "binary.stl").string(), Vec3::Ones())->vertices_O.size(), 8u);
  EXPECT_EQ(LoadMeshFile((dir / "ascii.stl").string(), Vec3::Ones())->triangles.size(), 4u);
  fs::remove_all(dir);
}

// package://meshy/meshes/cube.stl, looked for in robot.package_paths, then
// ROS_PACKAGE_PATH, then the URDF's ancestors: each step on its own.
TEST(RobotMeshTest, PackageUrisAreFoundInTheDocumentedOrder) {
  const fs::path dir = testing::FreshDir("robot_mesh_package");
  const std::string uri = "package://meshy/meshes/cube.stl";
  const auto cube = testing::CubeTriangles(kHalf_m);
  // three copies of the package: under a package_paths folder (as a subfolder
  // named meshy), under a ROS_PACKAGE_PATH folder (a folder of another name
  // whose package.xml says meshy), and the URDF's own package (an ancestor)
  testing::WriteBinaryStl(dir / "paths" / "meshy" / "meshes" / "cube.stl", cube);
  testing::WriteBinaryStl(dir / "ros" / "meshy_src" / "meshes" / "cube.stl", cube);
  testing::WriteText(dir / "ros" / "meshy_src" / "package.xml", "<package><name> meshy </name></package>");
  const fs::path urdf_dir = dir / "ws" / "meshy" / "urdf";
  testing::WriteBinaryStl(dir / "ws" / "meshy" / "meshes" / "cube.stl", cube);
  const std::vector<std::string> paths = {(dir / "paths").string()};

  {
    const RosPackagePath ros((dir / "ros").string());
    // 1. robot.package_paths first
    EXPECT_EQ(ResolveMeshUri(uri, urdf_dir, paths).path, dir / "paths" / "meshy" / "meshes" / "cube.stl");
    // 2. then ROS_PACKAGE_PATH
    EXPECT_EQ(ResolveMeshUri(uri, urdf_dir, {}).path, dir / "ros" / "meshy_src" / "meshes" / "cube.stl");
    // a package_paths folder holding the package without the file does not stop the search
    testing::WriteText(dir / "stale" / "meshy" / "package.xml", "<package><name>meshy</name></package>");
    EXPECT_EQ(ResolveMeshUri(uri, urdf_dir, std::vector{(dir / "stale").string()}).path,
              dir / "ros" / "meshy_src" / "meshes" / "cube.stl");
  }
  {
    const RosPackagePath ros(std::nullopt);
    // 3. then the URDF's ancestors: a folder named meshy
    EXPECT_EQ(ResolveMeshUri(uri, urdf_dir, {}).path, dir / "ws" / "meshy" / "meshes" / "cube.stl");
    // or one whose package.xml names it, whatever the folder is called
    const fs::path renamed = dir / "checkout" / "meshy-main";
    testing::WriteBinaryStl(renamed / "meshes" / "cube.stl", cube);
    testing::WriteText(renamed / "package.xml", "<package format=\"3\">\n<name>meshy</name>\n</package>");
    EXPECT_EQ(ResolveMeshUri(uri, renamed / "urdf", {}).path, renamed / "meshes" / "cube.stl");
    // a package_paths folder may be the package itself
    EXPECT_EQ(ResolveMeshUri(uri, dir, std::vector{(dir / "paths" / "meshy").string()}).path,
              dir / "paths" / "meshy" / "meshes" / "cube.stl");
    // nowhere: every place searched is named
    const MeshLookup none = ResolveMeshUri("package://nothere/m.stl", urdf_dir, paths);
    EXPECT_FALSE(none.path);
    for (const std::string& named : {std::string("package 'nothere' not found"), "robot.package_paths: " + paths[0],
                                     std::string("ROS_PACKAGE_PATH: none"), urdf_dir.lexically_normal().string(),
                                     (dir / "ws").lexically_normal().string()})
      EXPECT_NE(none.problem.find(named), std::string::npos) << named << " in: " << none.problem;
  }
  fs::remove_all(dir);
}

TEST(RobotMeshTest, PlainAndFileUrisAndTheirFailures) {
  const fs::path dir = testing::FreshDir("robot_mesh_uri");
  testing::WriteBinaryStl(dir / "meshes" / "cube.stl", testing::CubeTriangles(kHalf_m));
  EXPECT_EQ(ResolveMeshUri("meshes/cube.stl", dir, {}).path, dir / "meshes" / "cube.stl");
  EXPECT_EQ(ResolveMeshUri((dir / "meshes" / "cube.stl").string(), "/elsewhere", {}).path, dir / "meshes" / "cube.stl");
  EXPECT_EQ(ResolveMeshUri("file://" + (dir / "meshes" / "cube.stl").string(), "/elsewhere", {}).path,
            dir / "meshes" / "cube.stl");
  EXPECT_NE(ResolveMeshUri("meshes/none.stl", dir, {}).problem.find("does not exist"), std::string::npos);
  EXPECT_NE(ResolveMeshUri("meshes", dir, {}).problem.find("is not a regular file"), std::string::npos);
  EXPECT_NE(ResolveMeshUri("/dev/zero", dir, {}).problem.find("is not a regular file"), std::string::npos);
  EXPECT_NE(ResolveMeshUri("http://example.com/m.stl", dir, {}).problem.find("unsupported URI scheme 'http://'"),
            std::string::npos);
  EXPECT_NE(ResolveMeshUri("package://meshy", dir, {}).problem.find("package://PACKAGE/path"), std::string::npos);
  fs::remove_all(dir);
}

TEST(RobotMeshTest, AMissingOrUnreadableMeshNamesTheUrdfTheLinkTheUriAndTheFoldersSearched) {
  const fs::path dir = testing::FreshDir("robot_mesh_missing");
  const RosPackagePath ros((dir / "ros_a").string() + ":" + (dir / "ros_b").string());
  const fs::path urdf = dir / "robot" / "urdf" / "r.urdf";
  testing::WriteText(dir / "robot" / "meshes" / "broken.stl", "solid broken\n facet normal 0 0 1\n");
  testing::WriteText(urdf, R"(<robot name="r">
    <link name="base"><visual><geometry><mesh filename="package://gone/meshes/base.stl"/></geometry></visual></link>
    <link name="arm"><visual><geometry><mesh filename="../meshes/broken.stl"/></geometry></visual></link>
    <joint name="j" type="fixed"><parent link="base"/><child link="arm"/></joint></robot>)");
  const std::string message = ErrorOf([&] {
    RobotModel::FromUrdfFile(urdf.string(), {.geometry = LinkGeometryKind::kVisual, .package_paths = {(dir / "pp").string()}});
  });
  for (const std::string& named :
       {urdf.string() + ": link 'base' (visual): mesh 'package://gone/meshes/base.stl' not found: package 'gone' not found",
        "robot.package_paths: " + (dir / "pp").string(),
        "ROS_PACKAGE_PATH: " + (dir / "ros_a").string() + ", " + (dir / "ros_b").string(),
        "the URDF's folder and its ancestors: " + (dir / "robot" / "urdf").lexically_normal().string() + ", " +
            (dir / "robot").lexically_normal().string(),
        urdf.string() + ": link 'arm' (visual): mesh '../meshes/broken.stl': "})
    EXPECT_NE(message.find(named), std::string::npos) << named << "\nin:\n" << message;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace proxsim
