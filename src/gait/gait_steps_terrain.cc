// The terrain half of StepPlanner (gait_steps.h, "Uneven ground"): the
// foothold of each step on the ground profile, and the terrain step — the
// stance leg by IK to a pelvis height ramp, the swing on a lift–carry–lower
// arc sized against the ground.
//
// Frames: W world, P pelvis, H a step's heading frame (origin under the
// stance heel at z = 0, x along the step's heading yaw_to, z up; s is H's x).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "gait/gait_memo.h"
#include "gait/gait_steps.h"
#include "gait/joint_limits.h"
#include "gait/shank_clearance.h"
#include "gait/step_safety.h"

namespace proxsim {

namespace {

// Width of the speed ramps at either end of the pelvis height ramp (fraction of the step).
constexpr double kPelvisRampEnds = 0.15;
// Samples of the swing checked against the ground when a terrain step is planned.
constexpr int kSwingChecks = 64;
// Rounds of lifting the arc higher when the legs' IK lands the sole lower than the arc.
constexpr int kLiftRounds = 4;
// A deficit where the lift has barely risen (near lift-off and landing) sizes
// the lift as if the plateau's shape there were this: dividing by the shape
// itself flung the foot metres up for a millimetre's deficit next to the tread
// it leaves (the swing leg then folded back over the pelvis, pointing at it).
constexpr double kLiftShapeFloor = 0.2;
// A sole this close to its clearance counts as clearing it, m.
constexpr double kClearanceSlack_m = 2e-4;
// Heights within this of the stance tread are the stance tread's level, m (the
// ray caster answers in float).
constexpr double kSameLevel_m = 1e-6;
// Footholds PlanOnTerrain tries for a step, at least this far apart, before
// it keeps the first (gait_steps.h, "No dead ends").
constexpr std::size_t kFootholdChoices = 8;
constexpr double kFootholdSpacing_m = 0.02;
// Phase step of the finite difference that gives the planted ankle's velocity at toe-off.
constexpr double kRateStep = 1e-5;
// The profile starts this far behind the trailing sole and reaches this far beyond the next step's toe, m.
constexpr double kProfileMargin_m = 0.05;
// Rounds of rolling a stance foot onto its toe to keep its ankle within its limits.
constexpr int kStanceRollRounds = 4;
// How far inside the ankle's limits a rolled stance foot keeps it, rad (each
// round's IK moves the ankle a little after its pitch is set).
constexpr double kStanceRollMargin_rad = 2e-3;
// The planner keeps the swing sole this far under UnsafeStepReason's cap on its
// lift (kMaxLiftAboveGround_m), m: the check samples the step more densely.
constexpr double kLiftCapMargin_m = 0.005;
// Arcs tried in turn when the default arc's lift would carry the sole above
// the cap: a climbing foot gains its height sooner (a descending one keeps it
// longer) than over kArcHeightChangeSpan, and the last ones carry the foot
// forward only once it has risen (the trailing toe of a climb starts against
// the riser in front of it: a 0.26 m sole on a 0.30 m tread). The last ones also hold the foot's toe-off pitch until the carry starts: a
// foot that levels as it lifts swings its toe forward into that riser.
// The very last ones change height over longer spans: a foot leaving a higher
// tread for a lower one (the trailing foot after a step down, toe-off steep
// behind a lowered pelvis) then sinks as it levels, instead of levelling
// while still high above the edge it left.
// {height span, carry start, hold pitch}.
struct ArcShape {
  double height_span, carry_start;
  bool hold_pitch;
};
constexpr std::array<ArcShape, 10> kSoonerArcs = {{{0.55, kArcCarryStart, false},
                                                  {0.45, kArcCarryStart, false},
                                                  {0.35, kArcCarryStart, false},
                                                  {0.3, 0.2, false},
                                                  {0.3, 0.3, false},
                                                  {0.3, 0.3, true},
                                                  {0.25, 0.35, true},
                                                  {0.25, 0.45, true},
                                                  {0.85, 0.3, true},
                                                  {1.0, 0.3, true}}};

double Smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

// Position of a motion from 0 to 1 over u in [0, 1] whose speed ramps up over
// [0, r], is constant, and ramps down over [1 − r, 1] (C1; peak speed 1/(1 − r)).
double TrapezoidRamp(double u, double r) {
  u = std::clamp(u, 0.0, 1.0);
  const double v = 1 / (1 - r);
  if (u < r) return v * u * u / (2 * r);
  if (u > 1 - r) return 1 - v * (1 - u) * (1 - u) / (2 * r);
  return v * (u - r / 2);
}

double SwingProgress(double p) { return std::clamp((p - kDoubleSupportEnd) / (0.5 - kDoubleSupportEnd), 0.0, 1.0); }

Vec3 HeadingX(double yaw) { return Vec3(std::cos(yaw), std::sin(yaw), 0); }

// A point of W in H's (s, z).
Vec2 ToH(const StepPlan& plan, const Vec3& p_W) {
  return Vec2((p_W - plan.p_W_H).dot(HeadingX(plan.yaw_to)), p_W.z());
}

}  // namespace

double StepDuration_s(const StepPlan& plan, double period_s) {
  const double half = 0.5 * period_s;
  if (!plan.terrain) return half;
  const double peak_speed = std::abs(plan.pelvis_z1_m - plan.pelvis_z0_m) / (1 - kPelvisRampEnds) / half;
  return peak_speed <= kMaxPelvisRampSpeed_m_s ? half : half * peak_speed / kMaxPelvisRampSpeed_m_s;
}

LegAnglesRad StepPlanner::CurveStanceAngles(const StepPlan& plan, double p) const {
  const double g = plan.g_from + (plan.g_to - plan.g_from) * Smoothstep(p / kDoubleSupportEnd);
  return legs_.Curve(p, Amplitude(plan, p), g);
}

LegAnglesRad StepPlanner::TerrainStanceAngles(const StepPlan& plan, double p) const {
  // the pelvis the curves would give from the latched pivot, moved to the ramp
  const LegAnglesRad curve = CurveStanceAngles(plan, p);
  const Pose X_c = StancePelvis(plan, p, curve);
  const Vec3 x_P = X_c.linear().col(0);
  Vec3 target = X_c.translation() + x_P * (plan.pelvis_x0_offset_m * (1 - Smoothstep(p / 0.5)));
  target.z() = plan.pelvis_z0_m + (plan.pelvis_z1_m - plan.pelvis_z0_m) * TrapezoidRamp(p / 0.5, kPelvisRampEnds);
  // the stance leg from its pivot to that pelvis, at the curves' foot pitch
  FootPoint which = FootPoint::kHeel;
  Vec3 p_W_pivot = plan.p_W_heel;
  if (p >= FootFlatPhase() && plan.flat_latched) {
    which = p <= HeelOffPhase() ? FootPoint::kMid : FootPoint::kToe;
    p_W_pivot = plan.X_WF * legs_.FootPoint_L(plan.stance, which);
  }
  const auto pivot_in_P = [&](FootPoint point) {
    const Vec3 p_P = X_c.linear().transpose() * (plan.X_WF * legs_.FootPoint_L(plan.stance, point) - target);
    return Vec2xz(p_P.x(), p_P.z());
  };
  const Vec3 p_P_pivot = X_c.linear().transpose() * (p_W_pivot - target);
  Vec2xz pivot_P(p_P_pivot.x(), p_P_pivot.z());
  LegAnglesRad a = legs_.SolveAnkle(plan.stance, pivot_P - RotateSagittal(curve.pitch, legs_.FootOffset(plan.stance, which)), curve.pitch);
  // a flat foot whose ankle would bend past its limit (a pelvis lowered down a
  // step leans the shank forward) lifts its heel early: it pivots on its toe
  // from then on, as it does after heel-off (the pitch that puts the ankle at
  // its limit is toe-down, pitch < 0 is heel up; continuous, since the roll
  // starts where the ankle reaches its limit)
  if (which == FootPoint::kMid &&
      legs_.PitchWithinAnkleLimits(plan.stance, a, kStanceRollMargin_rad).pitch < a.pitch) {
    which = FootPoint::kToe;
    pivot_P = pivot_in_P(which);
    a = legs_.SolveAnkle(plan.stance, pivot_P - RotateSagittal(curve.pitch, legs_.FootOffset(plan.stance, which)), curve.pitch);
  }
  // on its toe, a foot whose ankle would bend past its limit rolls further onto
  // its toe instead: the heel rises, the toe stays; the pitch that puts the
  // ankle at its limit (a few rounds: the ankle moves with the pitch)
  if (which == FootPoint::kToe) {
    for (int round = 0; round < kStanceRollRounds; ++round) {
      const double pitch = legs_.PitchWithinAnkleLimits(plan.stance, a, kStanceRollMargin_rad).pitch;
      if (pitch == a.pitch) break;
      a = legs_.SolveAnkle(plan.stance, pivot_P - RotateSagittal(pitch, legs_.FootOffset(plan.stance, which)), pitch);
    }
  }
  return a;
}

Vec2xz StepPlanner::ArcAnkle(const StepPlan& plan, double p, const Pose& X_WP) const {
  const Vec2 ankle_H = plan.swing_arc.At(SwingProgress(p));
  const Vec2 pelvis_H = ToH(plan, X_WP.translation());
  // H's x is the pelvis's x from foot-flat on (the heading no longer turns)
  return Vec2xz(ankle_H.x() - pelvis_H.x(), ankle_H.y() - pelvis_H.y());
}

void StepPlanner::PlanOnTerrain(StepPlan* plan, bool stance_from_natural_landing, const Vec3& p_WP_strike,
                                bool check_onward) const {
  const LegGeometry& swing = legs_.leg(plan->swing);
  const LegGeometry& stance = legs_.leg(plan->stance);
  const double sole_m = swing.toe_x_m - swing.heel_x_m;
  const Vec3 x_H = HeadingX(plan->yaw_to);
  const Vec3 y_H(-x_H.y(), x_H.x(), 0);
  plan->p_W_H = Vec3(plan->p_W_heel.x(), plan->p_W_heel.y(), 0);

  // where the curves land the swing heel (the flat-floor plan's landing)
  const StepPose land = Evaluate(*plan, 0.5);
  const Vec3 p_W_natural = land.X_WP * legs_.Point3(plan->swing, land.swing, FootPoint::kHeel);
  const double s_natural = ToH(*plan, p_W_natural).x();
  const double s_trailing_toe = ToH(*plan, plan->p_W_trailing_toe).x();

  // the ground along the swing foot's line, from behind its lift-off to beyond the next step
  ProfileLine line;
  line.origin_W = (plan->p_W_H + y_H * (swing.sole_y_m - stance.sole_y_m)).head<2>();
  line.direction_W = x_H.head<2>();
  line.half_width_m = swing.half_width_m;
  line.s_begin_m = std::min(s_trailing_toe, 0.0) - sole_m - kProfileMargin_m;
  line.s_end_m = 3 * limits_.max_step_m + sole_m + limits_.margin_m + kProfileMargin_m;  // the look-ahead's reach
  line.z_top_m = plan->floor_z_m + legs_.leg_length_m();
  line.depth_m = line.z_top_m - plan->floor_z_m + 3.0;
  line.unknown_z_m = plan->floor_z_m;  // what a map has not seen: level with the stance foot
  const TerrainProfile profile(*terrain_, line);

  // the footholds in the order to try them (one, with the reason, when none is within reach)
  const std::vector<Foothold> choices =
      PlanFootholds(profile, 0.0, plan->floor_z_m, s_natural, limits_, kFootholdSpacing_m,
                    check_onward ? kFootholdChoices : 1);
  if (!choices.front().found) {
    plan->cannot_step = choices.front().reason;
    return;
  }
  const StepPlan unplanned = *plan;
  LandOn(plan, choices.front(), profile, s_natural, s_trailing_toe, stance_from_natural_landing, p_WP_strike);
  // no dead ends: on level ground every foothold is one; elsewhere the first
  // from which its own step and the next two can be taken (OnwardSwingsClear)
  const auto& segments = profile.segments();
  const bool level_ahead = std::all_of(segments.begin(), segments.end(), [&](const GroundSegment& g) {
    return std::abs(g.z_m - plan->floor_z_m) <= kSameLevel_m;
  });
  if (!check_onward || level_ahead) return;
  std::string why;
  if (plan->cannot_step.empty() && OnwardSwingsClear(*plan, &why)) return;
  for (std::size_t i = 1; i < choices.size(); ++i) {
    StepPlan other = unplanned;
    LandOn(&other, choices[i], profile, s_natural, s_trailing_toe, stance_from_natural_landing, p_WP_strike);
    if (other.cannot_step.empty() && OnwardSwingsClear(other, &why)) {
      *plan = std::move(other);
      return;
    }
  }
  // none: on level ground the legs stand before the step (the step refused,
  // saying why); elsewhere the first is kept (its own refusal, or the dead
  // end met when it comes)
  const bool level_step = plan->cannot_step.empty() && std::abs(plan->landing_z_m - plan->floor_z_m) <= kSameLevel_m &&
                          std::abs(plan->highest_ground_z_m - plan->floor_z_m) <= kSameLevel_m;
  if (level_step) {
    plan->dead_end = true;
    plan->cannot_step = "no foothold within reach from which the steps after it can be taken: " + why;
  }
}

void StepPlanner::LandOn(StepPlan* plan, const Foothold& foothold, const TerrainProfile& profile, double s_natural_m,
                         double s_trailing_toe_m, bool stance_from_natural_landing, const Vec3& p_WP_strike) const {
  const LegGeometry& swing = legs_.leg(plan->swing);
  const double sole_m = swing.toe_x_m - swing.heel_x_m;
  // the flat-floor step stands when it lands where the curves do, on the
  // stance's level, with nothing else under the swing, from a natural stance
  const double z_landing = std::abs(foothold.z_m - plan->floor_z_m) <= kSameLevel_m ? plan->floor_z_m : foothold.z_m;
  plan->natural_landing = foothold.s_heel_m == s_natural_m && z_landing == plan->floor_z_m;
  const std::size_t from = profile.SegmentAt(s_trailing_toe_m - sole_m);
  const std::size_t to = profile.SegmentAt(foothold.s_heel_m + sole_m);
  const bool sweep_level = from == to && profile.segments()[from].z_m <= plan->floor_z_m + kSameLevel_m;
  if (plan->natural_landing && stance_from_natural_landing && sweep_level) return;
  const StepPlan unfinished = *plan;
  Foothold landing{.found = true, .s_heel_m = foothold.s_heel_m, .z_m = z_landing, .segment = foothold.segment, .reason = {}};
  if (!FinishTerrain(plan, landing, profile, p_WP_strike)) return;
  // the shank would strike the edge of the tread the foot leaves (a foot landing
  // just past that edge, its shank leaning back over it): the heel as far
  // along its tread as the sole fits, if that is further
  const double s_heel_last_m = profile.segments()[foothold.segment].s_end_m - limits_.margin_m - sole_m;
  if (s_heel_last_m <= landing.s_heel_m) return;
  StepPlan further = unfinished;
  landing.s_heel_m = s_heel_last_m;
  FinishTerrain(&further, landing, profile, p_WP_strike);
  if (further.cannot_step.empty()) *plan = std::move(further);
}

std::string StepPlanner::LimitsReason(const StepPlan& plan) const {
  if (leg_limits_ == nullptr) return "";
  // the walker's checks (GaitWalker::CheckedDuration_s, CheckedRefusal),
  // remembered under its key: a step looked ahead at is checked once
  const std::string key = memo_key_ + StepPlanBytes(plan);
  StepWindows windows;
  double duration_s = 0;
  if (const std::optional<double> known = RememberedStepDuration(key)) {
    duration_s = *known;
    windows.duration_s = std::numeric_limits<double>::quiet_NaN();
  } else {
    duration_s = SpeedLimitedDuration_s(*this, *leg_limits_, plan, StepDuration_s(plan, period_s_), &windows);
    RememberStepDuration(key, duration_s);
  }
  std::string reason;
  if (std::optional<std::string> known = RememberedStepRefusal(key, duration_s)) {
    reason = std::move(*known);
  } else {
    reason = UnsafeStepReason(*this, *leg_limits_, plan, duration_s, &windows);
    RememberStepRefusal(key, duration_s, reason);
  }
  if (!reason.empty()) return reason;
  // the landing as the next step's stance takes it: the heel where it struck,
  // the foot at the curves' heel-strike pitch (a foot landing tilted within
  // its ankle's range may not be able to take that)
  const StepPose land = Evaluate(plan, 0.5);
  const double pitch = legs_.Curve(0.0, plan.k_to).pitch;
  const Vec2xz heel_P = legs_.Point(plan.swing, land.swing, FootPoint::kHeel);
  const LegAnglesRad stance =
      legs_.SolveAnkle(plan.swing, heel_P - RotateSagittal(pitch, legs_.FootOffset(plan.swing, FootPoint::kHeel)), pitch);
  if (const auto excess = leg_limits_->AngleExcess(plan.swing, stance))
    return "the landing foot as the next step's stance: " + excess->Describe();
  return "";
}

bool StepPlanner::OnwardSwingsClear(const StepPlan& plan, std::string* why) const {
  // the step itself within the legs' limits
  if (std::string excess = LimitsReason(plan); !excess.empty()) {
    *why = std::move(excess);
    return false;
  }
  // a step that found a foothold and is refused: its swing or its reach (a
  // step with none is the look-ahead's, and stands before what it cannot cross)
  const auto refused = [&](const StepPlan& step) {
    if (step.cannot_step.empty()) *why = LimitsReason(step);
    else if (step.terrain) *why = step.cannot_step;
    else why->clear();
    return !why->empty();
  };
  const StepPlan next = PlanNextStep(plan, plan.k_to, plan.yaw_to, /*check_onward=*/false);
  if (refused(next)) return false;
  if (!next.cannot_step.empty()) return true;
  const StepPlan after = PlanNextStep(next, next.k_to, next.yaw_to, /*check_onward=*/false);
  return !refused(after);
}

bool StepPlanner::FinishTerrain(StepPlan* plan, const Foothold& foothold, const TerrainProfile& profile,
                                const Vec3& p_WP_strike) const {
  const LegGeometry& sg = legs_.leg(plan->swing);
  plan->terrain = true;
  plan->landing_z_m = foothold.z_m;
  plan->foothold_s_m = foothold.s_heel_m;
  char text[240];

  // the curves' pelvis at heel strike and at the next one (the flat foot frame
  // from the curves first: it is the heel's, whatever the knee)
  plan->flat_latched = false;
  {
    const LegAnglesRad curve = CurveStanceAngles(*plan, FootFlatPhase());
    plan->X_WF = StancePelvis(*plan, FootFlatPhase(), curve) * legs_.FootPose_P(plan->stance, curve);
    plan->flat_latched = true;
  }
  const Pose X_c0 = StancePelvis(*plan, 0.0, CurveStanceAngles(*plan, 0.0));
  plan->pelvis_x0_offset_m = (p_WP_strike - X_c0.translation()).dot(X_c0.linear().col(0));
  plan->pelvis_z0_m = p_WP_strike.z();
  const Pose X_c1 = StancePelvis(*plan, 0.5, CurveStanceAngles(*plan, 0.5));

  // the landing: heel on the foothold at the curves' landing pitch
  const double pitch_land = SwingPitch(*plan, 0.5);
  const Vec2 ankle_land = Vec2(foothold.s_heel_m, foothold.z_m) - RotateSagittal(pitch_land, legs_.FootOffset(plan->swing, FootPoint::kHeel));
  // the pelvis at the next heel strike: lowered by the fall, and further if the
  // landing leg would be more stretched than on a flat floor
  const Vec2xz hip_P(sg.p_PH.x(), sg.p_PH.z());
  const double natural_reach = (legs_.Ankle(plan->swing, legs_.Curve(1.0, plan->k_to)) + plan->swing_end_delta - hip_P).norm();
  const Vec2 hip_H = ToH(*plan, X_c1.translation()) + Vec2(hip_P.x(), hip_P.y());
  const double ds = ankle_land.x() - hip_H.x();
  if (std::abs(ds) >= natural_reach) {
    std::snprintf(text, sizeof text, "the foothold %.2f m ahead is beyond the legs' reach", foothold.s_heel_m);
    plan->cannot_step = text;
    return false;
  }
  double lower = std::min(0.0, foothold.z_m - plan->floor_z_m);
  lower = std::min(lower, ankle_land.y() + std::sqrt(natural_reach * natural_reach - ds * ds) - hip_H.y());
  plan->pelvis_z1_m = X_c1.translation().z() + lower;

  // the knees at that landing: within what the gait asks of a leg
  const Pose X_WP_end = StancePelvis(*plan, 0.5, TerrainStanceAngles(*plan, 0.5));
  const Vec2 pelvis_end_H = ToH(*plan, X_WP_end.translation());
  const Vec2xz land_P(ankle_land.x() - pelvis_end_H.x(), ankle_land.y() - pelvis_end_H.y());
  const double knee = std::max(TerrainStanceAngles(*plan, 0.5).knee,
                               legs_.SolveAnkle(plan->swing, land_P, pitch_land).knee);
  const double rise = foothold.z_m - plan->floor_z_m;
  if (knee > kMaxKneeFlexion_rad + 1e-9 || (land_P - hip_P).norm() > sg.thigh_m + sg.shank_m + 1e-6) {
    std::snprintf(text, sizeof text, "stepping %s %.2f m to the foothold %.2f m ahead would bend a knee %.0f deg "
                  "(at most %.0f deg)", rise >= 0 ? "up" : "down", std::abs(rise), foothold.s_heel_m, RadToDeg(knee),
                  RadToDeg(kMaxKneeFlexion_rad));
    plan->cannot_step = text;
    return false;
  }

  // the swing arc: from where the planted foot leaves it at toe-off to the landing
  const auto planted_H = [&](double p) {
    const Pose X_WP = StancePelvis(*plan, p, TerrainStanceAngles(*plan, p));
    const Vec2xz a_P = PlantedAnkle(*plan, p, X_WP);
    return Vec2(ToH(*plan, X_WP.translation()) + Vec2(a_P.x(), a_P.y()));
  };
  SwingArc& arc = plan->swing_arc;
  arc = SwingArc{};  // (a plan is made from the last one: none of its arc's shape carries over)
  arc.start = planted_H(kDoubleSupportEnd);
  arc.start_rate = (arc.start - planted_H(kDoubleSupportEnd - kRateStep)) / kRateStep * (0.5 - kDoubleSupportEnd);
  arc.end = ankle_land;
  arc.lift_m = 0;
  arc.start_pitch_rad = SwingPitch(*plan, kDoubleSupportEnd);

  // its lift: the least that keeps the sole clear of the ground and its edges,
  // first on the arc itself, then on what the legs' IK makes of it
  const SoleShape sole{.heel_from_ankle = legs_.FootOffset(plan->swing, FootPoint::kHeel),
                       .toe_from_ankle = legs_.FootOffset(plan->swing, FootPoint::kToe),
                       .toe_top_m = sg.toe_top_m,
                       .heel_top_m = sg.heel_top_m};
  const std::size_t own_from = profile.SegmentAt(ToH(*plan, plan->p_W_trailing_toe).x());
  const std::size_t own_to = foothold.segment;
  // the highest ground under the swing's sweep: from under the sole as it
  // leaves (its heel a sole's length behind the latched toe) to the foothold
  const std::size_t sweep_from =
      profile.SegmentAt(ToH(*plan, plan->p_W_trailing_toe).x() - (sg.toe_x_m - sg.heel_x_m));
  plan->highest_ground_z_m = std::max(plan->floor_z_m, foothold.z_m);
  for (std::size_t i = std::min(sweep_from, own_to); i <= std::max({sweep_from, own_from, own_to}); ++i)
    plan->highest_ground_z_m = std::max(plan->highest_ground_z_m, profile.segments()[i].z_m);
  const auto phase = [](int j) { return kDoubleSupportEnd + (0.5 - kDoubleSupportEnd) * j / kSwingChecks; };
  // (an edge counts within the distance the sole moved since the last check)
  const auto moved = [&](const Vec2& ankle, double pitch, const Vec2& last_ankle, double last_pitch) {
    const auto [heel, toe] = SoleEnds(ankle, pitch, sole);
    const auto [last_heel, last_toe] = SoleEnds(last_ankle, last_pitch, sole);
    return std::max(std::abs(heel.x() - last_heel.x()), std::abs(toe.x() - last_toe.x()));
  };
  std::array<Pose, kSwingChecks + 1> X_WP_at;
  for (int j = 1; j <= kSwingChecks; ++j) X_WP_at[j] = StancePelvis(*plan, phase(j), TerrainStanceAngles(*plan, phase(j)));
  // sizes the lift of an arc: on the arc itself, then on what the legs' IK
  // makes of it; returns the sole's worst deficit below its clearance and its
  // highest lowest point above the highest ground of the sweep (what
  // UnsafeStepReason caps at kMaxLiftAboveGround_m)
  struct Sized {
    double worst = 0, peak_above_m = 0;
    double shank_worst = 0;  // the part of `worst` the shank's outline sets (gait/shank_clearance.h)
  };
  const auto size_lift = [&](SwingArc* arc) {
    plan->swing_arc = *arc;  // SwingPitch reads the plan's arc
    double lift = kSwingClearance_m;
    Vec2 last_ankle = arc->At(0);
    double last_pitch = SwingPitch(*plan, phase(0));
    arc->lift_m = 0;
    for (int j = 1; j < kSwingChecks; ++j) {
      const double u = static_cast<double>(j) / kSwingChecks;
      const Vec2 ankle = arc->At(u);
      const double pitch = SwingPitch(*plan, phase(j));
      const double deficit = SoleDeficit(profile, ankle, pitch, sole, kSwingClearance_m, own_from, own_to,
                                         moved(ankle, pitch, last_ankle, last_pitch));
      if (deficit > 0) lift = std::max(lift, deficit / std::max(SwingArc::LiftShape(u), kLiftShapeFloor));
      last_ankle = ankle;
      last_pitch = pitch;
    }
    arc->lift_m = lift;
    Sized sized;
    for (int round = 0;; ++round) {
      sized = Sized{};
      double more = 0;
      last_ankle = arc->start;
      last_pitch = SwingPitch(*plan, phase(0));
      plan->swing_arc = *arc;  // ArcAnkle reads the plan's arc
      // (the sole up to just before it lands on its own tread; the shank at the landing too)
      for (int j = 1; j <= kSwingChecks; ++j) {
        const double u = static_cast<double>(j) / kSwingChecks;
        const LegAnglesRad a = legs_.PitchWithinAnkleLimits(
            plan->swing, legs_.SolveAnkle(plan->swing, ArcAnkle(*plan, phase(j), X_WP_at[j]), SwingPitch(*plan, phase(j))));
        const double pitch = a.pitch;  // the foot's pitch as Evaluate tilts it
        const Vec2xz a_P = legs_.Ankle(plan->swing, a);
        const Vec2 ankle_H = ToH(*plan, X_WP_at[j].translation()) + Vec2(a_P.x(), a_P.y());
        const double sole_deficit =
            j == kSwingChecks ? -std::numeric_limits<double>::infinity()
                              : SoleDeficit(profile, ankle_H, pitch, sole, kSwingClearance_m, own_from, own_to,
                                            moved(ankle_H, pitch, last_ankle, last_pitch));
        // the shank too: it leans back over the edge a descending foot has just passed
        std::vector<Vec2> shank_H = legs_.ShankHull(plan->swing, a);
        const Vec2 pelvis_H = ToH(*plan, X_WP_at[j].translation());
        for (Vec2& p : shank_H) p += pelvis_H;
        const double shank_deficit = ShankDeficit(profile, shank_H, kShankClearance_m);
        const double deficit = std::max(sole_deficit, shank_deficit);
        sized.worst = std::max(sized.worst, deficit);
        sized.shank_worst = std::max(sized.shank_worst, shank_deficit);
        const auto [heel, toe] = SoleEnds(ankle_H, pitch, sole);
        sized.peak_above_m = std::max(sized.peak_above_m, std::min(heel.y(), toe.y()) - plan->highest_ground_z_m);
        if (deficit > kClearanceSlack_m) more = std::max(more, deficit / std::max(SwingArc::LiftShape(u), kLiftShapeFloor));
        last_ankle = ankle_H;
        last_pitch = pitch;
      }
      if (more == 0 || round == kLiftRounds) break;
      arc->lift_m += more;
    }
    return sized;
  };
  // the default arc first; when its lift would carry the sole above the cap,
  // an arc that climbs sooner or descends later (the sole then clears the edge
  // next to its lift-off without a plateau sized for it): the first that fits,
  // else the lowest that clears
  const SwingArc base = arc;
  SwingArc best = arc;
  Sized best_sized = size_lift(&best);
  const auto clears = [](const Sized& z) { return z.worst <= kClearanceSlack_m + 1e-3; };
  const auto fits = [&](const Sized& z) { return clears(z) && z.peak_above_m <= kMaxLiftAboveGround_m - kLiftCapMargin_m; };
  for (const ArcShape& shape : kSoonerArcs) {
    if (fits(best_sized)) break;
    SwingArc sooner = base;
    sooner.height_span = shape.height_span;
    sooner.carry_start = shape.carry_start;
    sooner.hold_pitch = shape.hold_pitch;
    const Sized z = size_lift(&sooner);
    if ((clears(z) && !clears(best_sized)) || (clears(z) && z.peak_above_m < best_sized.peak_above_m)) {
      best = sooner;
      best_sized = z;
    }
  }
  plan->swing_arc = best;
  if (!clears(best_sized)) {
    if (best_sized.shank_worst >= best_sized.worst)
      std::snprintf(text, sizeof text, "the swing shank cannot clear the ground on its way to the foothold %.2f m "
                    "ahead (%.0f mm short): it would strike an edge", foothold.s_heel_m, 1e3 * best_sized.worst);
    else
      std::snprintf(text, sizeof text, "the swing foot cannot clear the ground on its way to the foothold %.2f m "
                    "ahead (%.0f mm short)", foothold.s_heel_m, 1e3 * best_sized.worst);
    plan->cannot_step = text;
    return best_sized.shank_worst >= best_sized.worst;
  }
  return false;
}

double DefaultMaxStep_m(const BipedLegs& legs, double k) {
  // steady walking's landing, then the same landing raised until the knee bends to the limit
  const StepPlanner flat(legs);
  StepPlan plan = flat.FirstStep(Vec3::Zero(), 0.0, k);
  for (int step = 0; step < 4; ++step) plan = flat.NextStep(plan, k, 0.0);
  const LegAnglesRad land = flat.Evaluate(plan, 0.5).swing;
  const Vec2xz ankle = legs.Ankle(plan.swing, land);
  double lo = 0, hi = legs.leg_length_m();
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (legs.SolveAnkle(plan.swing, ankle + Vec2xz(0, mid), land.pitch).knee < kMaxKneeFlexion_rad ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace proxsim
