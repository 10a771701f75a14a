// One step of the kinematic walk: from a heel strike of one foot (the stance
// foot) to the heel strike of the other (the swing foot), as a pure function
// of the stance phase p in [0, 0.5]. This is the planted-foot construction
// (docs/robots.md, "The gait"):
//  - The stance foot pivots on its heel until foot-flat, lies flat until
//    heel-off, then pivots on its toe. Each pivot is latched in the world: the
//    heel at heel strike, then the flat foot's link frame F (which gives the sole
//    point under the ankle and the toe exactly). The pelvis is the pivot minus the
//    pivot's position in the pelvis frame (FK of the stance leg), so the
//    contact point never slides and the pelvis height follows from geometry.
//  - The pelvis is upright; its heading turns toward the next waypoint while
//    the stance foot rolls on its heel only (the foot spins about its heel).
//  - The stance leg follows the scaled normative curves (gait_curves.h). At
//    heel strike its hip/knee differ a little from the curves (see the swing
//    leg); the difference is blended out over the double-support window
//    (p < 0.1), which keeps joint angles and pelvis height continuous.
//  - Push-off: at small amplitudes the curves' toe rocker lifts the pelvis
//    higher than the swing leg can reach down at its heel strike. The stance
//    foot's pitch after heel-off is then scaled by a gain g ≤ 1 chosen so that
//    at the other foot's heel strike the pelvis is no higher than the curves'
//    landing posture allows (PushOffGain).
//  - The other foot stays planted through the double support that follows
//    the heel strike (p < kDoubleSupportEnd): its toe is latched in the world
//    where it was at heel strike and the foot pitches about it (heel rising)
//    as the curves' toe-off does; the leg's hip and knee come from two-link
//    inverse kinematics to the ankle that this puts under the toe.
//  - From toe-off the swing leg's ankle follows the curves' ankle path in the
//    pelvis frame plus a correction and a clearance bump, solved by planar
//    two-link IK. The correction is a cubic Hermite blend from where the
//    planted foot left off at toe-off (position and velocity, so the joint
//    motion has no kink there) to a landing pose whose heel touches the floor
//    exactly at the next heel strike (the pelvis height there is known: the
//    stance foot is then on its latched toe). The bump is sized once per step
//    so that the sole clears the floor by kSwingClearance_m in mid-swing; a
//    per-sample guard lifts the foot if a sample would still go below the floor.
//  - Contact points are the legs' exact 3D foot points (BipedLegs::Point3),
//    so the latched pivots hold whatever the robot's joint offsets; the heel
//    strike is latched on the floor.
// Departures from a real gait: no hip roll or yaw (so during a turn the
// trailing toe, planted while the pelvis turns on the stance heel, slides
// sideways), the pelvis does not sway sideways.
//
// Uneven ground (docs/terrain.md; gait_steps_terrain.cc). With a terrain (the
// scene's true surface, gait/terrain_query.h), every step first finds its
// foothold on the ground profile along the swing foot's line
// (gait/footstep_planner.h), nearest the heel the curves would land. When
// that is where the curves land, on the stance foot's level, with nothing
// under the swing's sweep but that level, and the stance started from such a
// landing, the step is the flat-floor step above, unchanged. Otherwise it is
// a terrain step:
//  - The pelvis height ramps from where it was at heel strike to the curves'
//    height above the stance tread at the next heel strike, lowered by the
//    fall of the step when stepping down (and further when a long step needs
//    it to reach), with a trapezoidal speed profile; its offset along the
//    heading from the curves' pelvis fades out. The stance leg reaches that
//    pelvis by two-link IK from its latched pivot (heel → flat → toe as
//    above, on any tread height), so the pivot never slides and the pelvis
//    follows the stance leg up and down.
//  - The swing leg lands its heel on the foothold at the curves' landing pitch,
//    by two-link IK; from toe-off its ankle follows a lift–carry–lower arc
//    (gait/swing_arc.h) whose lift is sized, against the ground profile, so
//    that the sole clears every edge it passes over by kSwingClearance_m.
//  - A step whose pelvis must rise or fall faster than kMaxPelvisRampSpeed_m_s
//    lasts longer (StepDuration_s).
//  - No dead ends: unless the ground ahead is level, the foothold is one from
//    which the next two steps can be taken — the other foot's, and the one
//    whose toe-off and swing leave this foothold, both planned here (their
//    arcs sized against the ground) at this step's amplitude and heading. A
//    foothold whose own swing, or either of those, cannot clear the ground
//    (a trailing toe left against a riser it cannot lift over) gives way to
//    the next of PlanFootholds' choices (kFootholdChoices, kFootholdSpacing_m
//    apart); when none passes, the first is kept.
// A step with no foothold within reach (a rise or fall beyond max_rise_m, a
// gap wider than a stride lets a step cross) carries the reason in
// `cannot_step`; the walker does not take it.
#pragma once

#include <string>

#include "gait/footstep_planner.h"
#include "gait/leg_kinematics.h"
#include "gait/swing_arc.h"
#include "gait/terrain_query.h"

namespace proxsim {

class LegLimits;

/// Minimum sole clearance aimed at in mid-swing, metres.
constexpr double kSwingClearance_m = 0.02;
/// End of double support and of the blends that start at heel strike (stance phase).
constexpr double kDoubleSupportEnd = kToeOffPhase - 0.5;
/// Most knee flexion the gait asks of a leg on uneven ground, rad.
constexpr double kMaxKneeFlexion_rad = DegToRad(100.0);
/// Peak vertical speed of a terrain step's pelvis ramp; a larger rise or fall slows the step, m/s.
constexpr double kMaxPelvisRampSpeed_m_s = 0.3;

/// Everything latched at one heel strike for the step that follows.
struct StepPlan {
  Side stance = Side::kLeft;
  Side swing = Side::kRight;
  double k_from = 1, k_to = 1;          ///< curve amplitude, ramped over [0, kDoubleSupportEnd]
  double g_from = 1, g_to = 1;          ///< push-off gain (PushOffGain of k), ramped likewise
  double yaw_from = 0, yaw_to = 0;      ///< pelvis heading, ramped over [0, foot-flat)
  double floor_z_m = 0;                 ///< floor height
  Vec3 p_W_heel = Vec3::Zero();         ///< stance heel latched at heel strike
  LegAnglesRad stance_offset;           ///< stance hip/knee minus curves at heel strike
  Pose X_WF = Pose::Identity();         ///< stance foot link's frame once flat (foot-flat to toe-off)
  bool flat_latched = false;            ///< X_WF is set (always, once a plan is finished)
  Vec3 p_W_trailing_toe = Vec3::Zero();       ///< the other foot's toe, latched at heel strike, planted until toe-off
  double swing_start_pitch = 0;               ///< swing foot pitch correction at p = 0
  Vec2xz swing_toe_off_delta = Vec2xz::Zero();  ///< swing ankle correction at toe-off, pelvis frame
  Vec2xz swing_toe_off_rate = Vec2xz::Zero();   ///< its rate over the swing (d/du, u from 0 at toe-off to 1 at heel strike)
  Vec2xz swing_end_delta = Vec2xz::Zero();    ///< swing ankle correction at p = 0.5
  double clearance_bump_m = 0;                ///< height of the mid-swing bump
  // uneven ground (docs/terrain.md)
  double landing_z_m = 0;        ///< height of the tread the swing heel lands on (floor_z_m on flat ground)
  bool natural_landing = true;   ///< the swing lands where the curves put it, on the stance's level
  bool terrain = false;          ///< a terrain step (see above); false: the flat-floor step
  /// refused by the look-ahead on level ground: from every foothold within
  /// reach a step after it cannot be taken (cannot_step says which and why)
  bool dead_end = false;
  std::string cannot_step;       ///< not empty: no foothold within reach, and why; the step is not to be taken
  double pelvis_x0_offset_m = 0;  ///< terrain: pelvis ahead of the curves' pelvis at heel strike (faded out)
  double pelvis_z0_m = 0;         ///< terrain: pelvis height at heel strike
  double pelvis_z1_m = 0;         ///< terrain: pelvis height at the next heel strike
  Vec3 p_W_H = Vec3::Zero();      ///< terrain: origin of the heading frame H (the stance heel, at z = 0)
  SwingArc swing_arc;             ///< terrain: the swing ankle's arc in H (H's x along yaw_to)
  double foothold_s_m = 0;        ///< terrain: the landing heel along H's x
  /// The highest ground the swing foot passes over, from the tread it leaves
  /// to the one it lands on, both included (floor_z_m on a flat floor), m:
  /// the swing sole never rises more than kMaxLiftAboveGround_m above it (gait/step_safety.h)
  double highest_ground_z_m = 0;
};

/// The robot at one stance phase of a step.
struct StepPose {
  Pose X_WP = Pose::Identity();  ///< pelvis
  LegAnglesRad stance, swing;
};

/// Computes steps for one biped.
class StepPlanner {
 public:
  explicit StepPlanner(const BipedLegs& legs) : legs_(legs) {}

  /// The ground the feet stand on (null: a flat floor at the start height)
  /// and what one step can do on it; `terrain` must outlive the planner.
  void set_terrain(const TerrainQuery* terrain, const FootholdLimits& limits) {
    terrain_ = terrain;
    limits_ = limits;
  }
  /// The legs' URDF limits the look-ahead of a terrain step holds the steps
  /// after it to, at the gait's period (null: none; OnwardSwingsClear);
  /// `limits` must outlive the planner. `memo_key`: the walker's key of its
  /// step checks (gait/gait_memo.h), under which the look-ahead's checks are
  /// remembered too (the walker's check of the step, when it comes, is then
  /// the look-ahead's answer).
  void set_leg_limits(const LegLimits* limits, double period_s, std::string memo_key) {
    leg_limits_ = limits;
    period_s_ = period_s;
    memo_key_ = std::move(memo_key);
  }
  const TerrainQuery* terrain() const { return terrain_; }
  const FootholdLimits& limits() const { return limits_; }

  /// The first step: left heel strike with the pelvis above (x, y) of p_W_start
  /// (its z is the floor), heading yaw, curves at amplitude k.
  StepPlan FirstStep(const Vec3& p_W_start, double yaw_rad, double k) const;
  /// The step after `prev`, from its heel strike (prev at p = 0.5): amplitude
  /// ramps to k_to and heading to yaw_to.
  StepPlan NextStep(const StepPlan& prev, double k_to, double yaw_to) const;
  /// The robot at stance phase p in [0, 0.5] of a step.
  StepPose Evaluate(const StepPlan& plan, double p) const;

  const BipedLegs& legs() const { return legs_; }

 private:
  double Amplitude(const StepPlan& plan, double p) const;
  LegAnglesRad StanceAngles(const StepPlan& plan, double p) const;
  Pose StancePelvis(const StepPlan& plan, double p, const LegAnglesRad& stance) const;
  // The curves' swing-leg angles at p (half a cycle on from the stance's).
  LegAnglesRad SwingCurve(const StepPlan& plan, double p) const;
  // The swing foot's pitch at p (given SwingCurve(plan, p): the same answer).
  double SwingPitch(const StepPlan& plan, double p) const;
  double SwingPitch(const StepPlan& plan, double p, const LegAnglesRad& swing_curve) const;
  // The ankle (P) that keeps the planted trailing toe at its latched point,
  // pelvis at X_WP (given the swing pitch at p: the same answer).
  Vec2xz PlantedAnkle(const StepPlan& plan, double p, const Pose& X_WP) const;
  Vec2xz PlantedAnkle(const StepPlan& plan, const Pose& X_WP, double swing_pitch) const;
  // The swing ankle target (P) from toe-off on, before the floor guard, given SwingCurve(plan, p).
  Vec2xz SwingAnkle(const StepPlan& plan, double p, const LegAnglesRad& swing_curve) const;
  // Latches X_WF, the landing correction and the clearance bump.
  void Finish(StepPlan* plan) const;

  // NextStep; check_onward: whether its foothold is checked for the swings that follow (PlanOnTerrain).
  StepPlan PlanNextStep(const StepPlan& prev, double k_to, double yaw_to, bool check_onward) const;

  // uneven ground (gait_steps_terrain.cc)
  // Plans the foothold of a finished flat-floor plan on the terrain and makes
  // it a terrain step when it has to be; p_WP_strike: the pelvis at heel strike.
  // check_onward: unless the ground ahead is level, the foothold is one from
  // which the next two steps (OnwardSwingsClear) can be taken, if any is.
  void PlanOnTerrain(StepPlan* plan, bool stance_from_natural_landing, const Vec3& p_WP_strike,
                     bool check_onward) const;
  // Lands the finished flat-floor plan `plan` on `foothold` (PlanOnTerrain's
  // step once its foothold is chosen); s_natural_m and s_trailing_toe_m: the
  // curves' landing heel and the trailing toe along the profile's line.
  void LandOn(StepPlan* plan, const Foothold& foothold, const TerrainProfile& profile, double s_natural_m,
              double s_trailing_toe_m, bool stance_from_natural_landing, const Vec3& p_WP_strike) const;
  // Whether the two steps after `plan` can be taken, at its amplitude and
  // heading: the other foot's, and the one whose swing leaves `plan`'s
  // foothold (its toe-off and its arc clear the ground). A step finding no
  // foothold within reach does not count against it (the look-ahead of
  // PlanFootholds sees those); a step its swing cannot clear, whose landing
  // the legs cannot reach, or (with leg limits) that the walker would refuse
  // for them (`plan` itself included: LimitsReason), does. `why`: the first
  // such step's reason.
  bool OnwardSwingsClear(const StepPlan& plan, std::string* why) const;
  // Why `plan` is beyond the legs' limits at the duration the walker would
  // give it for its joints' speeds (UnsafeStepReason at SpeedLimitedDuration_s,
  // gait/step_safety.h; "" when it is not, or without leg limits).
  std::string LimitsReason(const StepPlan& plan) const;
  // Makes `plan` a terrain step landing on `foothold`. Returns whether the
  // swing's shank, not its sole, kept it from clearing the ground (a foothold
  // further along the same tread may then clear it).
  bool FinishTerrain(StepPlan* plan, const Foothold& foothold, const TerrainProfile& profile,
                     const Vec3& p_WP_strike) const;
  // A terrain step's stance leg at p: two-link IK from its pivot to the pelvis ramp.
  LegAnglesRad TerrainStanceAngles(const StepPlan& plan, double p) const;
  // The curves' stance angles at p, without the heel-strike offset.
  LegAnglesRad CurveStanceAngles(const StepPlan& plan, double p) const;
  // A terrain step's swing ankle (P) at p >= kDoubleSupportEnd, pelvis at X_WP.
  Vec2xz ArcAnkle(const StepPlan& plan, double p, const Pose& X_WP) const;

  const BipedLegs& legs_;
  const TerrainQuery* terrain_ = nullptr;
  FootholdLimits limits_;
  const LegLimits* leg_limits_ = nullptr;
  double period_s_ = 0;
  std::string memo_key_;
};

/// How long a step lasts: half the period, longer for a terrain step whose
/// pelvis would otherwise rise or fall faster than kMaxPelvisRampSpeed_m_s.
double StepDuration_s(const StepPlan& plan, double period_s);

/// The highest step up (or down) the legs take from steady walking at
/// amplitude k: the rise at which the landing knee bends kMaxKneeFlexion_rad, m.
double DefaultMaxStep_m(const BipedLegs& legs, double k);

/// Push-off gain for amplitude k (1 when the curves need no reduction).
double PushOffGain(const BipedLegs& legs, Side stance, double k);

/// The stride (distance between two heel strikes of the same foot) of steady
/// straight walking at curve amplitude k, metres.
double SteadyStride_m(const StepPlanner& planner, double k);

}  // namespace proxsim
