// `proxsim bench`, the engines on the ray sets (`--only rays`): per scene
// size — the generated dining room at ~10k, 100k and 1M triangles — proxsim,
// bare Embree (fast and robust), Bullet and MuJoCo are built on the same
// triangles, cast the same incoherent rays and beam fans at 1 and 2 threads,
// and their answers are compared ray by ray. proxsim's figure is its whole
// pipeline: the cast, then every ray's echo, keyed noise and sensor model.
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/bench_scene.h"

namespace proxsim::bench {

/// The section's figures: "scenes" per size label and the headline ratios
/// (docs/performance.md). `rays_per_set` rays in each set, each timing the
/// best of `repeats`; the 1M-triangle scene is handed to `scene_1m` when not
/// null, for the end-to-end runs.
nlohmann::json RaysSection(bool quick, std::size_t rays_per_set, int repeats, BenchScene* scene_1m);

/// The section's two tables for the Markdown report (from the whole result).
std::string RaysReport(const nlohmann::json& result);

}  // namespace proxsim::bench
