// `proxsim bench`, the worlds section (`--only worlds`, docs/worlds.md):
//  - what moving objects cost: a paper-like sample (the paper's four
//    sensors, one ray each, on the left tibia, no strategy, no map) in the
//    1M-triangle dining room, one whole Simulation::Step, with 50 boxes
//    moving on loops about the room and without them; the target is
//    an extra cost of at most 10 %;
//  - what generating costs: GenerateWorld for a 20 m course and a 10 × 10 m
//    room at difficulty 1 (the most pieces), the slowest of 20 seeds, and the
//    whole round trip a run does (generate, write the scenario, read it back);
//    the target is under 50 ms.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "bench/bench_scene.h"

namespace proxsim::bench {

/// The section's figures; `scene_1m` the 1M-triangle room (made here when empty).
nlohmann::json WorldsSection(bool quick, const BenchScene& scene_1m);

/// The section's lines for the Markdown report.
std::string WorldsReport(const nlohmann::json& section);

}  // namespace proxsim::bench
