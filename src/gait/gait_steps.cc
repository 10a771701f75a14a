#include "gait/gait_steps.h"

#include <algorithm>
#include <cmath>

namespace proxsim {

namespace {

// Phase step of the finite difference that gives the planted ankle's velocity at toe-off.
constexpr double kRateStep = 1e-5;

double Smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

Rotation Heading(double yaw) { return Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix(); }

// The pelvis at p_WP, turned by R_WP (Heading of its yaw).
Pose PelvisPose(const Vec3& p_WP, const Rotation& R_WP) {
  Pose X = Pose::Identity();
  X.linear() = R_WP;
  X.translation() = p_WP;
  return X;
}

// Swing progress from toe-off (0) to heel strike (1).
double SwingProgress(double p) { return std::clamp((p - kDoubleSupportEnd) / (0.5 - kDoubleSupportEnd), 0.0, 1.0); }

// The lowest of the swing sole's heel and toe below the ankle, at a pitch.
double LowestSoleBelowAnkle(const BipedLegs& legs, Side side, double pitch) {
  return std::min(RotateSagittal(pitch, legs.FootOffset(side, FootPoint::kHeel)).y(),
                  RotateSagittal(pitch, legs.FootOffset(side, FootPoint::kToe)).y());
}

}  // namespace

double StepPlanner::Amplitude(const StepPlan& plan, double p) const {
  return plan.k_from + (plan.k_to - plan.k_from) * Smoothstep(p / kDoubleSupportEnd);
}

LegAnglesRad StepPlanner::StanceAngles(const StepPlan& plan, double p) const {
  const double g = plan.g_from + (plan.g_to - plan.g_from) * Smoothstep(p / kDoubleSupportEnd);
  LegAnglesRad a = legs_.Curve(p, Amplitude(plan, p), g);
  const double fade = 1 - Smoothstep(p / kDoubleSupportEnd);
  a.hip += plan.stance_offset.hip * fade;
  a.knee += plan.stance_offset.knee * fade;
  return a;
}

Pose StepPlanner::StancePelvis(const StepPlan& plan, double p, const LegAnglesRad& stance) const {
  // heel rocker: pivot on the latched heel while the heading turns
  if (p < FootFlatPhase() || !plan.flat_latched) {
    const double yaw = plan.yaw_from + (plan.yaw_to - plan.yaw_from) * Smoothstep(p / FootFlatPhase());
    const Rotation R = Heading(yaw);
    const Vec3 p_P_heel = legs_.Point3(plan.stance, stance, FootPoint::kHeel);
    return PelvisPose(plan.p_W_heel - R * p_P_heel, R);
  }
  // flat foot, then toe rocker: pivot on a point of the latched foot frame F
  // (a flat foot is exactly level, pitch 0; one whose heel rose early to keep
  // its ankle within its limits, pitch < 0, already pivots on its toe:
  // TerrainStanceAngles)
  const FootPoint which = p <= HeelOffPhase() && stance.pitch >= 0 ? FootPoint::kMid : FootPoint::kToe;
  const Vec3 p_W_pivot = plan.X_WF * legs_.FootPoint_L(plan.stance, which);
  const Rotation R = Heading(plan.yaw_to);
  const Vec3 p_P_pivot = legs_.Point3(plan.stance, stance, which);
  return PelvisPose(p_W_pivot - R * p_P_pivot, R);
}

LegAnglesRad StepPlanner::SwingCurve(const StepPlan& plan, double p) const {
  return legs_.Curve(p + 0.5, Amplitude(plan, p));
}

double StepPlanner::SwingPitch(const StepPlan& plan, double p) const {
  return SwingPitch(plan, p, SwingCurve(plan, p));
}

double StepPlanner::SwingPitch(const StepPlan& plan, double p, const LegAnglesRad& curve) const {
  const double s = Smoothstep(std::clamp(p / 0.5, 0.0, 1.0));
  const double pitch = curve.pitch + plan.swing_start_pitch * (1 - s);
  // over uneven ground the foot is carried level (the toe up, off the edges), as the arc lifts it
  if (!plan.terrain) return pitch;
  const double u = SwingProgress(p);
  const double level = pitch * (1 - SwingArc::LiftShape(u));
  if (!plan.swing_arc.hold_pitch || p < kDoubleSupportEnd) return level;
  // or, once off the ground, it keeps its toe-off pitch until the carry starts,
  // then levels as it travels
  const double c = plan.swing_arc.CarryShape(u);
  return plan.swing_arc.start_pitch_rad * (1 - c) + level * c;
}

Vec2xz StepPlanner::PlantedAnkle(const StepPlan& plan, double p, const Pose& X_WP) const {
  return PlantedAnkle(plan, X_WP, SwingPitch(plan, p));
}

Vec2xz StepPlanner::PlantedAnkle(const StepPlan& plan, const Pose& X_WP, double swing_pitch) const {
  // the latched toe in the pelvis frame, the ankle behind it at the foot's pitch
  const Vec3 p_P_toe = X_WP.inverse() * plan.p_W_trailing_toe;
  const Vec2xz toe_from_ankle = RotateSagittal(swing_pitch, legs_.FootOffset(plan.swing, FootPoint::kToe));
  Vec2xz p_PA(p_P_toe.x(), p_P_toe.z());
  p_PA -= toe_from_ankle;
  return p_PA;
}

Vec2xz StepPlanner::SwingAnkle(const StepPlan& plan, double p, const LegAnglesRad& curve) const {
  const double u = SwingProgress(p);
  // cubic Hermite from (delta, rate) at toe-off to (end delta, 0) at heel strike
  const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u, h01 = 3 * u * u - 2 * u * u * u;
  const double bump = std::pow(std::sin(kPi * u), 2);
  return legs_.Ankle(plan.swing, curve) + plan.swing_toe_off_delta * h00 + plan.swing_toe_off_rate * h10 +
         plan.swing_end_delta * h01 + Vec2xz(0, plan.clearance_bump_m * bump);
}

StepPose StepPlanner::Evaluate(const StepPlan& plan, double p) const {
  StepPose pose;
  pose.stance = plan.terrain ? TerrainStanceAngles(plan, p) : StanceAngles(plan, p);
  pose.X_WP = StancePelvis(plan, p, pose.stance);
  // the swing leg's curves at p, evaluated once for its pitch and its ankle
  const LegAnglesRad swing_curve = SwingCurve(plan, p);
  const double pitch = SwingPitch(plan, p, swing_curve);
  Vec2xz p_PA = Vec2xz::Zero();
  if (p < kDoubleSupportEnd) {
    // double support: the trailing foot stays planted on its toe
    p_PA = PlantedAnkle(plan, pose.X_WP, pitch);
  } else if (plan.terrain) {
    // swing over uneven ground: the arc, sized against the ground when planned
    p_PA = ArcAnkle(plan, p, pose.X_WP);
  } else {
    // swing, with a floor guard: lift the foot if its lowest sole point would be below the floor
    p_PA = SwingAnkle(plan, p, swing_curve);
    const double deficit =
        plan.floor_z_m - (pose.X_WP.translation().z() + p_PA.y() + LowestSoleBelowAnkle(legs_, plan.swing, pitch));
    if (deficit > 0) p_PA.y() += deficit;
  }
  pose.swing = legs_.SolveAnkle(plan.swing, p_PA, pitch);
  // over uneven ground the foot carried level may ask the ankle for more than
  // it bends: in the air the foot tilts instead (continuous: at toe-off the
  // planted foot's pitch is within the limits, or the step is not taken)
  if (plan.terrain && p >= kDoubleSupportEnd) pose.swing = legs_.PitchWithinAnkleLimits(plan.swing, pose.swing);
  return pose;
}

void StepPlanner::Finish(StepPlan* plan) const {
  // the flat foot frame: the stance foot link at foot-flat (pitch exactly 0)
  {
    const double p = FootFlatPhase();
    const LegAnglesRad stance = StanceAngles(*plan, p);
    const Pose X_WP = StancePelvis(*plan, p, stance);
    plan->X_WF = X_WP * legs_.FootPose_P(plan->stance, stance);
    plan->flat_latched = true;
  }
  // toe-off: where the planted foot leaves the swing path, and how fast it
  // moves there against the curves' own ankle path
  {
    const auto offset = [&](double p) -> Vec2xz {
      const Pose X_WP = StancePelvis(*plan, p, StanceAngles(*plan, p));
      return PlantedAnkle(*plan, p, X_WP) - legs_.Ankle(plan->swing, legs_.Curve(p + 0.5, Amplitude(*plan, p)));
    };
    const Vec2xz at_toe_off = offset(kDoubleSupportEnd);
    plan->swing_toe_off_delta = at_toe_off;
    plan->swing_toe_off_rate = (at_toe_off - offset(kDoubleSupportEnd - kRateStep)) / kRateStep * (0.5 - kDoubleSupportEnd);
  }
  // landing: at p = 0.5 the swing heel must touch the floor with the curves'
  // knee and pitch; solve the hip angle (forward branch) for that
  {
    const double k = plan->k_to;
    const LegAnglesRad end_stance = StanceAngles(*plan, 0.5);
    const Pose end_X_WP = StancePelvis(*plan, 0.5, end_stance);
    const LegGeometry& sg = legs_.leg(plan->swing);
    const LegAnglesRad curve = legs_.Curve(1.0, k);
    LegAnglesRad land = curve;
    const double z_target = plan->floor_z_m - end_X_WP.translation().z();  // heel z in P
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
      const double u = 0.15 + 0.7 * i / 40.0;
      const double p = kDoubleSupportEnd + u * (0.5 - kDoubleSupportEnd);
      const double pelvis_z = StancePelvis(*plan, p, StanceAngles(*plan, p)).translation().z();
      const LegAnglesRad swing_curve = SwingCurve(*plan, p);
      const double z = pelvis_z + SwingAnkle(*plan, p, swing_curve).y() +
                       LowestSoleBelowAnkle(legs_, plan->swing, SwingPitch(*plan, p, swing_curve)) - plan->floor_z_m;
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
  plan.floor_z_m = plan.landing_z_m = plan.highest_ground_z_m = p_W_start.z();
  const LegAnglesRad stance = legs_.Curve(0.0, k);
  const Rotation R = Heading(yaw_rad);
  const Vec3 p_P_heel = legs_.Point3(Side::kLeft, stance, FootPoint::kHeel);
  const Vec3 p_WP(p_W_start.x(), p_W_start.y(), p_W_start.z() - p_P_heel.z());
  plan.p_W_heel = p_WP + R * p_P_heel;
  // the trailing foot starts on its curve, lifted onto the floor if the curve
  // puts it below, and stays there until toe-off
  LegAnglesRad trailing = legs_.Curve(0.5, k);
  const double below = p_W_start.z() - (p_WP.z() + legs_.LowestSoleZ(Side::kRight, trailing));
  if (below > 0) trailing = legs_.SolveAnkle(Side::kRight, legs_.Ankle(Side::kRight, trailing) + Vec2xz(0, below), trailing.pitch);
  plan.p_W_trailing_toe = PelvisPose(p_WP, R) * legs_.Point3(Side::kRight, trailing, FootPoint::kToe);
  Finish(&plan);
  if (terrain_ != nullptr) PlanOnTerrain(&plan, /*stance_from_natural_landing=*/true, p_WP, /*check_onward=*/true);
  return plan;
}

StepPlan StepPlanner::NextStep(const StepPlan& prev, double k_to, double yaw_to) const {
  return PlanNextStep(prev, k_to, yaw_to, /*check_onward=*/true);
}

StepPlan StepPlanner::PlanNextStep(const StepPlan& prev, double k_to, double yaw_to, bool check_onward) const {
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
  plan.floor_z_m = plan.landing_z_m = plan.highest_ground_z_m = prev.landing_z_m;
  // latch the new stance heel where it struck, on the floor
  plan.p_W_heel = strike.X_WP * legs_.Point3(plan.stance, strike.swing, FootPoint::kHeel);
  plan.p_W_heel.z() = plan.floor_z_m;
  // and the old stance foot's toe, where it pivots (its latched toe)
  plan.p_W_trailing_toe = prev.X_WF * legs_.FootPoint_L(prev.stance, FootPoint::kToe);
  // stance: what the curves do not explain at heel strike, blended out
  const LegAnglesRad stance_curve = legs_.Curve(0.0, plan.k_from);
  plan.stance_offset.hip = strike.swing.hip - stance_curve.hip;
  plan.stance_offset.knee = strike.swing.knee - stance_curve.knee;
  // swing: its pitch starts from where the old stance foot is
  plan.swing_start_pitch = strike.stance.pitch - legs_.Curve(0.5, plan.k_from).pitch;
  Finish(&plan);
  if (terrain_ != nullptr) PlanOnTerrain(&plan, prev.natural_landing, strike.X_WP.translation(), check_onward);
  return plan;
}

double PushOffGain(const BipedLegs& legs, Side stance, double k) {
  const Side swing = stance == Side::kLeft ? Side::kRight : Side::kLeft;
  // pelvis height above the floor: at landing (swing heel down, curves) and at
  // the end of stance (stance toe down) for a gain g
  const double landing = -legs.Point(swing, legs.Curve(1.0, k), FootPoint::kHeel).y();
  const auto on_toe = [&](double g) { return -legs.Point(stance, legs.Curve(0.5, k, g), FootPoint::kToe).y(); };
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
  // on a flat floor, whatever ground the planner walks on
  const StepPlanner flat(planner.legs());
  StepPlan plan = flat.FirstStep(Vec3::Zero(), 0.0, k);
  std::vector<double> left_heel_x;
  for (int step = 0; step < 8; ++step) {
    if (plan.stance == Side::kLeft) left_heel_x.push_back(plan.p_W_heel.x());
    plan = flat.NextStep(plan, k, 0.0);
  }
  return left_heel_x.back() - left_heel_x[left_heel_x.size() - 2];
}

}  // namespace proxsim
