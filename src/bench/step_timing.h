// Wall time of a simulation's own steps, for the bench sections that compare
// one scenario against another (the map, robots, moving objects).
#pragma once

#include "scenario/scenario.h"

namespace proxsim::bench {

/// Wall time per Simulation::Step over the whole walk of `scenario`, best of
/// `repeats` (the world built once, reset between them; only steps are timed).
double SecondsPerStep(const Scenario& scenario, int repeats);

}  // namespace proxsim::bench
