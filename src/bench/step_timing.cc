#include "bench/step_timing.h"

#include <time.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "bench/bench_measures.h"
#include "sim/simulation.h"

namespace proxsim::bench {

namespace {

// The calling thread's CPU time in seconds.
double ThreadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// The q-quantile of `values` (0.5 the median), between neighbours.
double Quantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  const double at = q * static_cast<double>(values.size() - 1);
  const std::size_t below = static_cast<std::size_t>(at);
  const std::size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (at - static_cast<double>(below)) * (values[above] - values[below]);
}

struct WalkTime {
  double cpu_s;   // per step
  double wall_s;  // per step
};

// One whole walk of `sim` from its start.
WalkTime Walk(Simulation& sim, std::uint64_t seed) {
  sim.Reset(seed);
  const auto start = Clock::now();
  const double cpu_start = ThreadCpuSeconds();
  while (!sim.done()) sim.Step();
  const double steps = static_cast<double>(sim.sample_count());
  return {(ThreadCpuSeconds() - cpu_start) / steps, Since(start) / steps};
}

}  // namespace

double SecondsPerStep(const Scenario& scenario, int repeats) {
  double best = std::numeric_limits<double>::infinity();
  Simulation sim(scenario, 1);
  for (int i = 0; i < repeats; ++i) best = std::min(best, Walk(sim, scenario.seed).wall_s);
  return best;
}

StepComparison CompareSteps(const Scenario& base, const Scenario& other, int pairs) {
  StepComparison result;
  result.pairs = pairs;
  Simulation base_sim(base, 1), other_sim(other, 1);
  // one walk of each first, unmeasured: caches, the point-query scenes built on first use
  Walk(base_sim, base.seed);
  Walk(other_sim, other.seed);
  result.load_before = LoadAverage();
  std::vector<double> base_cpu, other_cpu, base_wall, other_wall, fractions;
  for (int i = 0; i < pairs; ++i) {
    // alternate which goes first, so that a load rising or falling within a pair favours neither
    WalkTime b{}, o{};
    if (i % 2 == 0) {
      b = Walk(base_sim, base.seed);
      o = Walk(other_sim, other.seed);
    } else {
      o = Walk(other_sim, other.seed);
      b = Walk(base_sim, base.seed);
    }
    base_cpu.push_back(b.cpu_s);
    other_cpu.push_back(o.cpu_s);
    base_wall.push_back(b.wall_s);
    other_wall.push_back(o.wall_s);
    fractions.push_back(o.cpu_s / b.cpu_s - 1);
  }
  result.load_after = LoadAverage();
  result.base_min_clearance_m = base_sim.robot_outcome().min_clearance_m;
  result.other_min_clearance_m = other_sim.robot_outcome().min_clearance_m;
  result.base_s = Quantile(base_cpu, 0.5);
  result.other_s = Quantile(other_cpu, 0.5);
  result.base_wall_s = Quantile(base_wall, 0.5);
  result.other_wall_s = Quantile(other_wall, 0.5);
  result.extra_fraction = Quantile(fractions, 0.5);
  result.extra_fraction_lo = Quantile(fractions, 0.25);
  result.extra_fraction_hi = Quantile(fractions, 0.75);
  result.extra_fraction_min = Quantile(fractions, 0);
  result.extra_fraction_max = Quantile(fractions, 1);
  return result;
}

}  // namespace proxsim::bench
