// Whether a planned step can be taken within the robot's limits, and why not:
// the one place that decides "this step is unsafe, because ...".
//
// A step is sampled densely over its stance phase p in [0, 0.5] (both legs,
// the poses StepPlanner::Evaluate gives) and is unsafe when, at any sample:
//  - a joint the gait drives leaves its URDF angle range, or moves faster than
//    its URDF velocity limit (its mean speed over any kSpeedWindow_s of the
//    step, at the step's duration; gait/joint_limits.h) — over the sampled
//    windows, and over the windows that end and start at each instant a leg
//    reaches or leaves its full reach (its knee then moves as the square
//    root of time, fastest in the window that meets that instant, which
//    sampled windows miss: found by bisection);
//  - a leg folds: a sole point (heel or toe) of either leg comes level with or
//    above that leg's own knee;
//  - the swing sole (its lowest point, after toe-off) rises more than
//    kMaxLiftAboveGround_m above the highest ground it passes over
//    (StepPlan::highest_ground_z_m): a foot that high is a planner gone wrong,
//    not a step.
// The answer names the joint, the angle or speed needed and the limit (or the
// heights). Today the walker refuses such a step as it refuses a step with no
// foothold: it stands before it with a `cannot_step` event
// (gait/gait_walker.h). A fall outcome can be put on the same answer later.
//
// Speeds scale with 1/duration, so a step whose joints would move too fast (a
// sharp turn, a step up) is slowed rather than refused (SpeedLimitedDuration_s);
// steady walking on level ground keeps half the gait period, which the load's
// check (gait/level_gait_check.h) has found within the limits.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "gait/gait_steps.h"
#include "gait/joint_limits.h"

namespace proxsim {

/// Highest the swing sole rises above the highest ground it must clear, m.
constexpr double kMaxLiftAboveGround_m = 0.10;
/// Samples of a step's stance phase the safety check takes.
constexpr int kStepSafetySamples = 200;
/// A joint's speed is its mean speed over this window, s: the finest sample
/// period of the shipped examples (100 Hz). The flat-floor gait's heel strike
/// has a kink too short for it (the new swing knee: 9.0 rad/s for about 3 ms,
/// 7.3 rad/s over 10 ms, for the built-in biped at stride 0.6 m, period 1.2 s).
constexpr double kSpeedWindow_s = 0.01;
/// A terrain step slowed for its joints' speeds aims at this fraction of each
/// top speed over its sampled windows (the windows at a leg's full reach,
/// found exactly, at 0.97: step_safety.cc).
constexpr double kSpeedMargin = 0.9;

/// The poses of a step that both checks below read at one duration: for
/// each speed window i in [0, kStepSafetySamples], the pose at its end p_i
/// and at its start p_i − window. Planning a step evaluates the same ~400
/// poses for its duration and then for its safety; sampled once, they are
/// shared (each is StepPlanner::Evaluate's pure answer, so nothing changes).
struct StepWindows {
  double duration_s = 0;  ///< the duration they were sampled at; NaN: none
  std::vector<std::pair<StepPose, StepPose>> end_start;
};

/// Why the step `plan` lasting duration_s cannot be taken ("" when it can).
/// `sampled`: the step's windows if known (used when sampled at duration_s).
std::string UnsafeStepReason(const StepPlanner& planner, const LegLimits& limits, const StepPlan& plan,
                             double duration_s, const StepWindows* sampled = nullptr);

/// The shortest duration, at least `at_least_s`, over which the joints of
/// `plan` stay within kSpeedMargin of their top speeds, s. `sampled`, if
/// given, receives the windows it sampled at the duration it returns (or a
/// NaN duration when its last round did not sample them).
double SpeedLimitedDuration_s(const StepPlanner& planner, const LegLimits& limits, const StepPlan& plan,
                              double at_least_s, StepWindows* sampled = nullptr);

/// The fastest joint's mean speed over kSpeedWindow_s across the heel strike
/// that ends `before` (lasting before_s) and starts `after` (lasting
/// after_s), relative to its top speed: the windows UnsafeStepReason, which
/// sees one step, cannot see.
double StrikeSpeedRatio(const StepPlanner& planner, const LegLimits& limits, const StepPlan& before, double before_s,
                        const StepPlan& after, double after_s);

}  // namespace proxsim
