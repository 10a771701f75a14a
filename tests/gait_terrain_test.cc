// The gait on uneven ground (docs/terrain.md): the built-in biped walks courses of
// steps and holes described in the test as level pieces along x, whose true
// surface and edges the test computes itself; every 5 ms it checks, with the
// robot's own 3D forward kinematics, that no sole goes below the surface,
// that the stance pivot and the trailing toe stay planted, that the swing
// sole clears every edge it passes over, and that the pelvis moves
// continuously; and where the robot gets to and why it stops.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gait/gait_walker.h"
#include "raycast/ray_caster.h"
#include "robot/robot_model.h"
#include "scene/scene.h"
#include "sim/caster_terrain.h"

namespace proxsim {
namespace {

constexpr double kRate_hz = 200.0;
constexpr double kHalfWidth_m = 1.5;   // every piece spans |y| <= this
constexpr double kBottom_m = -0.5;     // pieces reach down to here; a hole's bottom is this level

/// A level piece of ground along x: [x0, x1) at height z.
struct Piece {
  double x0, x1, z;
};

/// A course: level pieces, contiguous along x.
struct Course {
  std::vector<Piece> pieces;

  /// The true surface's height at x (the piece holding it).
  double SurfaceZ(double x) const {
    for (const Piece& p : pieces)
      if (x >= p.x0 && x < p.x1) return p.z;
    return -1e9;
  }
  /// The edges: top corners between pieces of different heights, (x, z).
  std::vector<Vec2> Edges() const {
    std::vector<Vec2> edges;
    for (std::size_t i = 0; i + 1 < pieces.size(); ++i)
      if (pieces[i].z != pieces[i + 1].z) edges.emplace_back(pieces[i].x1, std::max(pieces[i].z, pieces[i + 1].z));
    return edges;
  }
  /// Boxes from kBottom_m up to each piece's top (a hole: a slab below kBottom_m).
  Scene MakeScene() const {
    Scene scene;
    for (const Piece& p : pieces) {
      const double top = p.z > kBottom_m ? p.z : kBottom_m;
      const double bottom = p.z > kBottom_m ? kBottom_m : kBottom_m - 0.1;
      Pose X_WO = Pose::Identity();
      X_WO.translation() = Vec3(0.5 * (p.x0 + p.x1), 0, 0.5 * (top + bottom));
      scene.objects.push_back(SceneObject{"floor_" + std::to_string(scene.objects.size()),
                                          Box{Vec3(p.x1 - p.x0, 2 * kHalfWidth_m, top - bottom)}, X_WO, Material{},
                                          /*ground=*/true});
    }
    return scene;
  }
};

/// From x = 1: `n` steps up of `rise` and `tread` (the last one a landing of
/// `landing`), `n` down, then 3 m of floor.
Course Stairs(int n, double rise, double tread, double landing) {
  Course c;
  double x = 1.0;
  c.pieces.push_back({-1.0, x, 0.0});
  for (int i = 1; i < n; ++i, x += tread) c.pieces.push_back({x, x + tread, i * rise});
  c.pieces.push_back({x, x + landing, n * rise});
  x += landing;
  for (int i = n - 1; i >= 1; --i, x += tread) c.pieces.push_back({x, x + tread, i * rise});
  c.pieces.push_back({x, x + 3.0, 0.0});
  return c;
}

/// The built-in `stairs` course, as src/scene/builtin_scenes.cc documents it.
Course BuiltinCourse() {
  Course c = Stairs(4, 0.15, 0.30, 1.2);
  c.pieces.back().x1 = 5.0;
  c.pieces.push_back({5.0, 5.25, kBottom_m});
  c.pieces.push_back({5.25, 6.5, 0.0});
  c.pieces.push_back({6.5, 7.1, kBottom_m});
  c.pieces.push_back({7.1, 9.0, 0.0});
  return c;
}

struct TerrainWalk {
  double worst_sole_below_m = 0;      // deepest any sole point went below the surface
  double max_pivot_slip_m = 0;        // stance pivot against its latched point
  double max_trailing_toe_slip_m = 0; // the other toe through double support
  double min_edge_clearance_m = 1e9;  // swing sole above an edge under it
  int edges_passed = 0;               // swing samples with an edge under the sole
  double max_pelvis_dz_m = 0;         // between 5 ms samples
  double max_pelvis_z_m = -1e9;
  double final_x_m = 0;               // pelvis where the walk ended
  double front_toe_x_m = 0;           // the foremost toe there
  bool stopped = false;
  std::vector<LocomotionEvent> events;
  std::vector<double> heel_strike_x;  // the stance heels, in order
};

TerrainWalk WalkCourse(const Course& course, double stride_m, double end_x_m, double limit_s) {
  const Scene scene = course.MakeScene();
  RayCaster caster;
  std::vector<BodyShape> shapes;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    shapes.push_back({scene.objects[i].shape, scene.objects[i].X_WO, static_cast<std::int32_t>(i)});
  caster.AddBody(std::move(shapes), BodyKind::kWorld);
  caster.Commit();
  const CasterTerrain terrain(caster);

  WalkConfig config;
  config.gait.stride_m = stride_m;
  config.gait.period_s = 1.2;
  config.waypoints_m = {Vec2(0, 0), Vec2(end_x_m, 0)};
  GaitWalker walker(RobotModel::Builtin("biped"), config);
  walker.SetTerrain(&terrain);
  const BipedLegs& legs = walker.legs();
  const std::vector<Vec2> edges = course.Edges();

  TerrainWalk w;
  double last_z = NAN;
  RobotState s;
  for (int i = 0; i <= limit_s * kRate_hz; ++i) {
    s = walker.Advance(i / kRate_hz);
    for (LocomotionEvent& e : walker.TakeEvents()) w.events.push_back(e);
    const std::vector<Pose> X_WL = walker.model().ForwardKinematics(s.X_WP, s.q);
    const StepPlan& plan = walker.current_step();
    const double p = walker.step_phase();
    if (w.heel_strike_x.empty() || w.heel_strike_x.back() != plan.p_W_heel.x()) w.heel_strike_x.push_back(plan.p_W_heel.x());

    for (const Side side : {Side::kLeft, Side::kRight}) {
      const LegGeometry& g = legs.leg(side);
      const Pose& X_WF = X_WL[g.foot_link];
      const Vec3 heel = X_WF * g.p_L_heel, toe = X_WF * g.p_L_toe;
      // every point of the sole above the true surface
      for (int k = 0; k <= 12; ++k) {
        for (const double y : {-g.half_width_m, 0.0, g.half_width_m}) {
          const Vec3 q = X_WF * (g.p_L_heel + (g.p_L_toe - g.p_L_heel) * (k / 12.0) + Vec3(0, y, 0));
          w.worst_sole_below_m = std::max(w.worst_sole_below_m, course.SurfaceZ(q.x()) - q.z());
        }
      }
      // the swing sole over each edge it passes above
      if (side == plan.swing && p >= kDoubleSupportEnd && p < 0.5 && !s.stopped) {
        for (const Vec2& e : edges) {
          if (e.x() < std::min(heel.x(), toe.x()) || e.x() > std::max(heel.x(), toe.x())) continue;
          const double z_sole = heel.z() + (toe.z() - heel.z()) * (e.x() - heel.x()) / (toe.x() - heel.x());
          w.min_edge_clearance_m = std::min(w.min_edge_clearance_m, z_sole - e.y());
          ++w.edges_passed;
        }
      }
    }
    // the stance pivot and the planted trailing toe
    const LegGeometry& st = legs.leg(plan.stance);
    const Pose& X_WS = X_WL[st.foot_link];
    if (p < FootFlatPhase()) {
      w.max_pivot_slip_m = std::max(w.max_pivot_slip_m, (X_WS * st.p_L_heel - plan.p_W_heel).norm());
    } else {
      const Vec3& p_L = p <= HeelOffPhase() ? st.p_L_sole : st.p_L_toe;
      w.max_pivot_slip_m = std::max(w.max_pivot_slip_m, (X_WS * p_L - plan.X_WF * p_L).norm());
    }
    if (p < kDoubleSupportEnd) {
      const LegGeometry& sw = legs.leg(plan.swing);
      w.max_trailing_toe_slip_m = std::max(w.max_trailing_toe_slip_m, (X_WL[sw.foot_link] * sw.p_L_toe - plan.p_W_trailing_toe).norm());
    }
    const double z = s.X_WP.translation().z();
    if (!std::isnan(last_z)) w.max_pelvis_dz_m = std::max(w.max_pelvis_dz_m, std::abs(z - last_z));
    last_z = z;
    w.max_pelvis_z_m = std::max(w.max_pelvis_z_m, z);
    if (s.stopped) break;
  }
  w.stopped = s.stopped;
  w.final_x_m = s.X_WP.translation().x();
  const auto X_WL = walker.model().ForwardKinematics(s.X_WP, s.q);
  for (const Side side : {Side::kLeft, Side::kRight})
    w.front_toe_x_m = std::max(w.front_toe_x_m, (X_WL[legs.leg(side).foot_link] * legs.leg(side).p_L_toe).x());
  return w;
}

void Print(const char* name, const TerrainWalk& w) {
  std::printf("[ measured ] %s: deepest sole below the surface %.3f mm, pivot slip %.3g mm, trailing toe slip %.3g mm, "
              "least edge clearance %.1f mm (%d swing samples over an edge), max pelvis dz %.2f mm / 5 ms, "
              "ended at x = %.3f m (front toe %.3f m), %zu steps\n",
              name, 1e3 * w.worst_sole_below_m, 1e3 * w.max_pivot_slip_m, 1e3 * w.max_trailing_toe_slip_m,
              1e3 * w.min_edge_clearance_m, w.edges_passed, 1e3 * w.max_pelvis_dz_m, w.final_x_m, w.front_toe_x_m,
              w.heel_strike_x.size());
  for (const LocomotionEvent& e : w.events) std::printf("[ measured ]   %s: %s\n", e.event.c_str(), e.detail.c_str());
}

void ExpectTheQualityBar(const TerrainWalk& w) {
  EXPECT_LT(w.worst_sole_below_m, 1e-3);
  EXPECT_LT(w.max_pivot_slip_m, 1e-3);
  EXPECT_LT(w.max_trailing_toe_slip_m, 1e-3);
  EXPECT_GE(w.min_edge_clearance_m, 0.02 - 2e-4);  // the planner's slack (kClearanceSlack_m)
  EXPECT_LE(w.max_pelvis_dz_m, 2e-3);
}

TEST(GaitTerrain, WalksTheBuiltinCourseAndStopsBeforeTheWideHole) {
  const Course course = BuiltinCourse();
  const TerrainWalk w = WalkCourse(course, 0.6, 8.5, 30);
  Print("built-in stairs course, stride 0.6 m", w);
  ExpectTheQualityBar(w);
  EXPECT_GT(w.edges_passed, 0);
  // up on the landing, over the small hole, and standing before the wide one
  EXPECT_GT(w.max_pelvis_z_m, 0.6 + 0.9);
  EXPECT_TRUE(w.stopped);
  EXPECT_GT(w.final_x_m, 5.25);
  EXPECT_LT(w.front_toe_x_m, 6.5);
  ASSERT_EQ(w.events.size(), 1u);
  EXPECT_EQ(w.events[0].event, "cannot_step");
  EXPECT_NE(w.events[0].detail.find("a gap of 0.60 m"), std::string::npos) << w.events[0].detail;
}

TEST(GaitTerrain, OtherRisesAndTreads) {
  {
    const Course course = Stairs(3, 0.10, 0.35, 0.9);
    const TerrainWalk w = WalkCourse(course, 0.6, 6.0, 30);
    Print("rise 0.10 m, tread 0.35 m", w);
    ExpectTheQualityBar(w);
    EXPECT_GT(w.max_pelvis_z_m, 3 * 0.10 + 0.9);
    EXPECT_GT(w.final_x_m, course.pieces.back().x0 + 0.5);
    EXPECT_TRUE(w.events.empty());
  }
  {
    // steeper than the built-in course: within the biped's ankle range
    // (dorsiflexion 34 deg) the trailing foot leaves a 0.29 m tread on its
    // toe, heel high, and its front face would sweep through the riser ahead:
    // the legs stand before that step and say why (docs/terrain.md)
    const Course course = Stairs(3, 0.18, 0.29, 0.9);
    const TerrainWalk w = WalkCourse(course, 0.6, 6.0, 30);
    Print("rise 0.18 m, tread 0.29 m", w);
    ExpectTheQualityBar(w);
    EXPECT_GT(w.max_pelvis_z_m, 0.18 + 0.9);  // up the first riser
    EXPECT_TRUE(w.stopped);
    ASSERT_EQ(w.events.size(), 1u);
    EXPECT_EQ(w.events[0].event, "cannot_step");
    EXPECT_NE(w.events[0].detail.find("cannot clear the ground"), std::string::npos) << w.events[0].detail;
  }
}

}  // namespace
}  // namespace proxsim
