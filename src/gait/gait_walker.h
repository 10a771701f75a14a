// Kinematic walking of any biped along a path of waypoints (docs/robots.md,
// "The gait"): the steps of gait_steps.h chained in time, on the legs
// that robot.legs maps (gait/leg_kinematics.h) with every other joint held
// (robot.joints_deg), with the cycle time `period_s` and the curve amplitude
// chosen so that the stride is `stride_m`, heading changes at heel strikes
// (toward the current waypoint, at most kMaxTurnPerStep_rad per step, or up
// to kMaxSharpTurnPerStep_rad when the waypoint lies inside the circle the
// smaller turns would walk), and a stop at a heel strike — a double support
// with both feet down — when asked or when the last waypoint is reached.
//
// Waypoints: the current one is passed at a heel strike by the rule of
// gait/waypoint_rule.h (within half a stride of it, or beyond the line
// through it square to the way it was approached), which strategies ask
// too. The last is reached when the pelvis is within a quarter stride of it,
// or within a stride and one more step (toward it) would not bring the
// pelvis closer.
//
// Stride and period: as the gait section gives them, or, where it does not,
// the built-in biped's 0.6 m and 1.2 s scaled to this robot's leg length L
// (hip joint to sole) by dynamic similarity (the same Froude number):
// stride ∝ L, period ∝ √L.
//
// Time: a gait clock runs while walking and stands still while stopped; the
// left leg's phase is clock / period_s, 0 at its heel strike. The walk starts at
// t = the first Advance() time, in a left heel strike with the pelvis above
// `start_xyz_m` (whose z is the floor height), heading `start_yaw_rad`.
//
// Stride: the amplitude k of the curves (1 = the normative adult gait) sets
// the stride; k is found by bisection on the steady stride of straight walking
// for this robot's legs at load, and by interpolation in a table of sampled
// amplitudes for a stride set while walking (gait/stride_table.h). A stride beyond what k ∈ [0.05, 1.6] can give is
// clamped: achieved_stride_m() says what is walked. A new stride takes effect
// at the next heel strike, ramped in over the double support.
//
// Uneven ground (docs/terrain.md): with a terrain (SetTerrain), every step lands on a
// foothold planned on the scene's true surface (gait_steps.h, "Uneven
// ground"), and the robot stands on the surface below its start point (a
// start above no surface walks on a flat floor at its start height, as
// without a terrain). A step longer than a stride or shorter than a quarter
// of one is not planned, nor one up or down more than gait.max_step_m (by
// default what the legs reach with the knee bent kMaxKneeFlexion_rad). When
// the next step has no foothold, the robot stops before it, at the heel
// strike (both feet down), and reports `cannot_step` with the reason; it
// tries again when resumed or given a new path.
//
// Footholds on what the robot knows (`gait.footholds: map`, docs/terrain.md):
// with a footholds terrain (SetTerrain's second), every step is planned on it
// instead — where it knows nothing, level with the stance foot — while the
// robot still starts on the true surface, and at each heel strike the landed
// foot is felt on the true surface (gait/touchdown.h): it settles where it
// rests (the next step starts from there; its pelvis does not jump, the
// stance leg takes up the difference), or the walker reports a `fall` event
// with the reason and stands. The planted feet stand where they were felt:
// under them the planner reads that height, not the map's (gait/felt_ground.h).
//
// Joint limits (docs/robots.md): every step is checked before it is taken by
// UnsafeStepReason (gait/step_safety.h): a step that would take a joint
// outside its URDF range or beyond its top speed, fold a leg, or lift a foot
// far above what it clears is refused the same way (`cannot_step`, the joint,
// the angle or speed needed and the limit), so that no sample ever holds an
// impossible pose; a step is slowed rather than refused for its joints'
// speeds. A gait the legs cannot walk on level ground is an input
// error at load (gait/level_gait_check.h).
#pragma once

#include <memory>

#include "gait/felt_ground.h"
#include "gait/gait_steps.h"
#include "gait/joint_limits.h"
#include "gait/locomotion.h"
#include "gait/gait_config.h"
#include "gait/step_safety.h"
#include "gait/stride_table.h"
#include "gait/waypoint_rule.h"

namespace proxsim {

/// The built-in biped's leg length (hip joint to sole), stride and period: the reference of the scaled defaults.
constexpr double kReferenceLegLength_m = 0.98;
constexpr double kReferenceStride_m = 0.6;
constexpr double kReferencePeriod_s = 1.2;

class GaitWalker : public Locomotion {
 public:
  /// Walks `model` as `config` says (legs, held joints, start, gait,
  /// waypoints). Throws InputError when the legs' map or the held joints do not
  /// fit the model (BipedLegs, HeldJointAngles) or the gait is invalid.
  GaitWalker(RobotModel model, const WalkConfig& config);

  RobotState Advance(double t_s) override;
  void RequestStop() override { stop_requested_ = true; }
  void Resume() override;
  void SetStride(double stride_m) override;
  void SetPath(std::vector<Vec2> waypoints_m) override;
  std::vector<FootFrame> Feet() const override;
  std::optional<GaitCycle> gait_cycle() const override {
    return GaitCycle{achieved_stride_m_, gait_.period_s, max_step_m_, legs_->crouch_knee_rad(), pelvis_height_m_,
                     k_target_, {legs_->leg(Side::kLeft).foot0_rad, legs_->leg(Side::kRight).foot0_rad}};
  }
  void SetTerrain(const TerrainQuery* ground, const TerrainQuery* footholds = nullptr) override;
  std::vector<LocomotionEvent> TakeEvents() override;
  void Reset() override;
  const RobotModel& model() const override { return *model_; }

  /// Curve amplitude in use for the requested stride.
  double amplitude() const { return k_target_; }
  /// Stride walked at that amplitude (equals the request unless it was out of reach), m.
  double achieved_stride_m() const { return achieved_stride_m_; }
  /// True once the last waypoint has been reached.
  bool path_done() const { return path_done_; }
  /// The current step (for tests and viewers: the latched pivots).
  const StepPlan& current_step() const { return plan_; }
  /// Stance phase in [0, 0.5] of the current step at the last Advance().
  double step_phase() const { return step_phase_; }
  /// The legs as the gait reads them from the model.
  const BipedLegs& legs() const { return *legs_; }

 private:
  // At the heel strike ending the current step: decide heading and stopping.
  bool DecideAtHeelStrike(const Pose& X_WP, double* yaw_to);
  // What one step may do on uneven ground, from the legs and the stride.
  FootholdLimits Limits() const;
  // How long `plan` lasts: half the period, longer for a terrain step that
  // must rise or fall slowly, or for any step whose joints would move too fast (step_safety.h).
  // `sampled` receives the step's speed windows, for Refusal to reuse.
  double Duration_s(const StepPlan& plan, StepWindows* sampled = nullptr) const;
  // Duration_s and Refusal, remembered across walkers of the same legs and
  // gait under `key` (StepKey; gait/gait_memo.h): a remembered duration
  // leaves `sampled` empty (NaN), for Refusal not to read another step's windows.
  double CheckedDuration_s(const std::string& key, const StepPlan& plan, StepWindows* sampled) const;
  std::string CheckedRefusal(const std::string& key, const StepPlan& plan, double duration_s,
                             const StepWindows* sampled) const;
  // The step checks' key of `plan`: step_memo_key_ and every field of the plan.
  std::string StepKey(const StepPlan& plan) const;
  // Why `plan` is not to be taken ("" if it is): no foothold (the planner's
  // reason) or a step beyond the legs' limits (UnsafeStepReason, the one place
  // that decides; today it is refused like the other, see gait.unsafe_steps).
  // `sampled`: the windows Duration_s sampled (used if at duration_s).
  std::string Refusal(const StepPlan& plan, double duration_s, const StepWindows* sampled = nullptr) const;
  /// duration_s, or longer when the joints would move too fast across the
  /// heel strike from the step in force to `next` (StrikeSpeedRatio).
  double StrikeLimitedDuration_s(const StepPlan& next, double duration_s) const;
  // The landed foot of plan_ (at its heel strike `strike`) felt on the true
  // ground: plan_'s landing moved to where it rests, or false after a `fall` event.
  bool SettleLanding(const StepPose& strike);
  // A planted sole: heel at p_W_heel, along heading yaw, resting at z_m.
  Footprint SoleAt(Side side, const Vec3& p_W_heel, double yaw, double z_m) const;
  // Logs `cannot_step` once per reason in a row.
  void NoteCannotStep(const std::string& reason, bool level_ground = false);

  // the episode's beginning, for Reset()
  WalkConfig initial_;
  double initial_k_ = 1;
  double initial_achieved_stride_m_ = 0;
  void Start();
  StrideTable stride_table_;
  std::string step_memo_key_;  // the legs and gait, for the step checks' memo (StepKey)
  StepWindows windows_;  // a step's sampled poses, kept to reuse their buffer

  std::unique_ptr<RobotModel> model_;  // stable address: legs_ and planner_ refer into it
  std::unique_ptr<BipedLegs> legs_;
  double pelvis_height_m_ = 0;  // root above the floor at a level heel strike (GaitCycle::pelvis_height_m)
  std::unique_ptr<LegLimits> limits_;  // the legs' URDF limits
  std::unique_ptr<StepPlanner> planner_;
  GaitConfig gait_;
  std::vector<double> q_held_;  // every joint's angle when the gait does not drive it
  std::vector<Vec2> waypoints_m_;
  std::size_t next_waypoint_ = 0;
  Vec2 path_origin_m_ = Vec2::Zero();  // where the robot was when its path was given
  double k_target_ = 1;
  double achieved_stride_m_ = 0;
  const TerrainQuery* terrain_ = nullptr;    // the true surface
  const TerrainQuery* footholds_ = nullptr;  // what the footholds are planned on, when not the true surface
  std::unique_ptr<FeltGround> felt_;          // footholds_ with the planted feet where the legs felt them
  bool landing_felt_ = false;                // plan_'s landing has been felt (footholds_ only)
  bool fell_ = false;                        // a landing could not stand: the walker stands for good
  double max_step_m_ = 0;             // highest step up or down (gait.max_step_m, or from the legs)
  std::vector<LocomotionEvent> events_;
  std::string last_cannot_step_;      // the reason last logged, until a step is taken
  StepPlan plan_;
  double step_duration_s_ = 0;     // the current step's duration (half a period, or longer: StepDuration_s)
  double step_start_clock_s_ = 0;  // gait clock at the current step's heel strike
  double clock_s_ = 0;
  double step_phase_ = 0;
  double last_t_s_ = 0;
  bool started_ = false;
  bool stopped_ = false;
  bool stop_requested_ = false;
  bool path_done_ = false;
  double distance_m_ = 0;
  Vec3 last_p_WP_ = Vec3::Zero();  // pelvis at the previous sample, for the distance walked
  bool has_last_p_WP_ = false;
};

}  // namespace proxsim
