// Time of a simulation's own steps, for the bench sections that compare one
// scenario against another (the map, robots, moving objects).
#pragma once

#include "scenario/scenario.h"

namespace proxsim::bench {

/// Wall time per Simulation::Step over the whole walk of `scenario`, best of
/// `repeats` (the world built once, reset between them; only steps are timed).
double SecondsPerStep(const Scenario& scenario, int repeats);

/// Two scenarios' steps measured in turns, for a small difference between
/// them on a busy machine: `pairs` walks of each, interleaved (base, other,
/// then other, base, ...), each timed in the CPU time of the calling thread
/// (every step runs on it at 1 thread), so that what other processes take of
/// the cores counts less than in wall time. Each pair's walks are taken back
/// to back, at the same load: the fraction is the median of the pairs' own
/// fractions, with their spread.
struct StepComparison {
  double base_s = 0;            ///< median over the walks, CPU seconds per step
  double other_s = 0;
  double extra_fraction = 0;    ///< median over the pairs of other / base − 1
  double extra_fraction_lo = 0; ///< the pairs' fractions: lower and upper quartile
  double extra_fraction_hi = 0;
  double extra_fraction_min = 0;
  double extra_fraction_max = 0;
  double base_wall_s = 0;       ///< medians of the same walks' wall time per step
  double other_wall_s = 0;
  double base_min_clearance_m = 0;   ///< the robot's least clearance in each walk (what caps its
  double other_min_clearance_m = 0;  ///< clearance queries: a walk nearer things measures less far)
  double load_before = 0;       ///< the 1-minute load average around the measurement
  double load_after = 0;
  int pairs = 0;
};
StepComparison CompareSteps(const Scenario& base, const Scenario& other, int pairs);

}  // namespace proxsim::bench
