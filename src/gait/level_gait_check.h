// At load: can the robot's legs walk the gait asked for on level ground
// within their URDF limits? Steady straight walking at the amplitude that
// walks the stride, at the period asked for, is checked step by step by the
// same decider that checks every step while walking (gait/step_safety.h):
// angle ranges, top speeds (a step lasts half the period; the speeds grow as
// the period shrinks), folded legs. A stride beyond what the curves' largest
// amplitude walks is checked at the amplitude it would need (the curves
// scaled further, up to kSearchAmplitude): if that breaks a limit, the
// stride is refused rather than silently walked shorter.
#pragma once

#include <string>

#include "gait/joint_limits.h"
#include "gait/gait_steps.h"
#include "gait/stride_table.h"

namespace proxsim {

/// Largest amplitude at which a stride beyond kMaxAmplitude's is looked for.
constexpr double kSearchAmplitude = 3.0;
/// Steps of steady walking checked (the first steps ramp nothing in: k is constant).
constexpr int kLevelGaitSteps = 6;

/// Throws InputError (naming `source`, the gait's keys, the joint, the angle
/// or speed needed and the limit) when steady walking of stride_m at
/// period_s, walked by `walked` (the amplitude BisectAmplitude found), breaks a
/// limit on level ground. `planner` plans on a flat floor.
void CheckLevelGait(const StepPlanner& planner, const LegLimits& limits, const std::string& source,
                    double stride_m, double period_s, const AmplitudeStride& walked);

}  // namespace proxsim
