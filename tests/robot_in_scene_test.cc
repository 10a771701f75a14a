// Tests of RobotInScene::ClearanceTo, which skips links and samples that
// cannot come closer than the running minimum using bounds remembered from
// earlier calls. Whatever it skips, its answer must be the brute-force one:
// the least uncapped DistanceToWorld over every surface sample of every link
// (the robot samples its shapes every 2 cm), recomputed here from the public
// API at every step of a walk that passes and turns between objects of every
// kind, and of a robot turning on the spot.
#include "sim/robot_in_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "cli_helpers.h"
#include "sim/make_locomotion.h"
#include "sim/surface_samples.h"

namespace proxsim {
namespace {

// A robot walked by its scenario's locomotion, its bodies placed at each time
struct WalkingRobot {
  WalkingRobot(const RobotConfig& config, RayCaster& caster, std::int32_t first_object_id)
      : locomotion(MakeLocomotion(config, /*rate_hz, unused by a gait:*/ 50.0)), body(locomotion->model(), caster, first_object_id) {}
  void MoveTo(double t_s) { body.Place(locomotion->Advance(t_s)); }
  std::unique_ptr<Locomotion> locomotion;
  RobotInScene body;
};

constexpr std::int32_t kFloorId = 0;

Pose PoseXyzRpyDeg(double x, double y, double z, double roll, double pitch, double yaw) {
  return PoseFromXyzRpy(Vec3(x, y, z), Vec3(DegToRad(roll), DegToRad(pitch), DegToRad(yaw)));
}

// A vertical panel of triangles in its x-z plane, width × height, cells of cell_m.
Mesh Panel(double width_m, double height_m, double cell_m) {
  auto mesh = std::make_shared<TriangleMesh>();
  const int nx = static_cast<int>(std::round(width_m / cell_m)), nz = static_cast<int>(std::round(height_m / cell_m));
  for (int i = 0; i <= nx; ++i) {
    for (int k = 0; k <= nz; ++k) {
      mesh->vertices_O.emplace_back(static_cast<float>(i * cell_m), 0.0f, static_cast<float>(k * cell_m));
    }
  }
  auto vertex = [&](int i, int k) { return static_cast<std::uint32_t>(i * (nz + 1) + k); };
  for (int i = 0; i < nx; ++i) {
    for (int k = 0; k < nz; ++k) {
      mesh->triangles.push_back({vertex(i, k), vertex(i + 1, k), vertex(i + 1, k + 1)});
      mesh->triangles.push_back({vertex(i, k), vertex(i + 1, k + 1), vertex(i, k + 1)});
    }
  }
  Mesh shape;
  shape.data = mesh;
  return shape;
}

// The floor (excluded from the clearance) and, along the first 1.5 m of the
// path, a box and a mesh panel on the left, a sphere and a lying cylinder on
// the right, and a low box the path turns towards.
void AddWorld(RayCaster& caster) {
  caster.AddBody({BodyShape{Plane{}, Pose::Identity(), kFloorId},
                  BodyShape{Box{Vec3(0.4, 0.3, 0.5)}, PoseXyzRpyDeg(0.6, 0.42, 0.25, 0, 0, 10), 1},
                  BodyShape{Sphere{0.15}, PoseXyzRpyDeg(1.1, -0.4, 0.35, 0, 0, 0), 2},
                  BodyShape{Cylinder{0.05, 1.0}, PoseXyzRpyDeg(0.5, -0.33, 0.7, 0, 90, 0), 3},
                  BodyShape{Panel(0.6, 1.2, 0.05), PoseXyzRpyDeg(1.0, 0.38, 0, 0, 0, -5), 4},
                  BodyShape{Box{Vec3(0.3, 0.3, 0.1)}, PoseXyzRpyDeg(1.6, -0.6, 0.05, 0, 0, 30), 5}},
                 BodyKind::kWorld);
}

RobotConfig WalkThatTurns() {
  RobotConfig config;
  config.waypoints_m = {Vec2(0, 0), Vec2(1.0, 0), Vec2(1.6, -0.5)};
  return config;
}

// Every surface sample of every link in W, as the robot takes them.
std::vector<Vec3> SamplePoints_W(const RobotInScene& robot) {
  std::vector<Vec3> points_W;
  for (int link = 0; link < robot.model().link_count(); ++link) {
    for (const LinkShape& shape : robot.model().link(link).shapes) {
      for (const Vec3& p_O : SurfaceSamples_O(shape.shape, 0.02)) {
        points_W.push_back(robot.X_WL(link) * (shape.X_LO * p_O));
      }
    }
  }
  return points_W;
}

double BruteForceClearance(const RobotInScene& robot, const RayCaster& caster,
                           std::span<const std::int32_t> exclude_object_ids) {
  double best_m = std::numeric_limits<double>::infinity();
  for (const Vec3& p_W : SamplePoints_W(robot)) best_m = std::min(best_m, caster.DistanceToWorld(p_W, exclude_object_ids));
  return best_m;
}

// The running minimum, as Simulation keeps it: at every sample the answer is
// the brute force whenever that is below the minimum so far, and never below
// the minimum otherwise; the minimum itself is the brute-force one.
TEST(RobotInSceneTest, RunningMinimumClearanceEqualsTheBruteForceOne) {
  RayCaster caster;
  AddWorld(caster);
  WalkingRobot walking(WalkThatTurns(), caster, 10);
  RobotInScene& robot = walking.body;
  const std::vector<std::int32_t> exclude{kFloorId};
  constexpr double kRate_hz = 100;
  double running_m = std::numeric_limits<double>::infinity(), expected_running_m = running_m;
  int lowered = 0;
  for (int k = 0; k < 300; ++k) {
    walking.MoveTo(k / kRate_hz);
    caster.Commit();
    const double expected_m = BruteForceClearance(robot, caster, exclude);
    const double clearance_m = robot.ClearanceTo(exclude, running_m);
    if (expected_m < running_m) {
      ASSERT_EQ(clearance_m, expected_m) << "sample " << k;
      ++lowered;
    } else {
      ASSERT_GE(clearance_m, running_m) << "sample " << k;
    }
    running_m = std::min(running_m, clearance_m);
    expected_running_m = std::min(expected_running_m, expected_m);
  }
  EXPECT_EQ(running_m, expected_running_m);
  // the walk must come closer now and then, or the skips were never put to the test
  EXPECT_GT(lowered, 5);
  EXPECT_LT(running_m, 0.2);
}

// Without a running minimum every call must be exact, however the bounds left
// by earlier calls let it skip.
TEST(RobotInSceneTest, EveryClearanceWithoutACapEqualsTheBruteForceOne) {
  RayCaster caster;
  AddWorld(caster);
  WalkingRobot walking(WalkThatTurns(), caster, 10);
  RobotInScene& robot = walking.body;
  const std::vector<std::int32_t> exclude{kFloorId};
  double least_m = std::numeric_limits<double>::infinity(), most_m = 0;
  for (int k = 0; k < 150; ++k) {
    walking.MoveTo(k / 50.0);
    caster.Commit();
    const double clearance_m = robot.ClearanceTo(exclude);
    ASSERT_EQ(clearance_m, BruteForceClearance(robot, caster, exclude)) << "sample " << k;
    least_m = std::min(least_m, clearance_m);
    most_m = std::max(most_m, clearance_m);
  }
  EXPECT_GT(most_m - least_m, 0.1) << "the clearance should vary along the walk";
}

// Turning on the spot moves no link centre on the vertical axis, yet the
// corners of the torso sweep towards a box beside it: the bounds must account
// for rotation. (A replayed trajectory: a full turn in 2 s, one hip swinging.)
TEST(RobotInSceneTest, ClearanceOfARobotTurningOnTheSpotEqualsTheBruteForceOne) {
  const auto dir = testing::FreshDir("robot_in_scene");
  std::filesystem::create_directories(dir);
  const auto csv_path = dir / "spin.csv";
  {
    std::ofstream csv(csv_path);
    csv << "t_s,x_m,y_m,z_m,roll_deg,pitch_deg,yaw_deg,left_hip_pitch\n";
    for (int row = 0; row <= 8; ++row) csv << 0.25 * row << ",0,0,0.98,0,0," << 45 * row << "," << (row % 2 ? 30 : -20) << "\n";
  }
  RayCaster caster;
  caster.AddBody({BodyShape{Plane{}, Pose::Identity(), kFloorId},
                  BodyShape{Box{Vec3(0.3, 0.6, 0.6)}, PoseXyzRpyDeg(0.45, 0, 1.4, 0, 0, 0), 1},
                  BodyShape{Sphere{0.1}, PoseXyzRpyDeg(-0.2, -0.5, 0.4, 0, 0, 0), 2}},
                 BodyKind::kWorld);
  RobotConfig config;
  config.trajectory_file = csv_path.string();
  WalkingRobot walking(config, caster, 10);
  RobotInScene& robot = walking.body;
  const std::vector<std::int32_t> exclude{kFloorId};
  double running_m = std::numeric_limits<double>::infinity(), expected_running_m = running_m;
  for (int k = 0; k < 200; ++k) {
    walking.MoveTo(k / 100.0);
    caster.Commit();
    const double expected_m = BruteForceClearance(robot, caster, exclude);
    const double clearance_m = robot.ClearanceTo(exclude, running_m);
    if (expected_m < running_m) {
      ASSERT_EQ(clearance_m, expected_m) << "sample " << k;
    } else {
      ASSERT_GE(clearance_m, running_m) << "sample " << k;
    }
    running_m = std::min(running_m, clearance_m);
    expected_running_m = std::min(expected_running_m, expected_m);
  }
  EXPECT_EQ(running_m, expected_running_m);
  std::filesystem::remove_all(dir);
}

// The bounds hold for one exclude list: with the floor counted the feet touch
// it, and without it again the answer is the floorless one.
TEST(RobotInSceneTest, ClearanceStartsAfreshWhenTheExcludeListChanges) {
  RayCaster caster;
  AddWorld(caster);
  WalkingRobot walking(WalkThatTurns(), caster, 10);
  RobotInScene& robot = walking.body;
  const std::vector<std::int32_t> floor_excluded{kFloorId}, nothing_excluded;
  for (int k = 0; k < 40; ++k) {
    walking.MoveTo(k / 50.0);
    caster.Commit();
    const auto& exclude = k % 10 < 5 ? floor_excluded : nothing_excluded;
    ASSERT_EQ(robot.ClearanceTo(exclude), BruteForceClearance(robot, caster, exclude)) << "sample " << k;
  }
  EXPECT_LT(robot.ClearanceTo(nothing_excluded), 0.03) << "a foot on the floor";
  EXPECT_GT(robot.ClearanceTo(floor_excluded), 0.03);
}

}  // namespace
}  // namespace proxsim

namespace proxsim {
namespace {

// A built-in model is parsed once per process and options and then copied
// (sim/make_locomotion.cc): each load equals a fresh parse with its own options,
// whatever was loaded before.
TEST(LoadRobotModelTest, BuiltinModelLoadsEqualFreshParsesWhateverCameBefore) {
  for (const LinkGeometryKind geometry :
       {LinkGeometryKind::kVisual, LinkGeometryKind::kCollision, LinkGeometryKind::kVisual}) {
    RobotConfig config;
    config.model = "builtin:biped";
    config.geometry = geometry;
    const RobotModel loaded = LoadRobotModel(config);
    const RobotModel fresh = RobotModel::Builtin("biped", UrdfOptions{.geometry = geometry});
    ASSERT_EQ(loaded.link_count(), fresh.link_count());
    for (int link = 0; link < fresh.link_count(); ++link) {
      EXPECT_EQ(loaded.link_name(link), fresh.link_name(link));
      EXPECT_EQ(loaded.link(link).shapes_kind, fresh.link(link).shapes_kind) << "the options of another load";
      const auto& a = loaded.link(link).shapes;
      const auto& b = fresh.link(link).shapes;
      ASSERT_EQ(a.size(), b.size()) << loaded.link_name(link);
      for (std::size_t s = 0; s < a.size(); ++s) {
        EXPECT_EQ(a[s].shape.index(), b[s].shape.index());
        EXPECT_TRUE(a[s].X_LO.matrix() == b[s].X_LO.matrix());
      }
    }
  }
}

}  // namespace
}  // namespace proxsim
