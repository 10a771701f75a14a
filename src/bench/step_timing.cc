#include "bench/step_timing.h"

#include <algorithm>
#include <limits>

#include "bench/bench_measures.h"
#include "sim/simulation.h"

namespace proxsim::bench {

double SecondsPerStep(const Scenario& scenario, int repeats) {
  double best = std::numeric_limits<double>::infinity();
  Simulation sim(scenario, 1);
  for (int i = 0; i < repeats; ++i) {
    sim.Reset(scenario.seed);
    const auto start = Clock::now();
    while (!sim.done()) sim.Step();
    best = std::min(best, Since(start) / static_cast<double>(sim.sample_count()));
  }
  return best;
}

}  // namespace proxsim::bench
