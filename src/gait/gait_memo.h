// The load-time gait search, remembered across walkers in one process.
//
// Building a GaitWalker bisects the curve amplitude that walks the stride
// (BisectAmplitude: ~50 steady-stride plans) and checks steady level walking
// against the joint limits (CheckLevelGait): ~15 ms of the ~20 ms it takes
// to build a Simulation of the built-in biped. A closed-loop study builds a
// Simulation per episode with the same legs and gait hundreds of times, so
// the answer is kept here, keyed by every number the search reads (the
// legs' fingerprint, BipedLegs::Fingerprint, and the stride and period, bit
// for bit): a walker built from the same legs gets the very amplitude the
// search would compute, so results do not change. Only a gait that passed
// its check is remembered (a refused one is recomputed to name its fault).
// So is the legs' default highest step (DefaultMaxStep_m at that amplitude:
// four steady steps and a bisection, a function of the same key).
//
// Also remembered: each planned step's checks (its speed-limited duration and
// whether it is unsafe at a duration, gait/step_safety.h), keyed by the same
// search key and the plan's every field, bit for bit (StepPlanBytes): a
// walker plans the very same first step at its construction, on SetTerrain
// and on every Reset (three times an episode, and again in every episode that
// starts where the last did), and runs of one world with other sensors or
// strategies walk the same steps until they part. Each check is a pure
// function of those numbers (StepPlanner::Evaluate reads the plan alone), so
// a remembered answer is the answer.
#pragma once

#include <optional>
#include <string>

#include "gait/gait_steps.h"
#include "gait/stride_table.h"

namespace proxsim {

/// The remembered amplitude for `key` (see GaitSearchKey), if any. Thread-safe.
std::optional<AmplitudeStride> RememberedGait(const std::string& key);
/// Remembers a checked gait's amplitude. Thread-safe; the store is bounded
/// (emptied when it holds kMaxRememberedGaits keys).
void RememberGait(const std::string& key, const AmplitudeStride& walked);

constexpr std::size_t kMaxRememberedGaits = 64;

/// The legs' default highest step (DefaultMaxStep_m at the searched
/// amplitude) remembered under the same key, if any. Thread-safe.
std::optional<double> RememberedMaxStep(const std::string& key);
void RememberMaxStep(const std::string& key, double max_step_m);

/// Every field of `plan`, bit for bit (a step check's key; see above).
std::string StepPlanBytes(const StepPlan& plan);

/// A step's remembered duration (GaitWalker's Duration_s) under `key`
/// (GaitSearchKey + the gait period + StepPlanBytes), if any. Thread-safe.
std::optional<double> RememberedStepDuration(const std::string& key);
void RememberStepDuration(const std::string& key, double duration_s);
/// A step's remembered refusal ("" when it may be taken) at duration_s. Thread-safe.
std::optional<std::string> RememberedStepRefusal(const std::string& key, double duration_s);
void RememberStepRefusal(const std::string& key, double duration_s, const std::string& refusal);

/// Steps remembered at most (the store is emptied when it holds that many).
constexpr std::size_t kMaxRememberedSteps = 4096;

/// The key of the search for legs with fingerprint `legs_fingerprint`
/// walking stride_m at period_s.
std::string GaitSearchKey(const std::string& legs_fingerprint, double stride_m, double period_s);

}  // namespace proxsim
