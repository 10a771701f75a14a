// `proxsim bench`: proxsim's pipeline against bare Embree, Bullet and MuJoCo
// in one process, on one generated dining room at ~10k, 100k and 1M
// triangles and the same rays; then the default paper run and the heavy
// scenario end to end; then a real robot of meshes against the built-in biped; then placement studies;
// then the terrain map's cost per sample; then co-simulation and batched environments from Python. Every figure is measured in this run;
// docs/performance.md documents every key of the result.
#pragma once

#include <nlohmann/json.hpp>

namespace proxsim::bench {

struct BenchOptions {
  bool quick = false;     ///< fewer rays and a shorter heavy run (a smoke test, ~1 min)
  bool progress = true;   ///< progress lines on stderr
  bool rays = true;       ///< the engines on the ray sets
  bool end_to_end = true; ///< the paper run and the heavy scenario
  bool robots = true;     ///< loading the Unitree H1 and its cost per sample against the built-in biped
  bool study = true;      ///< placement studies: runs per second per core, a 1000-run study, 2 MPI ranks against 1
  bool outcomes = true;   ///< closed-loop studies: runs per second per core on generated rooms, 2 MPI ranks against 1
  bool terrain = true;    ///< planning footsteps on the stairs course against a paper-like sample
  bool map = true;        ///< the terrain map's cost per sample (bench/map_bench.h)
  bool python = true;     ///< co-simulation and the batched environment from Python (bench/python_envs_bench.h)
  bool worlds = true;     ///< moving objects' cost per sample, generating worlds (bench/worlds_bench.h)
};

/// Runs the whole suite and returns its figures.
nlohmann::json RunBench(const BenchOptions& options);

/// The figures as a human-readable Markdown report; throws nlohmann::json::exception
/// when `result` lacks a figure (a file that is not a whole `--json` run).
std::string BenchReport(const nlohmann::json& result);

}  // namespace proxsim::bench
