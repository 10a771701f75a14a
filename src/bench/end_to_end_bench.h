// `proxsim bench`, end to end (`--only e2e`): the default paper run as
// `proxsim run --no-report` runs it; the heavy scenario — 64 ultrasonic
// sensors with 32-ray beams on the biped's legs at 1 kHz in the 1M-triangle
// room — with its outputs written, then its simulation steps alone, then bare
// Embree on its own rays; then the closed loop (closed_loop_bench.h), each at
// 1 and 2 threads.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "bench/bench_scene.h"

namespace proxsim::bench {

/// The section's figures: "paper_run", "heavy", "closed_loop" and their
/// headline keys (docs/performance.md). `scene_1m` is the 1M-triangle room;
/// each bare-Embree timing is the best of `repeats`.
nlohmann::json EndToEndSection(bool quick, int repeats, const BenchScene& scene_1m);

/// The section's lines for the Markdown report, with the bench's wall time
/// (from the whole result).
std::string EndToEndReport(const nlohmann::json& result);

}  // namespace proxsim::bench
