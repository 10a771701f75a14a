#include "gait/step_safety.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>

namespace proxsim {

namespace {

// Rounds of slowing a step whose joints would move too fast.
constexpr int kSlowingRounds = 12;

const char* SideName(Side s) { return s == Side::kLeft ? "left" : "right"; }

// Highest sole point (heel or toe: BipedLegs::HeelAndToe) minus the knee, in
// the pelvis's upright sagittal plane (its z is the world's): ≥ 0 is a folded leg.
double SoleAboveKnee_m(const BipedLegs& legs, Side s, const LegAnglesRad& a, const std::array<Vec2xz, 2>& heel_toe) {
  const LegGeometry& g = legs.leg(s);
  const double knee_z = g.p_PH.z() - g.thigh_m * std::cos(a.hip);
  return std::max(heel_toe[0].y(), heel_toe[1].y()) - knee_z;
}

// The speed window in stance phase at a step's duration (p runs over [0, 0.5] in duration_s).
double SpeedWindow(double duration_s) { return std::min(0.5, 0.5 * kSpeedWindow_s / duration_s); }

// The end of speed window i: from p = window to 0.5.
double WindowEnd(double window, int i) { return window + (0.5 - window) * i / kStepSafetySamples; }

// Bisections that find where a leg straightens or bends off its reach.
constexpr int kSnapBisections = 40;
// A step slowed for its joints' speeds holds the windows at those instants
// (found exactly, not sampled) to this fraction of each top speed.
constexpr double kSnapSpeedMargin = 0.97;

// A leg at its full reach: the two-link IK clamped, its knee exactly straight
// (BipedLegs::SolveAnkle). Its knee leaves or reaches that as the square root
// of the time from the instant the target crosses the reach, so its mean
// speed over a window is largest for the window that ends or starts at that
// instant; a window sampled a few milliseconds off it sees much less.
bool Straight(const LegAnglesRad& a) { return a.knee == 0.0; }

bool SameReach(const StepPose& a, const StepPose& b) {
  return Straight(a.stance) == Straight(b.stance) && Straight(a.swing) == Straight(b.swing);
}

// The windows (end pose, start pose) of width `window` in phase that end and
// start where a leg straightens or bends between two consecutive poses of
// `grid` (phase, pose; ascending over [0, 0.5]), each kept within the step.
std::vector<std::pair<StepPose, StepPose>> SnapWindows(const StepPlanner& planner, const StepPlan& plan,
                                                       double window,
                                                       const std::vector<std::pair<double, StepPose>>& grid) {
  std::vector<std::pair<StepPose, StepPose>> windows;
  for (std::size_t i = 1; i < grid.size(); ++i) {
    if (SameReach(grid[i - 1].second, grid[i].second)) continue;
    // the instant of the change, by bisection
    double lo = grid[i - 1].first, hi = grid[i].first;
    const StepPose& at_lo = grid[i - 1].second;
    for (int k = 0; k < kSnapBisections; ++k) {
      const double mid = 0.5 * (lo + hi);
      (SameReach(planner.Evaluate(plan, mid), at_lo) ? lo : hi) = mid;
    }
    // the windows ending and starting there
    for (const double end : {std::max(hi, window), std::min(hi + window, 0.5)})
      windows.emplace_back(planner.Evaluate(plan, end), planner.Evaluate(plan, end - window));
  }
  return windows;
}

}  // namespace

std::string UnsafeStepReason(const StepPlanner& planner, const LegLimits& limits, const StepPlan& plan,
                             double duration_s, const StepWindows* sampled) {
  const BipedLegs& legs = planner.legs();
  const double window = SpeedWindow(duration_s);
  const bool known = sampled != nullptr && sampled->duration_s == duration_s;
  char text[320];
  std::vector<std::pair<double, StepPose>> grid;  // (p, pose) at every p below
  for (int i = -1; i <= kStepSafetySamples; ++i) {
    // p = 0, then the ends of the speed windows [p − window, p]
    const double p = i < 0 ? 0.0 : WindowEnd(window, i);
    const StepPose pose = i >= 0 && known ? sampled->end_start[i].first : planner.Evaluate(plan, p);
    grid.emplace_back(p, pose);
    const StepPose before = i < 0 ? pose : known ? sampled->end_start[i].second : planner.Evaluate(plan, p - window);
    // the swing sole's heel and toe, for its fold and its lift (LowestSoleZ's)
    std::array<Vec2xz, 2> swing_heel_toe;
    for (const Side side : {plan.stance, plan.swing}) {
      const LegAnglesRad& a = side == plan.stance ? pose.stance : pose.swing;
      const char* role = side == plan.stance ? "stance" : "swing";
      if (const auto excess = limits.AngleExcess(side, a)) {
        std::snprintf(text, sizeof text, "the %s %s leg at %.0f%% of the step: ", role, SideName(side), 200 * p);
        return text + excess->Describe();
      }
      if (i >= 0) {
        const LegAnglesRad& b = side == plan.stance ? before.stance : before.swing;
        if (const auto excess = limits.SpeedExcess(side, b, a, 2 * window * duration_s)) {
          std::snprintf(text, sizeof text, "the %s %s leg at %.0f%% of a %.2f s step: ", role, SideName(side),
                        200 * p, duration_s);
          return text + excess->Describe();
        }
      }
      const std::array<Vec2xz, 2> heel_toe = legs.HeelAndToe(side, a);
      if (side == plan.swing) swing_heel_toe = heel_toe;
      const double fold_m = SoleAboveKnee_m(legs, side, a, heel_toe);
      if (fold_m >= 0) {
        std::snprintf(text, sizeof text, "the %s %s leg would fold at %.0f%% of the step: its sole %.2f m above "
                      "its own knee", role, SideName(side), 200 * p, fold_m);
        return text;
      }
    }
    if (p >= kDoubleSupportEnd) {
      const double sole_z = pose.X_WP.translation().z() + std::min(swing_heel_toe[0].y(), swing_heel_toe[1].y());
      const double above_m = sole_z - plan.highest_ground_z_m;
      if (above_m > kMaxLiftAboveGround_m) {
        std::snprintf(text, sizeof text, "the %s swing foot would rise %.2f m above the highest ground it passes "
                      "over (at most %.2f m) at %.0f%% of the step", SideName(plan.swing), above_m,
                      kMaxLiftAboveGround_m, 200 * p);
        return text;
      }
    }
  }
  // the windows at the instants a leg reaches or leaves its full reach
  for (const auto& [pose, before] : SnapWindows(planner, plan, window, grid)) {
    for (const Side side : {plan.stance, plan.swing}) {
      const LegAnglesRad& a = side == plan.stance ? pose.stance : pose.swing;
      const LegAnglesRad& b = side == plan.stance ? before.stance : before.swing;
      if (const auto excess = limits.SpeedExcess(side, b, a, 2 * window * duration_s)) {
        std::snprintf(text, sizeof text, "the %s %s leg straightening or bending off its full reach in a %.2f s "
                      "step: ", side == plan.stance ? "stance" : "swing", SideName(side), duration_s);
        return text + excess->Describe();
      }
    }
  }
  return "";
}

double SpeedLimitedDuration_s(const StepPlanner& planner, const LegLimits& limits, const StepPlan& plan,
                              double at_least_s, StepWindows* sampled) {
  StepWindows own;
  StepWindows& windows = sampled != nullptr ? *sampled : own;
  // the same windows as UnsafeStepReason's: the fastest joint's mean speed
  // over kSpeedWindow_s, relative to its top speed, at duration d
  const auto ratio_at = [&](double d) {
    const double window = SpeedWindow(d);
    windows.duration_s = d;
    windows.end_start.resize(kStepSafetySamples + 1);
    double ratio = 0;
    std::vector<std::pair<double, StepPose>> grid;
    grid.emplace_back(0.0, planner.Evaluate(plan, 0.0));
    for (int i = 0; i <= kStepSafetySamples; ++i) {
      const double p = WindowEnd(window, i);
      auto& [pose, before] = windows.end_start[i];
      pose = planner.Evaluate(plan, p);
      before = planner.Evaluate(plan, p - window);
      ratio = std::max(ratio, limits.SpeedRatio(plan.stance, before.stance, pose.stance, 2 * window * d));
      ratio = std::max(ratio, limits.SpeedRatio(plan.swing, before.swing, pose.swing, 2 * window * d));
      grid.emplace_back(p, pose);
    }
    // and the windows at the instants a leg reaches or leaves its full reach:
    // those are the worst windows there, found exactly, so they are held to
    // kSnapSpeedMargin rather than to the margin that covers the windows
    // between samples
    constexpr double kSnapScale = kSpeedMargin / kSnapSpeedMargin;
    for (const auto& [pose, before] : SnapWindows(planner, plan, window, grid)) {
      ratio = std::max(ratio, kSnapScale * limits.SpeedRatio(plan.stance, before.stance, pose.stance, 2 * window * d));
      ratio = std::max(ratio, kSnapScale * limits.SpeedRatio(plan.swing, before.swing, pose.swing, 2 * window * d));
    }
    return ratio;
  };
  // speeds scale about as 1/d, but the window moves in phase as d grows: a
  // few rounds of scaling by the ratio found
  double d = at_least_s;
  for (int round = 0; round < kSlowingRounds; ++round) {
    const double ratio = ratio_at(d);
    if (ratio <= kSpeedMargin) break;
    d *= ratio / kSpeedMargin;
  }
  // the windows held are d's only if the last round sampled d
  if (windows.duration_s != d) windows.duration_s = std::numeric_limits<double>::quiet_NaN();
  return d;
}

double StrikeSpeedRatio(const StepPlanner& planner, const LegLimits& limits, const StepPlan& before, double before_s,
                        const StepPlan& after, double after_s) {
  constexpr int kOffsets = 10;
  double ratio = 0;
  for (int k = 0; k <= kOffsets; ++k) {
    // a window of kSpeedWindow_s, t_back of it before the strike
    const double t_back = kSpeedWindow_s * k / kOffsets, t_on = kSpeedWindow_s - t_back;
    const StepPose from = planner.Evaluate(before, std::max(0.0, 0.5 - 0.5 * t_back / before_s));
    const StepPose to = planner.Evaluate(after, std::min(0.5, 0.5 * t_on / after_s));
    for (const Side side : {Side::kLeft, Side::kRight}) {
      const LegAnglesRad& a = side == before.stance ? from.stance : from.swing;
      const LegAnglesRad& b = side == after.stance ? to.stance : to.swing;
      ratio = std::max(ratio, limits.SpeedRatio(side, a, b, kSpeedWindow_s));
    }
  }
  return ratio;
}

}  // namespace proxsim
