// No dead ends on stairs the legs can climb (docs/terrain.md, "No dead
// ends"): a course of three risers whose treads are 1.5 foot lengths (rounded
// up to the centimetre), its first riser at 20 offsets along the path 3 cm
// apart (one stride of the biped), is walked by the gait on the course's true
// surface. Each walk ends at the path's end, or standing before the first
// riser with a `cannot_step` that says why; never standing (under the
// default `unsafe_steps: fall`, falling) on the stairs. At every 10 ms sample
// every revolute joint's speed (its change since the last sample) is within
// its URDF velocity limit and its angle within its range, and no sole point
// goes below the surface. Courses up onto a landing: the built-in biped's
// rises 0.06 to 0.31 m (gait.max_step_m, from its legs: 0.32 m), the Unitree
// H1's 0.06 to 0.27 m (0.28 m; skipped, saying so, when
// ../shared/robots/h1_description is absent); courses up and down again: the
// biped's 0.12 and 0.18 m, the H1's 0.12 m (steeper descents on these treads
// stand on the landing: docs/terrain.md).
// Each course's outcomes are printed as a [ measured ] line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "gait/gait_walker.h"
#include "raycast/ray_caster.h"
#include "robot/robot_model.h"
#include "scenario/scenario.h"
#include "scene/scene.h"
#include "sim/caster_terrain.h"

namespace proxsim {
namespace stairs_offsets_test {
namespace {

namespace fs = std::filesystem;

constexpr double kSampleRate_hz = 100.0;  // the CLI examples' finest rate: one sample is 10 ms
constexpr int kOffsets = 20;
constexpr double kOffsetStep_m = 0.03;     // 20 offsets over 0.6 m: one stride of the biped
constexpr double kFirstRiser_x_m = 1.0;    // at offset 0; the robot starts at x = 0
constexpr int kRisers = 3;                 // up, and as many down
constexpr double kLanding_m = 1.2;
constexpr double kRunOut_m = 1.5;          // floor after the last riser down, the path ending on it
constexpr double kFloorBottom_m = -0.5;    // every box reaches down to here

// A level piece of the course along x: [x0, x1) at height z.
struct Tread {
  double x0, x1, z;
};

// The course with its first riser at x_riser_m: kRisers up to a landing,
// and (`down`) as many down to the floor, or (not) the landing runs on; the
// path ends kRunOut_m onto the last piece.
std::vector<Tread> RiserCourse(double x_riser_m, double rise_m, double tread_m, bool down) {
  std::vector<Tread> treads{{-1.0, x_riser_m, 0.0}};
  double x = x_riser_m;
  for (int i = 1; i < kRisers; ++i, x += tread_m) treads.push_back({x, x + tread_m, i * rise_m});
  if (!down) {
    treads.push_back({x, x + kRunOut_m + 1.0, kRisers * rise_m});
    return treads;
  }
  treads.push_back({x, x + kLanding_m, kRisers * rise_m});
  x += kLanding_m;
  for (int i = kRisers - 1; i >= 1; --i, x += tread_m) treads.push_back({x, x + tread_m, i * rise_m});
  treads.push_back({x, x + kRunOut_m + 1.0, 0.0});
  return treads;
}

double TopAt(const std::vector<Tread>& treads, double x) {
  for (const Tread& t : treads)
    if (x >= t.x0 && x < t.x1) return t.z;
  return -1e9;
}

struct OffsetWalk {
  bool reached = false;           // the path's end
  bool refused_before = false;    // standing before the first riser with cannot_step
  std::string refusal;            // the cannot_step detail, if any
  double stood_toe_x_m = 0;       // the foremost toe where it stood
  double worst_speed_ratio = 0;   // a joint's speed over one sample / its velocity limit
  std::string worst_speed_joint;
  double worst_speed_t_s = 0;
  double worst_angle_excess_rad = -1e9;
  std::string worst_angle_joint;
  double deepest_sole_m = 0;      // a sole point below the surface
};

// Walks `model` (with `config`'s legs and gait) over the course at x_riser_m.
OffsetWalk WalkRisers(const RobotModel& model, const WalkConfig& config, double x_riser_m, double rise_m,
                      double tread_m, bool down) {
  const std::vector<Tread> treads = RiserCourse(x_riser_m, rise_m, tread_m, down);
  RayCaster caster;
  std::vector<BodyShape> shapes;
  for (std::size_t i = 0; i < treads.size(); ++i) {
    const Tread& t = treads[i];
    Pose X_WO = Pose::Identity();
    X_WO.translation() = Vec3(0.5 * (t.x0 + t.x1), 0, 0.5 * (t.z + kFloorBottom_m));
    shapes.push_back({Box{Vec3(t.x1 - t.x0, 3.0, t.z - kFloorBottom_m)}, X_WO, static_cast<std::int32_t>(i)});
  }
  caster.AddBody(std::move(shapes), BodyKind::kWorld);
  caster.Commit();
  const CasterTerrain terrain(caster);

  WalkConfig walk = config;
  const double x_end_m = treads.back().x0 + kRunOut_m;
  walk.waypoints_m = {Vec2(0, 0), Vec2(x_end_m, 0)};
  GaitWalker walker(model, walk);
  walker.SetTerrain(&terrain);
  const RobotModel& m = walker.model();
  const BipedLegs& legs = walker.legs();

  OffsetWalk w;
  std::vector<double> last_q;
  RobotState s;
  const double limit_s = 60.0;
  for (int i = 0; i <= limit_s * kSampleRate_hz; ++i) {
    const double t_s = i / kSampleRate_hz;
    s = walker.Advance(t_s);
    for (const LocomotionEvent& e : walker.TakeEvents())
      if (e.event == "cannot_step") w.refusal = e.detail;
    // every revolute joint: its angle within its range, its speed over the sample within its limit
    for (int j = 0; j < m.joint_count(); ++j) {
      const RobotJoint& joint = m.joint(j);
      if (joint.type != JointType::kRevolute) continue;
      const double excess = std::max(joint.lower - s.q[j], s.q[j] - joint.upper);
      if (excess > w.worst_angle_excess_rad) {
        w.worst_angle_excess_rad = excess;
        w.worst_angle_joint = joint.name;
      }
      if (last_q.empty() || joint.velocity <= 0) continue;
      const double ratio = std::abs(s.q[j] - last_q[j]) * kSampleRate_hz / joint.velocity;
      if (ratio > w.worst_speed_ratio) {
        w.worst_speed_ratio = ratio;
        w.worst_speed_joint = joint.name;
        w.worst_speed_t_s = t_s;
      }
    }
    last_q = s.q;
    // the soles above the surface
    const std::vector<Pose> X_WL = m.ForwardKinematics(s.X_WP, s.q);
    for (const Side side : {Side::kLeft, Side::kRight}) {
      const LegGeometry& g = legs.leg(side);
      for (int k = 0; k <= 8; ++k) {
        const Vec3 q = X_WL[g.foot_link] * (g.p_L_heel + (g.p_L_toe - g.p_L_heel) * (k / 8.0));
        w.deepest_sole_m = std::max(w.deepest_sole_m, TopAt(treads, q.x()) - q.z());
      }
    }
    if (s.stopped) break;
  }
  w.reached = walker.path_done();
  const std::vector<Pose> X_WL = m.ForwardKinematics(s.X_WP, s.q);
  for (const Side side : {Side::kLeft, Side::kRight}) {
    const LegGeometry& g = legs.leg(side);
    w.stood_toe_x_m = std::max(w.stood_toe_x_m, (X_WL[g.foot_link] * g.p_L_toe).x());
  }
  w.refused_before = !w.reached && s.stopped && !w.refusal.empty() && w.stood_toe_x_m < x_riser_m;
  return w;
}

// The course at 20 offsets: every walk climbed (or refused before the first
// riser), every joint within its limits at every sample.
void ClimbAtEveryOffset(const char* robot, const RobotModel& model, const WalkConfig& config, double rise_m,
                        double tread_m, bool down) {
  int climbed = 0, refused = 0;
  double worst_ratio = 0;
  std::string worst;
  for (int i = 0; i < kOffsets; ++i) {
    const double x_riser_m = kFirstRiser_x_m + i * kOffsetStep_m;
    const OffsetWalk w = WalkRisers(model, config, x_riser_m, rise_m, tread_m, down);
    climbed += w.reached;
    refused += w.refused_before;
    EXPECT_TRUE(w.reached || w.refused_before)
        << robot << (down ? " up and down" : " up") << ", rise " << rise_m << " m, tread " << tread_m
        << " m, first riser at x = " << x_riser_m
        << " m: stood with its front toe at x = " << w.stood_toe_x_m << " m: " << w.refusal;
    EXPECT_LE(w.worst_speed_ratio, 1.0 + 1e-9)
        << robot << ", rise " << rise_m << " m, first riser at x = " << x_riser_m << " m: " << w.worst_speed_joint
        << " at " << w.worst_speed_ratio << " of its velocity limit over the 10 ms sample ending at t = "
        << w.worst_speed_t_s << " s";
    EXPECT_LE(w.worst_angle_excess_rad, 1e-6) << robot << ", first riser at x = " << x_riser_m << ": "
                                              << w.worst_angle_joint;
    EXPECT_LT(w.deepest_sole_m, 1e-3) << robot << ", first riser at x = " << x_riser_m;
    if (w.worst_speed_ratio > worst_ratio) {
      worst_ratio = w.worst_speed_ratio;
      char text[160];
      std::snprintf(text, sizeof text, "%s at x_riser %.2f m, t = %.2f s", w.worst_speed_joint.c_str(), x_riser_m,
                    w.worst_speed_t_s);
      worst = text;
    }
  }
  std::printf("[ measured ] %s, %d rises of %.2f m %s, treads %.2f m, %d offsets: %d walked to the path's end, %d "
              "refused before the first riser; fastest joint %.3f of its velocity limit (%s)\n",
              robot, kRisers, rise_m, down ? "up and as many down" : "up", tread_m, kOffsets, climbed, refused,
              worst_ratio, worst.c_str());
}

// The tread: 1.5 foot lengths (heel to toe), rounded up to the centimetre;
// the highest rise: gait.max_step_m as the legs give it, less a centimetre.
struct Stairs {
  double tread_m, top_rise_m;
};
Stairs StairsFor(const RobotModel& model, const WalkConfig& config) {
  const GaitWalker walker(model, config);
  const LegGeometry& g = walker.legs().leg(Side::kLeft);
  return {std::ceil(150 * (g.toe_x_m - g.heel_x_m)) / 100, std::floor(100 * walker.gait_cycle()->max_step_m) / 100 - 0.01};
}

TEST(StairsOffsets, BipedClimbsRisersUpToMaxStepAtEveryOffset) {
  const RobotModel model = RobotModel::Builtin("biped");
  WalkConfig config;
  config.gait.stride_m = 0.6;
  config.gait.period_s = 1.2;
  const Stairs stairs = StairsFor(model, config);
  for (const double rise_m : {0.06, 0.12, 0.18, 0.24, stairs.top_rise_m})
    ClimbAtEveryOffset("biped", model, config, rise_m, stairs.tread_m, /*down=*/false);
  for (const double rise_m : {0.12, 0.18}) ClimbAtEveryOffset("biped", model, config, rise_m, stairs.tread_m, /*down=*/true);
}

TEST(StairsOffsets, H1ClimbsRisersUpToMaxStepAtEveryOffset) {
  const fs::path example = fs::path(PROXSIM_SOURCE_DIR) / "data" / "scenarios" / "h1_dining_room.yaml";
  if (!fs::is_regular_file(testing::kH1Dir / "urdf" / "h1.urdf"))
    GTEST_SKIP() << "skipped: the Unitree H1 is not at " << testing::kH1Dir.lexically_normal().string()
                 << " (the H1 tests read ../shared/robots/h1_description from beside the project)";
  RobotConfig config = LoadScenarioFile(example.string()).robot.value();
  config.strategy.reset();
  const RobotModel model =
      RobotModel::FromUrdfFile(config.model, {.geometry = config.geometry, .package_paths = config.package_paths});
  const Stairs stairs = StairsFor(model, config);
  for (const double rise_m : {0.06, 0.12, 0.18, stairs.top_rise_m})
    ClimbAtEveryOffset("h1", model, config, rise_m, stairs.tread_m, /*down=*/false);
  ClimbAtEveryOffset("h1", model, config, 0.12, stairs.tread_m, /*down=*/true);
}

}  // namespace
}  // namespace stairs_offsets_test
}  // namespace proxsim
