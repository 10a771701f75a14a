#include "gait/level_gait_check.h"

#include <cstdio>

#include "core/input_error.h"
#include "gait/step_safety.h"

namespace proxsim {

namespace {

// Why steady straight walking at amplitude k cannot be walked ("" if it can).
std::string LevelWalkReason(const StepPlanner& flat, const LegLimits& limits, double k, double period_s) {
  StepPlan plan = flat.FirstStep(Vec3::Zero(), 0.0, k);
  for (int step = 0; step < kLevelGaitSteps; ++step) {
    std::string reason = UnsafeStepReason(flat, limits, plan, 0.5 * period_s);
    if (!reason.empty()) return reason;
    plan = flat.NextStep(plan, k, 0.0);
  }
  return "";
}

}  // namespace

void CheckLevelGait(const StepPlanner& planner, const LegLimits& limits, const std::string& source,
                    double stride_m, double period_s, const AmplitudeStride& walked) {
  const StepPlanner flat(planner.legs());
  char text[200];
  std::string reason = LevelWalkReason(flat, limits, walked.k, period_s);
  if (reason.empty() && walked.stride_m < stride_m - 1e-3) {
    // clamped: the amplitude the stride would need, the curves scaled further
    double lo = walked.k, hi = kSearchAmplitude;
    if (SteadyStride_m(flat, hi) > stride_m) {
      for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (SteadyStride_m(flat, mid) < stride_m ? lo : hi) = mid;
      }
    }
    reason = LevelWalkReason(flat, limits, hi, period_s);
    if (!reason.empty()) {
      std::snprintf(text, sizeof text, " (the longest stride the gait walks is %.2f m; a longer one would need the "
                    "curves at %.2f times the normative gait)", walked.stride_m, hi);
      reason += text;
    }
  }
  if (reason.empty()) return;
  std::snprintf(text, sizeof text, ": gait: stride_m %.2f m at period_s %.3f s cannot be walked on level ground "
                "within the URDF's joint limits: ", stride_m, period_s);
  throw InputError(source + text + reason);
}

}  // namespace proxsim
