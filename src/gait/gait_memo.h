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
#pragma once

#include <optional>
#include <string>

#include "gait/stride_table.h"

namespace proxsim {

/// The remembered amplitude for `key` (see GaitSearchKey), if any. Thread-safe.
std::optional<AmplitudeStride> RememberedGait(const std::string& key);
/// Remembers a checked gait's amplitude. Thread-safe; the store is bounded
/// (emptied when it holds kMaxRememberedGaits keys).
void RememberGait(const std::string& key, const AmplitudeStride& walked);

constexpr std::size_t kMaxRememberedGaits = 64;

/// The key of the search for legs with fingerprint `legs_fingerprint`
/// walking stride_m at period_s.
std::string GaitSearchKey(const std::string& legs_fingerprint, double stride_m, double period_s);

}  // namespace proxsim
