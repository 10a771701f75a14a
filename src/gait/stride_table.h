// The curve amplitude k that walks a given stride, found without re-planning
// the gait on every request. The steady stride of straight walking,
// SteadyStride_m(planner, k), costs about a millisecond (it plans eight
// steps), so a bisection over it costs tens of milliseconds: fine once at
// load, not for a strategy or a learning loop that sets the stride at every
// step. The table samples k once (on the first request that needs it) and
// answers by linear interpolation between its samples; the exact points the
// load's bisection found are kept as samples, so that asking again for the
// loaded stride gives back exactly the loaded amplitude.
#pragma once

#include <utility>
#include <vector>

namespace proxsim {

class StepPlanner;

/// Amplitude k and the stride it walks, m.
struct AmplitudeStride {
  double k = 1;
  double stride_m = 0;
};

/// The amplitudes the gait may walk: below, the legs barely swing; above,
/// the curves exceed what a leg can do.
constexpr double kMinAmplitude = 0.05, kMaxAmplitude = 1.6;

class StrideTable {
 public:

  /// Records an exactly computed answer for `stride_m` (the load's bisection).
  void AddExact(double stride_m, AmplitudeStride point);

  /// The amplitude for `stride_m` and the stride it walks: interpolated
  /// between the sampled points (sampled from `planner` on the first call),
  /// clamped to the strides that k ∈ [kMinAmplitude, kMaxAmplitude] walk.
  AmplitudeStride For(const StepPlanner& planner, double stride_m);

  /// Samples taken uniformly in k when the table is first used.
  static constexpr int kSamples = 33;

 private:
  void Sample(const StepPlanner& planner);

  bool sampled_ = false;
  std::vector<std::pair<double, AmplitudeStride>> exact_;  // (stride asked for, its exact answer)
  std::vector<AmplitudeStride> points_;                     // sorted by k once sampled
};

/// The amplitude k ∈ [kMinAmplitude, kMaxAmplitude] whose steady stride is
/// `stride_m`, by bisection (the stride is assumed to grow with k), and the
/// stride it walks: the nearest end of the range when out of reach.
AmplitudeStride BisectAmplitude(const StepPlanner& planner, double stride_m);

}  // namespace proxsim
