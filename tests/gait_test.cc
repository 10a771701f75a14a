// Gait: the normative curves, and the walker's planted-foot guarantees checked
// with the robot's own 3D forward kinematics over several cycles at 200 Hz.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "gait/gait_curves.h"
#include "gait/gait_walker.h"
#include "robot/robot_model.h"

namespace proxsim {
namespace {

constexpr double kGaitRate_hz = 200.0;

// The 4 corners of a foot's sole in the world.
std::vector<Vec3> SoleCorners(const BipedLegs& legs, Side side, const std::vector<Pose>& X_WL) {
  const LegGeometry& g = legs.leg(side);
  std::vector<Vec3> corners;
  for (const Vec3& end : {g.p_L_heel, g.p_L_toe})
    for (double y : {-g.half_width_m, g.half_width_m}) corners.push_back(X_WL[g.foot_link] * (end + Vec3(0, y, 0)));
  return corners;
}

double LowestSoleZ(const BipedLegs& legs, Side side, const std::vector<Pose>& X_WL) {
  double z = 1e9;
  for (const Vec3& c : SoleCorners(legs, side, X_WL)) z = std::min(z, c.z());
  return z;
}

// The stance pivot of the current step, from 3D FK, and its latched value.
std::pair<Vec3, Vec3> PivotNowAndLatched(const BipedLegs& legs, const StepPlan& plan, double p,
                                         const std::vector<Pose>& X_WL) {
  const LegGeometry& g = legs.leg(plan.stance);
  const Pose& X_WF = X_WL[g.foot_link];
  if (p < FootFlatPhase()) return {X_WF * g.p_L_heel, plan.p_W_heel};
  const Vec3& p_L = p <= HeelOffPhase() ? g.p_L_sole : g.p_L_toe;
  return {X_WF * p_L, plan.X_WF * p_L};
}

WalkConfig StraightConfig(double stride_m, double period_s) {
  WalkConfig c;
  c.gait.stride_m = stride_m;
  c.gait.period_s = period_s;
  return c;
}

TEST(GaitCurves, PassThroughKeyPointsAndArePeriodicC1) {
  EXPECT_NEAR(NormativeHipFlexionDeg()(0.50), -10.0, 1e-12);
  EXPECT_NEAR(NormativeKneeFlexionDeg()(0.70), 62.0, 1e-12);
  EXPECT_NEAR(NormativeAnkleDorsiflexionDeg()(0.62), -15.0, 1e-12);
  for (const PeriodicCurve* c : {&NormativeHipFlexionDeg(), &NormativeKneeFlexionDeg(), &NormativeAnkleDorsiflexionDeg()}) {
    EXPECT_NEAR((*c)(0.0), (*c)(1.0), 1e-12);
    // C1 across the wrap and across a knot: one-sided slopes agree
    for (double knot : {0.0, 0.25, 0.85}) {
      const double h = 1e-6;
      const double left = ((*c)(knot) - (*c)(knot - h)) / h, right = ((*c)(knot + h) - (*c)(knot)) / h;
      EXPECT_NEAR(left, right, 1e-2 * std::max(1.0, std::abs(left)));
    }
  }
  // the stance foot is exactly flat between foot-flat and heel-off, heel rocker before, toe rocker after
  EXPECT_GT(FootFlatPhase(), 0.02);
  EXPECT_LT(FootFlatPhase(), kDoubleSupportEnd);
  EXPECT_GT(HeelOffPhase(), 0.3);
  EXPECT_EQ(CurveLegAngles(0.2, 0.7).pitch, 0.0);
  EXPECT_GT(CurveLegAngles(0.01, 0.7).pitch, 0.0);
  EXPECT_LT(CurveLegAngles(0.45, 0.7).pitch, 0.0);
}

struct WalkFigures {
  double max_pivot_slip_m = 0, max_trailing_toe_slip_m = 0, lowest_sole_m = 1e9, max_pelvis_dz_m = 0,
         max_q_period_diff = 0, min_shank_deg = 1e9;
  std::vector<double> left_strike_x;
  double distance_per_cycle_m = 0;
};

WalkFigures WalkStraight(double stride_m, double period_s, int cycles) {
  GaitWalker walker(RobotModel::Builtin("biped"), StraightConfig(stride_m, period_s));
  const BipedLegs legs(walker.model());
  WalkFigures f;
  const int per_cycle = static_cast<int>(std::lround(period_s * kGaitRate_hz));
  std::vector<std::vector<double>> q_hist;
  std::vector<double> dist_hist;
  double last_z = NAN;
  Side last_stance = Side::kRight;
  for (int i = 0; i <= cycles * per_cycle; ++i) {
    const RobotState s = walker.Advance(i / kGaitRate_hz);
    const std::vector<Pose> X_WL = walker.model().ForwardKinematics(s.X_WP, s.q);
    const StepPlan& plan = walker.current_step();
    const double p = walker.step_phase();
    const auto [now, latched] = PivotNowAndLatched(legs, plan, p, X_WL);
    f.max_pivot_slip_m = std::max(f.max_pivot_slip_m, (now - latched).norm());
    // the other foot, planted on its toe through the double support
    if (p < kDoubleSupportEnd) {
      const Vec3 toe = X_WL[legs.leg(plan.swing).foot_link] * legs.leg(plan.swing).p_L_toe;
      f.max_trailing_toe_slip_m = std::max(f.max_trailing_toe_slip_m, (toe - plan.p_W_trailing_toe).norm());
    }
    for (const Side side : {Side::kLeft, Side::kRight})
      f.min_shank_deg = std::min(f.min_shank_deg, RadToDeg(legs.ReadJoints(side, s.q).hip - legs.ReadJoints(side, s.q).knee));
    f.lowest_sole_m = std::min({f.lowest_sole_m, LowestSoleZ(legs, Side::kLeft, X_WL), LowestSoleZ(legs, Side::kRight, X_WL)});
    if (!std::isnan(last_z)) f.max_pelvis_dz_m = std::max(f.max_pelvis_dz_m, std::abs(s.X_WP.translation().z() - last_z));
    last_z = s.X_WP.translation().z();
    if (plan.stance == Side::kLeft && last_stance == Side::kRight) f.left_strike_x.push_back(plan.p_W_heel.x());
    last_stance = plan.stance;
    q_hist.push_back(s.q);
    dist_hist.push_back(s.distance_walked_m);
  }
  // periodicity over the steady cycles (skip the first two)
  for (int i = 2 * per_cycle; i + per_cycle < static_cast<int>(q_hist.size()); ++i)
    for (std::size_t j = 0; j < q_hist[i].size(); ++j)
      f.max_q_period_diff = std::max(f.max_q_period_diff, std::abs(q_hist[i][j] - q_hist[i + per_cycle][j]));
  f.distance_per_cycle_m = dist_hist[cycles * per_cycle] - dist_hist[(cycles - 1) * per_cycle];
  return f;
}

TEST(GaitWalker, PlantedFootNoPenetrationContinuousPeriodicStride) {
  for (const auto& [stride, period] : {std::pair{0.6, 1.2}, std::pair{1.0, 1.1}, std::pair{0.4, 1.0}}) {
    const WalkFigures f = WalkStraight(stride, period, 6);
    std::printf("[ measured ] stride %.2f m period %.2f s: pivot slip %.3g mm, trailing toe slip %.3g mm, lowest sole %.3g mm, "
                "max pelvis dz %.3g mm / 5 ms, q periodicity %.3g rad, min shank %.1f deg, stride %.6f m, pelvis per cycle %.6f m\n",
                stride, period, 1e3 * f.max_pivot_slip_m, 1e3 * f.max_trailing_toe_slip_m, 1e3 * f.lowest_sole_m, 1e3 * f.max_pelvis_dz_m,
                f.max_q_period_diff, f.min_shank_deg, f.left_strike_x.back() - f.left_strike_x[f.left_strike_x.size() - 2],
                f.distance_per_cycle_m);
    EXPECT_LT(f.max_pivot_slip_m, 1e-3);
    EXPECT_LT(f.max_trailing_toe_slip_m, 1e-3);
    EXPECT_GT(f.lowest_sole_m, -1e-3);
    EXPECT_LT(f.max_pelvis_dz_m, 3e-3);
    EXPECT_LT(f.max_q_period_diff, 1e-9);
    ASSERT_GE(f.left_strike_x.size(), 4u);
    // stride: heel strike to heel strike of the left foot, and the pelvis advance per cycle, within 2 mm
    EXPECT_NEAR(f.left_strike_x.back() - f.left_strike_x[f.left_strike_x.size() - 2], stride, 2e-3);
    EXPECT_NEAR(f.distance_per_cycle_m, stride, 2e-3);
  }
}

TEST(GaitWalker, FollowsWaypointsWithATurnAndStopsAtTheLast) {
  WalkConfig c = StraightConfig(0.6, 1.2);
  c.waypoints_m = {Vec2(0, 0), Vec2(3, 0), Vec2(3, 2)};
  GaitWalker walker(RobotModel::Builtin("biped"), c);
  const BipedLegs legs(walker.model());
  RobotState s;
  double lowest = 1e9;
  for (int i = 0; i <= 60 * 200; ++i) {
    s = walker.Advance(i / kGaitRate_hz);
    const auto X_WL = walker.model().ForwardKinematics(s.X_WP, s.q);
    lowest = std::min({lowest, LowestSoleZ(legs, Side::kLeft, X_WL), LowestSoleZ(legs, Side::kRight, X_WL)});
    if (s.stopped) break;
  }
  ASSERT_TRUE(s.stopped);
  EXPECT_TRUE(walker.path_done());
  const Vec2 end = s.X_WP.translation().head<2>();
  std::printf("[ measured ] path (0,0)->(3,0)->(3,2): stopped at t=%.2f s at (%.3f, %.3f), yaw %.1f deg, lowest sole %.3g mm\n",
              s.t_s, end.x(), end.y(), RadToDeg(RpyFromRotation(s.X_WP.linear()).z()), 1e3 * lowest);
  EXPECT_LT((end - Vec2(3, 2)).norm(), 0.3);  // half a stride
  EXPECT_GT(RadToDeg(RpyFromRotation(s.X_WP.linear()).z()), 60.0);  // it turned left
  EXPECT_GT(lowest, -1e-3);
}

// Every stride from 0.3 to 1.0 m reaches the last waypoint (the pelvis within
// half a stride of it, standing) of paths given with or without the start
// point, straight and with turns, and one that starts behind the robot. At
// strides of 0.42 to 0.55 m the start point used to be passed only if the
// pelvis was within half a stride of it at the first heel strike, and the
// robot walked in circles back to it.
TEST(GaitWalker, ReachesTheLastWaypointForEveryStrideAndPath) {
  const std::vector<std::pair<const char*, std::vector<Vec2>>> paths = {
      {"straight", {Vec2(0, 0), Vec2(4, 0)}},
      {"straight, no start point", {Vec2(4, 0)}},
      {"a right angle", {Vec2(0, 0), Vec2(3, 0), Vec2(3, 2)}},
      {"a right angle, no start point", {Vec2(3, 0), Vec2(3, 2)}},
      {"zigzag", {Vec2(0, 0), Vec2(1.5, 1), Vec2(3, -1), Vec2(4.5, 0)}},
      {"behind", {Vec2(-2, 1)}}};
  constexpr double kSweepRate_hz = 50, kLimit_s = 60;
  double worst_ratio = 0, slowest_s = 0;
  for (int step = 0; step <= 14; ++step) {
    const double stride = 0.30 + 0.05 * step;
    for (const auto& [name, waypoints] : paths) {
      SCOPED_TRACE(std::string(name) + ", stride " + std::to_string(stride));
      WalkConfig c = StraightConfig(stride, 1.2);
      c.waypoints_m = waypoints;
      GaitWalker walker(RobotModel::Builtin("biped"), c);
      RobotState s;
      double max_abs_y = 0;
      for (int i = 0; i <= kLimit_s * kSweepRate_hz && !s.stopped; ++i) {
        s = walker.Advance(i / kSweepRate_hz);
        max_abs_y = std::max(max_abs_y, std::abs(s.X_WP.translation().y()));
      }
      ASSERT_TRUE(walker.path_done()) << "still walking after " << kLimit_s << " s, at " << s.X_WP.translation().transpose();
      const double miss_m = (s.X_WP.translation().head<2>() - waypoints.back()).norm();
      EXPECT_LT(miss_m, 0.5 * stride);
      if (std::ranges::all_of(waypoints, [](const Vec2& w) { return w.y() == 0; }))
        EXPECT_LT(max_abs_y, 0.05) << "a straight path walked off its line";
      worst_ratio = std::max(worst_ratio, miss_m / stride);
      slowest_s = std::max(slowest_s, s.t_s);
    }
  }
  std::printf("[ measured ] strides 0.30-1.00 m, %zu paths: every last waypoint reached, farthest stop %.2f strides "
              "from it, slowest %.1f s\n", paths.size(), worst_ratio, slowest_s);
}

TEST(GaitWalker, RequestStopStandsStillInDoubleSupportThenResumes) {
  GaitWalker walker(RobotModel::Builtin("biped"), StraightConfig(0.6, 1.2));
  const BipedLegs legs(walker.model());
  RobotState s;
  int i = 0;
  for (; i <= 2.3 * 200; ++i) s = walker.Advance(i / kGaitRate_hz);
  walker.RequestStop();
  const double requested_at = s.t_s;
  for (; !s.stopped; ++i) s = walker.Advance(i / kGaitRate_hz);
  // stopped within one step (half a period) of the request
  EXPECT_LE(s.t_s - requested_at, 0.6 + 1e-9);
  EXPECT_EQ(s.support, SupportLeg::kDouble);
  const auto X_WL = walker.model().ForwardKinematics(s.X_WP, s.q);
  EXPECT_NEAR(LowestSoleZ(legs, Side::kLeft, X_WL), 0.0, 1e-3);   // both feet down
  EXPECT_NEAR(LowestSoleZ(legs, Side::kRight, X_WL), 0.0, 1e-3);
  const RobotState frozen = s;
  for (int j = 0; j < 400; ++j, ++i) s = walker.Advance(i / kGaitRate_hz);
  EXPECT_TRUE(s.stopped);
  EXPECT_TRUE(s.X_WP.isApprox(frozen.X_WP, 1e-12));
  EXPECT_EQ(s.q, frozen.q);
  EXPECT_DOUBLE_EQ(s.distance_walked_m, frozen.distance_walked_m);
  walker.Resume();
  for (int j = 0; j < 400; ++j, ++i) s = walker.Advance(i / kGaitRate_hz);
  EXPECT_FALSE(s.stopped);
  EXPECT_GT(s.distance_walked_m, frozen.distance_walked_m + 0.5);
}

TEST(GaitWalker, SetStrideChangesTheStrideWithoutPenetration) {
  GaitWalker walker(RobotModel::Builtin("biped"), StraightConfig(0.6, 1.2));
  const BipedLegs legs(walker.model());
  std::vector<double> left_x;
  Side last = Side::kRight;
  double lowest = 1e9, max_dz = 0, last_z = NAN;
  for (int i = 0; i <= 12 * 240; ++i) {
    if (i == 3 * 240) walker.SetStride(0.9);
    const RobotState s = walker.Advance(i / kGaitRate_hz);
    const auto X_WL = walker.model().ForwardKinematics(s.X_WP, s.q);
    lowest = std::min({lowest, LowestSoleZ(legs, Side::kLeft, X_WL), LowestSoleZ(legs, Side::kRight, X_WL)});
    if (!std::isnan(last_z)) max_dz = std::max(max_dz, std::abs(s.X_WP.translation().z() - last_z));
    last_z = s.X_WP.translation().z();
    if (walker.current_step().stance == Side::kLeft && last == Side::kRight) left_x.push_back(walker.current_step().p_W_heel.x());
    last = walker.current_step().stance;
  }
  EXPECT_NEAR(walker.achieved_stride_m(), 0.9, 1e-4);
  EXPECT_NEAR(left_x.back() - left_x[left_x.size() - 2], 0.9, 2e-3);
  EXPECT_GT(lowest, -1e-3);
  EXPECT_LT(max_dz, 3e-3);
}

// A stride set while walking is looked up in a table of sampled amplitudes,
// not searched: the amplitude it gives walks the stride asked for within the
// interpolation's error (bounded here: 1 mm, against the exact steady stride
// of that amplitude), the loaded stride maps back to the loaded amplitude
// exactly, and the stride in force is a no-op.
TEST(GaitWalker, SetStrideLooksUpAnAmplitudeThatWalksTheStrideAskedFor) {
  GaitWalker walker(RobotModel::Builtin("biped"), StraightConfig(0.6, 1.2));
  const double loaded_k = walker.amplitude();
  const StepPlanner planner(walker.legs());
  for (double stride_m = 0.30; stride_m <= 0.901; stride_m += 0.05) {
    walker.SetStride(stride_m);
    EXPECT_NEAR(SteadyStride_m(planner, walker.amplitude()), stride_m, 1e-3) << "stride " << stride_m;
    EXPECT_NEAR(walker.achieved_stride_m(), stride_m, 1e-9);  // the loaded 0.6 m: as the bisection found it
  }
  walker.SetStride(0.6);
  EXPECT_EQ(walker.amplitude(), loaded_k);
  const double k_before = walker.amplitude();
  walker.SetStride(0.6);  // in force: nothing to do
  EXPECT_EQ(walker.amplitude(), k_before);
  // out of reach: clamped to the largest amplitude, as the load's bisection clamps
  walker.SetStride(50.0);
  EXPECT_DOUBLE_EQ(walker.amplitude(), kMaxAmplitude);
  EXPECT_LT(walker.achieved_stride_m(), 50.0);
}

}  // namespace
}  // namespace proxsim
