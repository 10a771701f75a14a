#include "gait/gait_walker.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "core/input_error.h"
#include "gait/gait_memo.h"
#include "gait/held_joints.h"
#include "gait/level_gait_check.h"
#include "gait/step_safety.h"
#include "gait/touchdown.h"

namespace proxsim {

namespace {

double WrapAngle(double a) { return std::remainder(a, 2 * kPi); }

// A felt landing this close to the planned tread is on it, m: a map holds its
// heights in float (an ideal sensor's tread is exact to about 1e-7 m), and the
// step planned on it stays the step planned.
constexpr double kSettleTolerance_m = 1e-5;

// robot.joints_deg, preceded by the keyframe's angle for every other joint the
// legs do not drive (a hinge: the angles held are revolute ones), so that the
// robot holds its arms and torso as its makers posed them
std::vector<std::pair<std::string, double>> HeldWithKeyframe(const RobotModel& model, const WalkConfig& config,
                                                             const RobotKeyframe* key) {
  if (key == nullptr) return config.joints_rad;
  const std::array<LegNames, 2> legs = config.legs.value_or(BuiltinBipedLegs());
  std::vector<std::pair<std::string, double>> held;
  for (const int j : model.MovingJoints()) {
    const RobotJoint& joint = model.joint(j);
    if (joint.type != JointType::kRevolute && joint.type != JointType::kContinuous) continue;
    bool skip = false;
    for (const LegNames& leg : legs) skip = skip || joint.name == leg.hip || joint.name == leg.knee || joint.name == leg.ankle;
    for (const auto& given : config.joints_rad) skip = skip || joint.name == given.first;
    if (!skip && key->q_by_joint[j] != 0.0) held.emplace_back(joint.name, key->q_by_joint[j]);
  }
  held.insert(held.end(), config.joints_rad.begin(), config.joints_rad.end());
  return held;
}

}  // namespace

GaitWalker::GaitWalker(RobotModel model, const WalkConfig& config)
    : initial_(config), model_(std::make_unique<RobotModel>(std::move(model))), gait_(config.gait) {
  std::vector<std::string> problems;
  if (!config.gait.derive_period_from_legs && !(gait_.period_s > 0))
    problems.push_back(model_->source() + ": gait period_s must be > 0");
  if (!config.gait.derive_stride_from_legs && !(gait_.stride_m > 0))
    problems.push_back(model_->source() + ": gait stride_m must be > 0");
  if (!problems.empty()) throw InputError(problems);
  // the keyframe the gait takes its pose from, if one is named
  const RobotKeyframe* key = nullptr;
  if (!config.gait.keyframe.empty()) {
    key = model_->Keyframe(config.gait.keyframe);
    if (key == nullptr) {
      std::string known;
      for (const RobotKeyframe& k : model_->keyframes()) known += (known.empty() ? "" : ", ") + ("'" + k.name + "'");
      problems.push_back(model_->source() + ": gait.keyframe: no keyframe '" + config.gait.keyframe + "' in the model (" +
                         (known.empty() ? std::string("it has none: keyframes are an MJCF's <keyframe><key name=...>")
                                        : "its keyframes: " + known) +
                         ")");
      throw InputError(problems);
    }
  }
  // the held joints and the legs, their problems reported together
  try {
    q_held_ = HeldJointAngles(*model_, HeldWithKeyframe(*model_, config, key), config.legs.value_or(BuiltinBipedLegs()));
  } catch (const InputError& error) {
    problems = error.problems();
    q_held_.assign(model_->joint_count(), 0.0);
  }
  try {
    legs_ = std::make_unique<BipedLegs>(*model_, config.legs, q_held_);
  } catch (const InputError& error) {
    problems.insert(problems.end(), error.problems().begin(), error.problems().end());
  }
  if (!problems.empty()) throw InputError(problems);
  // the crouch: given, or the keyframe's knee bend (the mean of its legs'), else none
  double crouch_rad = 0.0;
  if (config.gait.crouch_knee_rad) {
    crouch_rad = *config.gait.crouch_knee_rad;
  } else if (key != nullptr) {
    crouch_rad = std::max(0.0, 0.5 * (legs_->ReadJoints(Side::kLeft, key->q_by_joint).knee +
                                      legs_->ReadJoints(Side::kRight, key->q_by_joint).knee));
  }
  legs_->SetCrouch(crouch_rad);
  limits_ = std::make_unique<LegLimits>(*legs_);
  planner_ = std::make_unique<StepPlanner>(*legs_);
  // stride and period not given: the built-in biped's, scaled to these legs
  // (the ratio is exactly 1 for the built-in biped, whose defaults stay exact)
  const double length_ratio = std::abs(legs_->leg_length_m() - kReferenceLegLength_m) < 1e-9
                                  ? 1.0
                                  : legs_->leg_length_m() / kReferenceLegLength_m;
  if (config.gait.derive_stride_from_legs) initial_.gait.stride_m = kReferenceStride_m * length_ratio;
  if (config.gait.derive_period_from_legs) initial_.gait.period_s = kReferencePeriod_s * std::sqrt(length_ratio);
  gait_ = initial_.gait;
  // the exact amplitude search runs once; Reset() and SetStride() reuse its
  // answer, and so does the next walker built from the same legs and gait in
  // this process (a study's episodes: gait/gait_memo.h)
  const std::string memo_key = GaitSearchKey(legs_->Fingerprint(), initial_.gait.stride_m, initial_.gait.period_s);
  step_memo_key_ = memo_key;
  // (the look-ahead of a terrain step holds the steps after it to the legs'
  // limits, its checks remembered under the walker's key)
  planner_->set_leg_limits(limits_.get(), gait_.period_s, step_memo_key_);
  const std::optional<AmplitudeStride> remembered = RememberedGait(memo_key);
  const AmplitudeStride loaded = remembered ? *remembered : BisectAmplitude(*planner_, initial_.gait.stride_m);
  stride_table_.AddExact(initial_.gait.stride_m, loaded);
  if (!remembered) {
    CheckLevelGait(*planner_, *limits_, model_->source(), initial_.gait.stride_m, initial_.gait.period_s, loaded);
    RememberGait(memo_key, loaded);
  }
  initial_k_ = loaded.k;
  pelvis_height_m_ = -legs_->Point3(Side::kLeft, legs_->Curve(0.0, loaded.k), FootPoint::kHeel).z();
  initial_achieved_stride_m_ = loaded.stride_m;
  // (the default, like the amplitude it is found at, a function of the search key)
  if (config.gait.max_step_m > 0) {
    max_step_m_ = config.gait.max_step_m;
  } else if (const std::optional<double> known = RememberedMaxStep(memo_key)) {
    max_step_m_ = *known;
  } else {
    max_step_m_ = DefaultMaxStep_m(*legs_, initial_k_);
    RememberMaxStep(memo_key, max_step_m_);
  }
  Start();
}

FootholdLimits GaitWalker::Limits() const {
  double sole_m = 0;
  for (const Side side : {Side::kLeft, Side::kRight}) sole_m = std::max(sole_m, legs_->leg(side).toe_x_m - legs_->leg(side).heel_x_m);
  return FootholdLimits{.sole_length_m = sole_m,
                        .margin_m = 0.01,
                        .min_step_m = 0.25 * achieved_stride_m_,
                        .max_step_m = achieved_stride_m_,
                        .max_rise_m = max_step_m_};
}

void GaitWalker::SetTerrain(const TerrainQuery* ground, const TerrainQuery* footholds) {
  terrain_ = ground;
  footholds_ = ground != nullptr ? footholds : nullptr;
  felt_ = footholds_ != nullptr ? std::make_unique<FeltGround>(*footholds_) : nullptr;
  Start();
}

bool GaitWalker::SettleLanding(const StepPose& strike) {
  if (footholds_ == nullptr || landing_felt_) return true;
  landing_felt_ = true;
  const LegGeometry& leg = legs_->leg(plan_.swing);
  LandedSole sole;
  for (const FootPoint point : {FootPoint::kHeel, FootPoint::kMid, FootPoint::kToe})
    sole.p_W[static_cast<int>(point)] = strike.X_WP * legs_->Point3(plan_.swing, strike.swing, point);
  sole.across_W = strike.X_WP.linear().col(1);
  sole.half_width_m = leg.half_width_m;
  sole.side = plan_.swing == Side::kLeft ? "left" : "right";
  const Touchdown touchdown =
      FeelTouchdown(*terrain_, sole, plan_.landing_z_m, gait_.touchdown_tolerance_m, legs_->leg_length_m());
  if (touchdown.fell) {
    fell_ = true;
    events_.push_back({"fall", touchdown.reason, sole.p_W[static_cast<int>(FootPoint::kMid)]});
    return false;
  }
  // the next step starts from where the foot rests: a terrain step, whose
  // pelvis ramps on from where it is (gait_steps.h)
  if (std::abs(touchdown.rest_z_m - plan_.landing_z_m) > kSettleTolerance_m) {
    plan_.landing_z_m = touchdown.rest_z_m;
    plan_.natural_landing = false;
  }
  // the next step is planned with both feet where they stand: the landed one
  // (flat about its heel), and the one it leaves, flat where it was latched
  const Vec3 p_W_old_heel = plan_.X_WF * legs_->FootPoint_L(plan_.stance, FootPoint::kHeel);
  felt_->set_footprints({SoleAt(plan_.swing, sole.p_W[0], plan_.yaw_to, plan_.landing_z_m),
                         SoleAt(plan_.stance, p_W_old_heel, plan_.yaw_to, plan_.floor_z_m)});
  return true;
}

Footprint GaitWalker::SoleAt(Side side, const Vec3& p_W_heel, double yaw, double z_m) const {
  const LegGeometry& leg = legs_->leg(side);
  const Vec3 along(std::cos(yaw), std::sin(yaw), 0);
  return Footprint{.p_W_heel = p_W_heel,
                   .p_W_toe = p_W_heel + (leg.toe_x_m - leg.heel_x_m) * along,
                   .half_width_m = leg.half_width_m,
                   .z_m = z_m};
}

std::vector<LocomotionEvent> GaitWalker::TakeEvents() {
  std::vector<LocomotionEvent> events;
  events.swap(events_);
  return events;
}

namespace {
// Steps tried in turn at a heel strike: {share of the turn asked for, share of
// the stride}; the first is the step asked for, the last a short one that
// turns a little (what a person does when a step feels wrong).
constexpr std::array<std::pair<double, double>, 7> kGentlerSteps = {
    {{1.0, 1.0}, {0.5, 1.0}, {1.0, 0.7}, {0.5, 0.7}, {1.0, 0.5}, {0.5, 0.5}, {0.25, 0.35}}};

// Whether a step found its foothold (a refusal after that is the legs' or
// the swing's clearance, or a dead end the look-ahead saw, not a missing floor).
bool FootholdFound(const StepPlan& plan) { return plan.cannot_step.empty() || plan.terrain || plan.dead_end; }

// Whether a step passes over level ground only (its stance's floor, its
// landing and the highest ground under its swing within a centimetre): a
// step refused there is refused by the legs' own limits, not by the terrain.
bool OnLevelGround(const StepPlan& plan) {
  constexpr double kLevel_m = 0.01;
  return FootholdFound(plan) && std::abs(plan.landing_z_m - plan.floor_z_m) < kLevel_m &&
         std::abs(plan.highest_ground_z_m - plan.floor_z_m) < kLevel_m;
}
// Rounds of slowing a step for its joints' speeds across its heel strike, and
// the least each slows it by.
constexpr int kStrikeSlowingRounds = 8;
constexpr double kStrikeSlowingMin = 1.05;
}  // namespace

double GaitWalker::Duration_s(const StepPlan& plan, StepWindows* sampled) const {
  // a step whose joints would move too fast (a sharp turn, a change of
  // stride, a step up) is slowed; steady walking is not (the load checked it)
  return SpeedLimitedDuration_s(*planner_, *limits_, plan, StepDuration_s(plan, gait_.period_s), sampled);
}

double GaitWalker::StrikeLimitedDuration_s(const StepPlan& next, double duration_s) const {
  // the joints across the heel strike that starts `next`: the step in force
  // is fixed, so only the new one can be slowed (speeds there scale less than
  // 1/duration: a few rounds); steady walking is within the limits there too
  // (the load's check), and keeps its duration
  for (int round = 0; round < kStrikeSlowingRounds; ++round) {
    const double ratio = StrikeSpeedRatio(*planner_, *limits_, plan_, step_duration_s_, next, duration_s);
    if (ratio <= 1.0) break;
    duration_s *= std::max(ratio / kSpeedMargin, kStrikeSlowingMin);
  }
  return duration_s;
}

std::string GaitWalker::StepKey(const StepPlan& plan) const {
  // (step_memo_key_ holds the period Duration_s reads: it is the walker's for life)
  return step_memo_key_ + StepPlanBytes(plan);
}

double GaitWalker::CheckedDuration_s(const std::string& key, const StepPlan& plan, StepWindows* sampled) const {
  if (const std::optional<double> known = RememberedStepDuration(key)) {
    sampled->duration_s = std::numeric_limits<double>::quiet_NaN();
    return *known;
  }
  const double duration_s = Duration_s(plan, sampled);
  RememberStepDuration(key, duration_s);
  return duration_s;
}

std::string GaitWalker::CheckedRefusal(const std::string& key, const StepPlan& plan, double duration_s,
                                       const StepWindows* sampled) const {
  if (std::optional<std::string> known = RememberedStepRefusal(key, duration_s)) return std::move(*known);
  std::string refusal = Refusal(plan, duration_s, sampled);
  RememberStepRefusal(key, duration_s, refusal);
  return refusal;
}

std::string GaitWalker::Refusal(const StepPlan& plan, double duration_s, const StepWindows* sampled) const {
  if (!plan.cannot_step.empty()) return plan.cannot_step;
  return UnsafeStepReason(*planner_, *limits_, plan, duration_s, sampled);
}

void GaitWalker::NoteCannotStep(const std::string& reason, bool level_ground) {
  if (reason == last_cannot_step_) return;
  last_cannot_step_ = reason;
  events_.push_back({"cannot_step", reason, std::nullopt, level_ground});
}

void GaitWalker::Start() {
  gait_ = initial_.gait;
  waypoints_m_ = initial_.waypoints_m;
  next_waypoint_ = 0;
  path_origin_m_ = initial_.start_xyz_m.head<2>();
  k_target_ = initial_k_;
  achieved_stride_m_ = initial_achieved_stride_m_;
  events_.clear();
  last_cannot_step_.clear();
  // on a terrain, the robot stands on the surface below its start; above no
  // surface it walks on a flat floor at its start height. (Whatever lies below:
  // sim/start_check.h refuses, before the run, a start this puts on an object
  // that is not ground, unless robot.start.on names it.)
  Vec3 start = initial_.start_xyz_m;
  const TerrainQuery* terrain = terrain_;
  if (terrain != nullptr) {
    const double reach_m = 2 * legs_->leg_length_m();
    const Vec3 from = start + Vec3(0, 0, reach_m);
    double z = 0;
    terrain->HeightsBelow(std::span<const Vec3>(&from, 1), 2 * reach_m + 10.0, std::span<double>(&z, 1));
    if (!std::isfinite(z)) terrain = nullptr;
    else if (std::abs(z - start.z()) > kLevelTolerance_m) start.z() = z;
  }
  // the footholds on what the robot knows, when it plans on that (the start
  // stays the truth's), with both feet standing where the robot starts
  const bool on_map = terrain != nullptr && felt_ != nullptr;
  if (on_map) {
    planner_->set_terrain(nullptr, Limits());
    const StepPlan standing = planner_->FirstStep(start, initial_.start_yaw_rad, k_target_);
    const double yaw = initial_.start_yaw_rad;
    const LegGeometry& trailing = legs_->leg(standing.swing);
    const Vec3 p_W_trailing_heel =
        standing.p_W_trailing_toe - (trailing.toe_x_m - trailing.heel_x_m) * Vec3(std::cos(yaw), std::sin(yaw), 0);
    felt_->set_footprints({SoleAt(standing.stance, standing.p_W_heel, yaw, start.z()),
                           SoleAt(standing.swing, p_W_trailing_heel, yaw, start.z())});
  }
  planner_->set_terrain(on_map ? felt_.get() : terrain, Limits());
  plan_ = planner_->FirstStep(start, initial_.start_yaw_rad, k_target_);
  const std::string first_key = StepKey(plan_);
  step_duration_s_ = CheckedDuration_s(first_key, plan_, &windows_);
  step_start_clock_s_ = 0;
  clock_s_ = 0;
  step_phase_ = 0;
  last_t_s_ = 0;
  started_ = false;
  stopped_ = false;
  stop_requested_ = false;
  path_done_ = false;
  landing_felt_ = false;
  fell_ = false;
  distance_m_ = 0;
  last_p_WP_ = Vec3::Zero();
  has_last_p_WP_ = false;
  // no foothold for the first step, or an unsafe one: stand where it starts
  if (const std::string refusal = CheckedRefusal(first_key, plan_, step_duration_s_, &windows_); !refusal.empty()) {
    stopped_ = true;
    NoteCannotStep(refusal);
  }
}

void GaitWalker::SetStride(double stride_m) {
  // a stride already in force costs nothing; another is looked up, not searched
  if (!(stride_m > 0) || stride_m == gait_.stride_m) return;
  gait_.stride_m = stride_m;
  const AmplitudeStride walked = stride_table_.For(*planner_, stride_m);
  k_target_ = walked.k;
  achieved_stride_m_ = walked.stride_m;
  if (planner_->terrain() != nullptr) planner_->set_terrain(planner_->terrain(), Limits());
}

void GaitWalker::Resume() {
  if (fell_) return;  // fallen: nothing walks on
  stopped_ = false;
  stop_requested_ = false;
}

bool GaitWalker::DecideAtHeelStrike(const Pose& X_WP, double* yaw_to) {
  *yaw_to = plan_.yaw_to;
  if (stop_requested_) return true;
  if (waypoints_m_.empty()) return false;
  const Vec2 p = X_WP.translation().head<2>();
  const double stride = achieved_stride_m_, step = 0.5 * stride;
  next_waypoint_ = WaypointAhead(waypoints_m_, next_waypoint_, path_origin_m_, p, stride);
  const Vec2 to = waypoints_m_[next_waypoint_] - p;
  const double turn = TurnTowardRad(p, plan_.yaw_to, waypoints_m_[next_waypoint_], step);

  if (next_waypoint_ + 1 == waypoints_m_.size()) {
    // the last one: stop within a quarter stride, or within a stride when one
    // more step along the turned heading would not bring the pelvis closer
    const Vec2 heading(std::cos(plan_.yaw_to + turn), std::sin(plan_.yaw_to + turn));
    const bool closer = (to - step * heading).norm() < to.norm();
    if (to.norm() < 0.25 * stride || (to.norm() < stride && !closer)) {
      path_done_ = true;
      return true;
    }
  }
  *yaw_to = plan_.yaw_to + turn;
  return false;
}

RobotState GaitWalker::Advance(double t_s) {
  if (!started_) {
    started_ = true;
    last_t_s_ = t_s;
  }
  const double dt = std::max(0.0, t_s - last_t_s_);
  last_t_s_ = std::max(last_t_s_, t_s);
  if (!stopped_) {
    clock_s_ += dt;
    // heel strikes passed since the last sample
    while (clock_s_ >= step_start_clock_s_ + step_duration_s_) {
      const StepPose strike = planner_->Evaluate(plan_, 0.5);
      double yaw_to = 0;
      // (footholds on what the robot knows: the landed foot felt on the true ground first)
      bool stop = !SettleLanding(strike) || DecideAtHeelStrike(strike.X_WP, &yaw_to);
      StepPlan next;
      double next_duration_s = 0;
      if (!stop) {
        // the step asked for; beyond the legs' limits (a sharp turn at a long
        // stride), a gentler one: half the turn, then a shorter step (the turn
        // is finished over the following steps, the stride regained after)
        std::string refusal;
        for (const auto& [turn_share, k_share] : kGentlerSteps) {
          const double yaw = plan_.yaw_to + turn_share * WrapAngle(yaw_to - plan_.yaw_to);
          next = planner_->NextStep(plan_, k_target_ * k_share, yaw);
          // (the step's poses sampled once for its duration and its safety)
          const std::string key = StepKey(next);
          next_duration_s = StrikeLimitedDuration_s(next, CheckedDuration_s(key, next, &windows_));
          refusal = CheckedRefusal(key, next, next_duration_s, &windows_);
          // (no foothold within reach, or none the swing clears: a gentler step finds none either)
          if (refusal.empty() || !next.cannot_step.empty()) break;
        }
        // no foothold within reach, or a step beyond the legs' limits: stop
        // before it (on level ground the robot stands: its own limits, never a fall)
        if (!refusal.empty()) {
          NoteCannotStep(refusal, OnLevelGround(next));
          stop = true;
        }
      }
      if (stop) {
        stopped_ = true;
        stop_requested_ = false;
        clock_s_ = step_start_clock_s_ + step_duration_s_;  // freeze at the heel strike
        break;
      }
      last_cannot_step_.clear();
      plan_ = std::move(next);
      landing_felt_ = false;
      step_start_clock_s_ += step_duration_s_;
      step_duration_s_ = next_duration_s;
    }
  }
  const double p = std::clamp((clock_s_ - step_start_clock_s_) / (2 * step_duration_s_), 0.0, 0.5);
  const StepPose pose = planner_->Evaluate(plan_, p);

  RobotState state;
  state.t_s = t_s;
  state.X_WP = pose.X_WP;
  state.q = q_held_;
  legs_->WriteJoints(plan_.stance, pose.stance, state.q);
  legs_->WriteJoints(plan_.swing, pose.swing, state.q);
  // the left leg's phase, from the step so that it agrees with the support leg
  step_phase_ = p;
  const double phase = plan_.stance == Side::kLeft ? p : p + 0.5;
  state.gait_phase = phase >= 1.0 ? phase - 1.0 : phase;
  state.stopped = stopped_;
  if (stopped_ || p < kDoubleSupportEnd)
    state.support = SupportLeg::kDouble;
  else
    state.support = plan_.stance == Side::kLeft ? SupportLeg::kLeft : SupportLeg::kRight;
  const Vec3 p_WP = pose.X_WP.translation();
  if (has_last_p_WP_) distance_m_ += (p_WP - last_p_WP_).head<2>().norm();
  last_p_WP_ = p_WP;
  has_last_p_WP_ = true;
  state.distance_walked_m = distance_m_;
  return state;
}

void GaitWalker::Reset() { Start(); }

void GaitWalker::SetPath(std::vector<Vec2> waypoints_m) {
  waypoints_m_ = std::move(waypoints_m);
  next_waypoint_ = 0;
  path_origin_m_ = has_last_p_WP_ ? Vec2(last_p_WP_.head<2>()) : initial_.start_xyz_m.head<2>();
  // a robot that stood at the end of its old path walks on to the new one
  if (path_done_) {
    path_done_ = false;
    if (stopped_ && !waypoints_m_.empty()) Resume();
  }
}

std::vector<FootFrame> GaitWalker::Feet() const {
  std::vector<FootFrame> feet;
  for (const Side side : {Side::kLeft, Side::kRight}) {
    const LegGeometry& leg = legs_->leg(side);
    feet.push_back({.link = leg.foot_link, .p_L_sole = leg.p_L_sole, .p_L_toe = leg.p_L_toe, .p_L_heel = leg.p_L_heel,
                     .up_L = leg.up_L});
  }
  return feet;
}

}  // namespace proxsim
