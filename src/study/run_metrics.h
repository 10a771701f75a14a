// What one study run measured: one candidate mounting, in one scene variant,
// with one seed. Computed from the readings and the scene's truth (this is
// scoring, not a strategy): for each hazard whether and when it was first
// detected and the lead distance then (the leading toe to the detected point,
// along the heading); false alarms (fresh detections the built-in stop rule
// would take for an obstacle, on no hazard); the shares of samples lost to
// `self` echoes and to grazing; and the floor coverage (the share of 5 cm
// stretches of the walk in which the sensor detected the ground).
#pragma once

#include <string>
#include <vector>

#include "sim/simulation.h"

namespace proxsim {

struct HazardResult {
  bool applies = false;   ///< the variant has such objects
  bool detected = false;
  double first_t_s = 0;
  double lead_m = 0;      ///< leading toe to the detected point, along the heading, at the first detection
};

struct RunMetrics {
  std::vector<HazardResult> hazards;  ///< one per study hazard
  std::int64_t samples = 0;           ///< the sensor's own samples
  std::int64_t false_alarms = 0;
  double self_share = 0;
  double grazing_share = 0;
  double floor_coverage = 0;
  /// The episode's outcome (referee/referee.h) and its time: the same
  /// for every candidate of a run (they ride together and have no strategy),
  /// and the metrics above are measured up to it.
  OutcomeKind outcome = OutcomeKind::kTimeUp;
  double outcome_t_s = 0;
};

/// Whether `prefix` names a hazard in `world`: a scene object (not a robot
/// link) whose name starts with it.
bool NamesAHazard(const World& world, const std::string& prefix);

/// Accumulates the metrics of every sensor of a simulation, sample by sample.
class RunMetricsRecorder {
 public:
  /// `hazards`: object-name prefixes; `sim` must outlive the recorder.
  RunMetricsRecorder(const Simulation& sim, const std::vector<std::string>& hazards);
  /// After each Step().
  void Add();
  /// One per sensor, in scenario order.
  std::vector<RunMetrics> Finish() const;

  /// Stretch of the walk over which floor coverage is counted, m.
  static constexpr double kCoverageBin_m = 0.05;

 private:
  int HazardOf(std::int32_t object_id) const;  // the study hazard of a hit object, -1 none

  const Simulation& sim_;
  std::vector<int> hazard_of_object_;  // hazard index of each object id, -1 none
  std::vector<bool> ground_object_;
  std::vector<RunMetrics> metrics_;
  std::vector<std::int64_t> self_, grazing_;
  std::vector<std::vector<bool>> floor_bins_;  // per sensor, per stretch walked
  std::int64_t bins_walked_ = 0;
};

}  // namespace proxsim
