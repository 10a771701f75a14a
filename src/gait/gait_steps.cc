#include "gait/gait_steps.h"

#include <algorithm>
#include <cmath>

namespace proxsim {

namespace {

double Smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

Pose PelvisPose(const Vec3& p_WP, double yaw) {
  Pose X = Pose::Identity();
  X.linear() = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
  X.translation() = p_WP;
  return X;
}

// A sagittal point of a leg as a 3D point in the pelvis frame (at the hip's y).
Vec3 InPelvis(const LegGeometry& g, const Vec2xz& p) { return {p.x(), g.p_PH.y(), p.y()}; }

}  // namespace

double StepPlanner::Amplitude(const StepPlan& plan, double p) const {
  return plan.k_from + (plan.k_to - plan.k_from) * Smoothstep(p / kDoubleSupportEnd);
}

LegAnglesRad StepPlanner::StanceAngles(const StepPlan& plan, double p) const {
  const double g = plan.g_from + (plan.g_to - plan.g_from) * Smoothstep(p / kDoubleSupportEnd);
  LegAnglesRad a = CurveLegAngles(p, Amplitude(plan, p), g);
  const double fade = 1 - Smoothstep(p / kDoubleSupportEnd);
  a.hip += plan.stance_offset.hip * fade;
  a.knee += plan.stance_offset.knee * fade;
  return a;
}

Pose StepPlanner::StancePelvis(const StepPlan& plan, double p, const LegAnglesRad& stance) const {
  const LegGeometry& g = legs_.leg(plan.stance);
  // heel rocker: pivot on the latched heel while the heading turns
  if (p < FootFlatPhase() || !plan.flat_latched) {
    const double yaw = plan.yaw_from + (plan.yaw_to - plan.yaw_from) * Smoothstep(p / FootFlatPhase());
    const Rotation R = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
    const Vec3 p_P_heel = InPelvis(g, legs_.Point(plan.stance, stance, FootPoint::kHeel));
    return PelvisPose(plan.p_W_heel - R * p_P_heel, yaw);
  }
  // flat foot, then toe rocker: pivot on a point of the latched foot frame F
  const FootPoint which = p <= HeelOffPhase() ? FootPoint::kMid : FootPoint::kToe;
  const Vec2xz off = legs_.FootOffset(plan.stance, which);
  const Vec3 p_W_pivot = plan.X_WF * Vec3(off.x(), 0, off.y());
  const Rotation R = Eigen::AngleAxisd(plan.yaw_to, Vec3::UnitZ()).toRotationMatrix();
  const Vec3 p_P_pivot = InPelvis(g, legs_.Point(plan.stance, stance, which));
  return PelvisPose(p_W_pivot - R * p_P_pivot, plan.yaw_to);
}

std::pair<Vec2xz, double> StepPlanner::SwingTarget(const StepPlan& plan, double p) const {
  const double u = std::clamp(p / 0.5, 0.0, 1.0);
  const double s = Smoothstep(u);
  const LegAnglesRad curve = CurveLegAngles(p + 0.5, Amplitude(plan, p));
  const double bump = std::pow(std::sin(kPi * u), 2);
  const Vec2xz p_PA = legs_.Ankle(plan.swing, curve) + plan.swing_start_delta * (1 - s) +
                      plan.swing_end_delta * s + Vec2xz(0, plan.clearance_bump_m * bump);
  return {p_PA, curve.pitch + plan.swing_start_pitch * (1 - s)};
}

StepPose StepPlanner::Evaluate(const StepPlan& plan, double p) const {
  StepPose pose;
  pose.stance = StanceAngles(plan, p);
  pose.X_WP = StancePelvis(plan, p, pose.stance);
  auto [p_PA, pitch] = SwingTarget(plan, p);
  // floor guard: lift the swing foot if its lowest sole corner would be below the floor
  const double lowest = std::min(RotateSagittal(pitch, legs_.FootOffset(plan.swing, FootPoint::kHeel)).y(),
                                 RotateSagittal(pitch, legs_.FootOffset(plan.swing, FootPoint::kToe)).y());
  const double deficit = plan.floor_z_m - (pose.X_WP.translation().z() + p_PA.y() + lowest);
  if (deficit > 0 && p > 0) p_PA.y() += deficit;
  pose.swing = legs_.SolveAnkle(plan.swing, p_PA, pitch);
  return pose;
}

void StepPlanner::Finish(StepPlan* plan) const {
  const LegGeometry& g = legs_.leg(plan->stance);
  // the flat foot frame: the stance foot at foot-flat (pitch exactly 0)
  {
    const double p = FootFlatPhase();
    const LegAnglesRad stance = StanceAngles(*plan, p);
    const Pose X_WP = StancePelvis(*plan, p, stance);
    plan->X_WF = X_WP * Eigen::Translation3d(InPelvis(g, legs_.Ankle(plan->stance, stance)));
    plan->flat_latched = true;
  }
  // landing: at p = 0.5 the swing heel must touch the floor with the curves'
  // knee and pitch; solve the hip angle (forward branch) for that
  {
    const double k = plan->k_to;
    const StepPose end = [&] {
      StepPose e;
      e.stance = StanceAngles(*plan, 0.5);
      e.X_WP = StancePelvis(*plan, 0.5, e.stance);
      return e;
    }();
    const LegGeometry& sg = legs_.leg(plan->swing);
    const LegAnglesRad curve = CurveLegAngles(1.0, k);
    LegAnglesRad land = curve;
    const double z_target = plan->floor_z_m - end.X_WP.translation().z();  // heel z in P
    const double o_z = RotateSagittal(curve.pitch, legs_.FootOffset(plan->swing, FootPoint::kHeel)).y();
    for (int attempt = 0; attempt < 2; ++attempt) {
      const double kn = land.knee;
      const double R = std::hypot(sg.thigh_m + sg.shank_m * std::cos(kn), sg.shank_m * std::sin(kn));
      const double phi = std::atan2(sg.shank_m * std::sin(kn), sg.thigh_m + sg.shank_m * std::cos(kn));
      const double c = (sg.p_PH.z() + o_z - z_target) / R;
      if (c <= 1.0 || attempt == 1) {
        land.hip = phi + std::acos(std::clamp(c, -1.0, 1.0));
        break;
      }
      land.knee = 0;  // out of reach with the curve's knee: straighten it
    }
    plan->swing_end_delta = legs_.Ankle(plan->swing, land) - legs_.Ankle(plan->swing, curve);
  }
  // clearance bump: smallest c with sole(u) + c·sin²(πu) ≥ clearance·sin²(πu) in mid-swing
  {
    plan->clearance_bump_m = 0;
    double c = 0;
    for (int i = 0; i <= 40; ++i) {
      const double u = 0.15 + 0.7 * i / 40.0, p = 0.5 * u;
      const double pelvis_z = StancePelvis(*plan, p, StanceAngles(*plan, p)).translation().z();
      const auto [p_PA, pitch] = SwingTarget(*plan, p);
      const double lowest = std::min(RotateSagittal(pitch, legs_.FootOffset(plan->swing, FootPoint::kHeel)).y(),
                                     RotateSagittal(pitch, legs_.FootOffset(plan->swing, FootPoint::kToe)).y());
      const double z = pelvis_z + p_PA.y() + lowest - plan->floor_z_m;
      const double b = std::pow(std::sin(kPi * u), 2);
      c = std::max(c, kSwingClearance_m - z / b);
    }
    plan->clearance_bump_m = c;
  }
}

StepPlan StepPlanner::FirstStep(const Vec3& p_W_start, double yaw_rad, double k) const {
  StepPlan plan;
  plan.stance = Side::kLeft;
  plan.swing = Side::kRight;
  plan.k_from = plan.k_to = k;
  plan.g_from = plan.g_to = PushOffGain(legs_, plan.stance, k);
  plan.yaw_from = plan.yaw_to = yaw_rad;
  plan.floor_z_m = p_W_start.z();
  const LegAnglesRad stance = CurveLegAngles(0.0, k);
  const Rotation R = Eigen::AngleAxisd(yaw_rad, Vec3::UnitZ()).toRotationMatrix();
  const Vec3 p_P_heel = InPelvis(legs_.leg(Side::kLeft), legs_.Point(Side::kLeft, stance, FootPoint::kHeel));
  const Vec3 p_WP(p_W_start.x(), p_W_start.y(), p_W_start.z() - p_P_heel.z());
  plan.p_W_heel = p_WP + R * p_P_heel;
  // the trailing foot starts on its curve, lifted onto the floor if the curve puts it below
  const LegAnglesRad trailing = CurveLegAngles(0.5, k);
  const double below = p_W_start.z() - (p_WP.z() + legs_.LowestSoleZ(Side::kRight, trailing));
  if (below > 0) plan.swing_start_delta = Vec2xz(0, below);
  Finish(&plan);
  return plan;
}

StepPlan StepPlanner::NextStep(const StepPlan& prev, double k_to, double yaw_to) const {
  const StepPose strike = Evaluate(prev, 0.5);
  StepPlan plan;
  plan.stance = prev.swing;
  plan.swing = prev.stance;
  plan.k_from = prev.k_to;
  plan.k_to = k_to;
  plan.g_from = prev.g_to;
  plan.g_to = PushOffGain(legs_, plan.stance, k_to);
  plan.yaw_from = prev.yaw_to;
  plan.yaw_to = yaw_to;
  plan.floor_z_m = prev.floor_z_m;
  // latch the new stance heel where it struck
  const Vec3 p_P_heel = InPelvis(legs_.leg(plan.stance), legs_.Point(plan.stance, strike.swing, FootPoint::kHeel));
  plan.p_W_heel = strike.X_WP * p_P_heel;
  // stance: what the curves do not explain at heel strike, blended out
  const LegAnglesRad stance_curve = CurveLegAngles(0.0, plan.k_from);
  plan.stance_offset.hip = strike.swing.hip - stance_curve.hip;
  plan.stance_offset.knee = strike.swing.knee - stance_curve.knee;
  // swing: start from where the old stance foot is
  const LegAnglesRad swing_curve = CurveLegAngles(0.5, plan.k_from);
  plan.swing_start_delta = legs_.Ankle(plan.swing, strike.stance) - legs_.Ankle(plan.swing, swing_curve);
  plan.swing_start_pitch = strike.stance.pitch - swing_curve.pitch;
  Finish(&plan);
  return plan;
}

double PushOffGain(const BipedLegs& legs, Side stance, double k) {
  const Side swing = stance == Side::kLeft ? Side::kRight : Side::kLeft;
  // pelvis height above the floor: at landing (swing heel down, curves) and at
  // the end of stance (stance toe down) for a gain g
  const double landing = -legs.Point(swing, CurveLegAngles(1.0, k), FootPoint::kHeel).y();
  const auto on_toe = [&](double g) { return -legs.Point(stance, CurveLegAngles(0.5, k, g), FootPoint::kToe).y(); };
  if (on_toe(1.0) <= landing) return 1.0;
  if (on_toe(0.0) >= landing) return 0.0;
  double lo = 0, hi = 1;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (on_toe(mid) > landing ? hi : lo) = mid;
  }
  return lo;
}

double SteadyStride_m(const StepPlanner& planner, double k) {
  StepPlan plan = planner.FirstStep(Vec3::Zero(), 0.0, k);
  std::vector<double> left_heel_x;
  for (int step = 0; step < 8; ++step) {
    if (plan.stance == Side::kLeft) left_heel_x.push_back(plan.p_W_heel.x());
    plan = planner.NextStep(plan, k, 0.0);
  }
  return left_heel_x.back() - left_heel_x[left_heel_x.size() - 2];
}

}  // namespace proxsim
