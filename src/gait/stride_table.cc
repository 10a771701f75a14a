#include "gait/stride_table.h"

#include <algorithm>

#include "gait/gait_steps.h"

namespace proxsim {

namespace {

bool ByAmplitude(const AmplitudeStride& a, const AmplitudeStride& b) { return a.k < b.k; }

}  // namespace

void StrideTable::AddExact(double stride_m, AmplitudeStride point) {
  exact_.emplace_back(stride_m, point);
  points_.push_back(point);
  if (sampled_) std::sort(points_.begin(), points_.end(), ByAmplitude);
}

void StrideTable::Sample(const StepPlanner& planner) {
  for (int i = 0; i < kSamples; ++i) {
    const double k = kMinAmplitude + (kMaxAmplitude - kMinAmplitude) * i / (kSamples - 1);
    points_.push_back({k, SteadyStride_m(planner, k)});
  }
  std::sort(points_.begin(), points_.end(), ByAmplitude);
  sampled_ = true;
}

AmplitudeStride StrideTable::For(const StepPlanner& planner, double stride_m) {
  // a stride computed exactly answers for itself, before any sampling
  for (const auto& [asked_m, point] : exact_)
    if (asked_m == stride_m) return point;
  if (!sampled_) Sample(planner);
  // beyond the reach of the amplitudes: the nearest end (as the bisection clamps)
  if (stride_m <= points_.front().stride_m) return points_.front();
  if (stride_m >= points_.back().stride_m) return points_.back();
  // the first bracket holding the stride (the stride grows with k)
  for (std::size_t i = 1; i < points_.size(); ++i) {
    const AmplitudeStride& a = points_[i - 1];
    const AmplitudeStride& b = points_[i];
    if ((a.stride_m <= stride_m && stride_m <= b.stride_m) && b.stride_m > a.stride_m) {
      const double w = (stride_m - a.stride_m) / (b.stride_m - a.stride_m);
      return {a.k + w * (b.k - a.k), stride_m};
    }
  }
  return points_.back();
}

AmplitudeStride BisectAmplitude(const StepPlanner& planner, double stride_m) {
  double lo = kMinAmplitude, hi = kMaxAmplitude;
  if (SteadyStride_m(planner, hi) <= stride_m) {
    lo = hi;
  } else if (SteadyStride_m(planner, lo) >= stride_m) {
    hi = lo;
  } else {
    for (int i = 0; i < 40; ++i) {
      const double mid = 0.5 * (lo + hi);
      (SteadyStride_m(planner, mid) < stride_m ? lo : hi) = mid;
    }
  }
  const double k = 0.5 * (lo + hi);
  return {k, SteadyStride_m(planner, k)};
}

}  // namespace proxsim
