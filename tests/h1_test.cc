// A real humanoid: the Unitree H1, Unitree's description (URDF and 21 binary
// STL meshes, not part of this repository) read from beside it in
// ../shared/robots/h1_description, never copied into it;
// every test here is skipped, saying so, when that folder is absent).
// It loads with every mesh read once; walked by the shipped example
// scenario's leg map, every link is where forward kinematics computed here
// from the URDF's joint origins puts it, a loaded foot's contact point slips
// less than 1 mm, nothing goes below the floor by more than 1 mm, and the
// pelvis advances one stride per cycle within 2 %; a sensor on one shin
// reads its other shin as `self`, at the mesh's distance with visual
// geometry and at the cylinder's closed-form one with collision geometry;
// the example scenario runs end to end and stops before the obstacle.
#include <gtest/gtest.h>

#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "cli_helpers.h"

#include "gait/gait_walker.h"
#include "scenario/scenario.h"
#include "robot/robot_model.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;

using testing::kH1Dir;
const fs::path kH1Example = fs::path(PROXSIM_SOURCE_DIR) / "data" / "scenarios" / "h1_dining_room.yaml";

#define SKIP_WITHOUT_H1()                                                                                    \
  if (!fs::is_regular_file(kH1Dir / "urdf" / "h1.urdf"))                                                     \
  GTEST_SKIP() << "skipped: the Unitree H1 is not at " << kH1Dir.lexically_normal().string()                 \
               << " (the H1 tests read ../shared/robots/h1_description from beside the project)"

// The example scenario's robot section, with its package paths and leg map.
RobotConfig H1Config() { return LoadScenarioFile(kH1Example.string()).robot.value(); }

// Link poses by forward kinematics written here from urdfdom's joint origins
// and axes: X_WC = X_WP·origin·Rot(axis, q) (revolute) for every joint.
std::map<std::string, Pose> UrdfForwardKinematics(const urdf::ModelInterface& urdf, const RobotModel& model,
                                                  const Pose& X_WRoot, std::span<const double> q) {
  std::map<std::string, Pose> X_WL;
  std::vector<urdf::LinkConstSharedPtr> todo = {urdf.getRoot()};
  X_WL[urdf.getRoot()->name] = X_WRoot;
  while (!todo.empty()) {
    const urdf::LinkConstSharedPtr link = todo.back();
    todo.pop_back();
    for (const auto& joint : link->child_joints) {
      const urdf::Pose& o = joint->parent_to_joint_origin_transform;
      Pose X_PJ = Pose::Identity();
      X_PJ.translate(Vec3(o.position.x, o.position.y, o.position.z));
      X_PJ.rotate(Eigen::Quaterniond(o.rotation.w, o.rotation.x, o.rotation.y, o.rotation.z));
      Pose motion = Pose::Identity();
      if (joint->type == urdf::Joint::REVOLUTE || joint->type == urdf::Joint::CONTINUOUS)
        motion.rotate(Eigen::AngleAxisd(q[model.JointIndex(joint->name)],
                                        Vec3(joint->axis.x, joint->axis.y, joint->axis.z).normalized()));
      X_WL[joint->child_link_name] = X_WL.at(link->name) * X_PJ * motion;
      todo.push_back(urdf.getLink(joint->child_link_name));
    }
  }
  return X_WL;
}

// Triangles in a binary STL's header count.
std::uint32_t StlTriangles(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(80);
  std::uint32_t count = 0;
  in.read(reinterpret_cast<char*>(&count), 4);
  return count;
}

TEST(H1Test, LoadsWithEveryMeshReadOnce) {
  SKIP_WITHOUT_H1();
  const RobotConfig config = H1Config();
  const RobotModel visual = RobotModel::FromUrdfFile(config.model, {.geometry = config.geometry, .package_paths = config.package_paths});
  std::uint32_t triangles = 0;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kH1Dir / "meshes")) {
    triangles += StlTriangles(entry.path());
    ++files;
  }
  EXPECT_EQ(visual.link_count(), 25);
  EXPECT_EQ(visual.MeshFileCount(), static_cast<std::size_t>(files));
  EXPECT_EQ(visual.MeshTriangleCount(), triangles);
  // its collision geometry is cylinders, boxes and spheres only
  const RobotModel collision = RobotModel::FromUrdfFile(config.model, {.geometry = LinkGeometryKind::kCollision, .package_paths = {}});
  EXPECT_EQ(collision.MeshFileCount(), 1u) << "logo_link has visual geometry only: its mesh stands in";
  std::printf("[ measured ] H1: %d links, %zu mesh files, %u triangles\n", visual.link_count(), visual.MeshFileCount(), triangles);
}

TEST(H1Test, WalksWithEveryLinkWhereTheUrdfPutsItFeetPlantedAndNothingUnderTheFloor) {
  SKIP_WITHOUT_H1();
  RobotConfig config = H1Config();
  config.strategy.reset();
  GaitWalker walker(RobotModel::FromUrdfFile(config.model, {.geometry = config.geometry, .package_paths = config.package_paths}),
                    config);
  const RobotModel& model = walker.model();
  const BipedLegs& legs = walker.legs();
  std::vector<std::string> messages;
  const urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDFFile(config.model);
  ASSERT_TRUE(urdf);

  // the links' mesh vertices that can come near the floor (legs, feet)
  std::vector<std::vector<Vec3>> low_points_L(model.link_count());
  const std::vector<Pose> X_PL0 = model.ForwardKinematics(Pose::Identity(), std::vector<double>(model.joint_count(), 0.0));
  for (int link = 0; link < model.link_count(); ++link) {
    for (const LinkShape& shape : model.link(link).shapes) {
      const auto* mesh = std::get_if<Mesh>(&shape.shape);
      if (!mesh) continue;
      for (const Vec3f& v : mesh->data->vertices_O) low_points_L[link].push_back(shape.X_LO * v.cast<double>());
    }
    // links whose vertices all stay above the knees' height standing: never near the floor
    double lowest = 1e9;
    for (const Vec3& p : low_points_L[link]) lowest = std::min(lowest, (X_PL0[link] * p).z());
    if (lowest > -0.6) low_points_L[link].clear();
  }

  const GaitCycle cycle = *walker.gait_cycle();
  constexpr double kRate_hz = 100;
  const int cycles = 5;
  double worst_pose_m = 0, pivot_slip_m = 0, toe_slip_m = 0, lowest_m = 1e9;
  std::vector<double> pelvis_x_at_cycle;
  const int samples = static_cast<int>(std::lround(cycles * cycle.period_s * kRate_hz));
  for (int i = 0; i <= samples; ++i) {
    const double t_s = i / kRate_hz;
    const RobotState s = walker.Advance(t_s);
    const std::vector<Pose> X_WL = model.ForwardKinematics(s.X_WP, s.q);
    // every link against the test's own forward kinematics
    const auto expected = UrdfForwardKinematics(*urdf, model, s.X_WP, s.q);
    for (int link = 0; link < model.link_count(); ++link) {
      const Pose& X = expected.at(model.link_name(link));
      worst_pose_m = std::max({worst_pose_m, (X.translation() - X_WL[link].translation()).norm(),
                               (X.linear() - X_WL[link].linear()).norm()});
    }
    // the loaded feet: the stance pivot and, through the double support, the trailing toe
    const StepPlan& plan = walker.current_step();
    const double p = walker.step_phase();
    const LegGeometry& stance = legs.leg(plan.stance);
    const Vec3& p_L_pivot = p < FootFlatPhase() ? stance.p_L_heel : p <= HeelOffPhase() ? stance.p_L_sole : stance.p_L_toe;
    const Vec3 latched = p < FootFlatPhase() ? plan.p_W_heel : plan.X_WF * p_L_pivot;
    pivot_slip_m = std::max(pivot_slip_m, (X_WL[stance.foot_link] * p_L_pivot - latched).norm());
    if (p < kDoubleSupportEnd) {
      const LegGeometry& trailing = legs.leg(plan.swing);
      toe_slip_m = std::max(toe_slip_m, (X_WL[trailing.foot_link] * trailing.p_L_toe - plan.p_W_trailing_toe).norm());
    }
    if (i % 2 == 0)
      for (int link = 0; link < model.link_count(); ++link)
        for (const Vec3& p_L : low_points_L[link]) lowest_m = std::min(lowest_m, (X_WL[link] * p_L).z());
    if (i % static_cast<int>(std::lround(cycle.period_s * kRate_hz)) == 0) pelvis_x_at_cycle.push_back(s.X_WP.translation().x());
  }
  std::printf("[ measured ] H1, stride %.3f m, period %.3f s: link poses vs the test's FK %.2g m, stance pivot slip %.3g mm, "
              "trailing toe slip %.3g mm, lowest mesh vertex %.3g mm\n",
              cycle.stride_m, cycle.period_s, worst_pose_m, 1e3 * pivot_slip_m, 1e3 * toe_slip_m, 1e3 * lowest_m);
  EXPECT_LT(worst_pose_m, 1e-12);
  EXPECT_LT(pivot_slip_m, 1e-3);
  EXPECT_LT(toe_slip_m, 1e-3);
  EXPECT_GT(lowest_m, -1e-3);
  ASSERT_GE(pelvis_x_at_cycle.size(), 4u);
  // one stride per cycle, within 2 % (the first cycle starts from standing)
  for (std::size_t k = 2; k < pelvis_x_at_cycle.size(); ++k) {
    const double advance_m = pelvis_x_at_cycle[k] - pelvis_x_at_cycle[k - 1];
    std::printf("[ measured ] H1 cycle %zu: pelvis advanced %.4f m (stride %.4f m)\n", k, advance_m, cycle.stride_m);
    EXPECT_NEAR(advance_m, cycle.stride_m, 0.02 * cycle.stride_m);
  }
}

// A sensor on the left shin looking right, across at the other shin, 0.2 m
// below the knee and 0.025 m ahead of its axis (the shin's mesh lies ahead of
// it), the H1 standing straight (a one-row trajectory, every joint at 0):
// with visual geometry it reads the knee link's mesh, with collision
// geometry the link's cylinder, radius 0.05 m about the right knee's axis
// 2·0.20286 m away, met 0.025 m off its centre: at 2·0.20286 − 0.06 −
// √(0.05² − 0.025²) m from a sensor 0.06 m right of the left knee's axis (1 cm
// outside its own cylinder). Both are `self` echoes.
TEST(H1Test, ASensorOnOneShinReadsTheOtherShinsRealGeometryAsSelf) {
  SKIP_WITHOUT_H1();
  const fs::path dir = testing::FreshDir("h1_across");
  fs::create_directories(dir);
  std::ofstream(dir / "standing.csv") << "t_s,x_m,y_m,z_m,roll_deg,pitch_deg,yaw_deg\n0,0,0,1.05,0,0,0\n";
  const std::string scenario_text = "proxsim: 1\nduration_s: 0.01\nrate_hz: 100\nscene: {builtin: empty}\nrobot:\n"
                                    "  model: " + (kH1Dir / "urdf" / "h1.urdf").string() + "\n"
                                    "  trajectory: " + (dir / "standing.csv").string() + "\n"
                                    "  geometry: GEOMETRY\n"
                                    "sensors:\n"
                                    "  - {name: across, type: ideal, link: left_knee_link, pose: {xyz_m: [0.025, -0.06, -0.2], rpy_deg: [0, 0, -90]}}\n";
  const auto read = [&](const std::string& geometry) {
    std::string text = scenario_text;
    text.replace(text.find("GEOMETRY"), 8, geometry);
    Simulation sim(LoadScenarioText(text, (dir / "across.yaml").string()));
    const SampleFrame& frame = sim.Step();
    EXPECT_EQ(frame.sensors[0].reading.status, ReadingStatus::kSelf) << geometry;
    if (frame.sensors[0].object_id >= 0)
      EXPECT_EQ(sim.object_name(frame.sensors[0].object_id), "right_knee_link") << geometry;
    return frame.sensors[0].echo.distance_m;
  };
  const double cylinder_m = read("collision");
  const double mesh_m = read("visual");
  std::printf("[ measured ] H1 shin to shin: %.4f m to the mesh, %.4f m to the collision cylinder\n", mesh_m, cylinder_m);
  EXPECT_NEAR(cylinder_m, 2 * 0.20286 - 0.06 - std::sqrt(0.05 * 0.05 - 0.025 * 0.025), 1e-5);
  EXPECT_GT(mesh_m, cylinder_m + 0.015) << "the mesh shin is slimmer than its collision cylinder";
  fs::remove_all(dir);
}

TEST(H1Test, TheExampleScenarioRunsAndStopsBeforeTheObstacle) {
  SKIP_WITHOUT_H1();
  const fs::path out = testing::FreshDir("h1_example");
  const auto result = testing::RunProxsim("run " + kH1Example.string() + " --out " + out.string() + " --no-report");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream file(out / "summary.json");
  const auto summary = nlohmann::json::parse(file);
  const auto& robot = summary.at("robot");
  EXPECT_TRUE(robot.at("stopped").get<bool>());
  EXPECT_GT(robot.at("min_clearance_m").get<double>(), 0.2);
  EXPECT_GT(robot.at("distance_walked_m").get<double>(), 1.0);
  // the stride and period walked: the built-in biped's scaled to the H1's legs
  EXPECT_LT(robot.at("gait").at("stride_m").get<double>(), 0.6);
  EXPECT_TRUE(summary.at("inputs").at("robot").at("gait").at("stride_m").is_null());
  EXPECT_GT(summary.at("sensors").at("laser_left_shin").at("detections_by_object").value("obstacle", 0), 0);
  fs::remove_all(out);
}

}  // namespace
}  // namespace proxsim
