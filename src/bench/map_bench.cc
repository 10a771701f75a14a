#include "bench/map_bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <vector>

#include "bench/bench_measures.h"
#include "bench/step_timing.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"
#include "terrain/octomap_recorder.h"
#include "terrain/terrain_files.h"
#include "terrain/terrain_map.h"

namespace proxsim::bench {

namespace {

// The paper run without its stop rule: every sample walks and reads.
Scenario PaperWalk(bool with_map) {
  Scenario scenario = LoadBuiltinScenario("paper");
  scenario.robot->strategy.reset();
  scenario.map.enabled = with_map;
  return scenario;
}

// One sample's observation, copied out of the simulation.
struct RecordedSample {
  double t_s = 0;
  std::vector<SensorOutput> sensors;
  RobotKnowledge robot;
};

}  // namespace

nlohmann::json MapSection(bool quick) {
  nlohmann::json section;
  const int repeats = quick ? 3 : 15;
  const Scenario with_map = PaperWalk(true);
  const double step_with_s = SecondsPerStep(with_map, repeats);
  const double step_without_s = SecondsPerStep(PaperWalk(false), repeats);

  // the walk's observations, then the map's update alone on them
  std::vector<RecordedSample> walk;
  Simulation sim(with_map, 1);
  while (!sim.done()) {
    sim.Step();
    const Observation& o = sim.observation();
    walk.push_back({o.t_s, {o.sensors.begin(), o.sensors.end()}, *o.robot});
  }
  const TerrainMap& reference = *sim.terrain_map();
  std::vector<SensorSpec> specs;
  std::vector<bool> feeds;
  for (std::size_t i = 0; i < with_map.sensors.size(); ++i) {
    specs.push_back(with_map.sensors[i].spec);
    feeds.push_back(reference.feeds_map(i));
  }
  double update_s = std::numeric_limits<double>::infinity(), octomap_s = update_s, score_s = update_s;
  TerrainMap map(with_map.map, specs, feeds);
  for (int i = 0; i < repeats; ++i) {
    map.Reset();
    auto start = Clock::now();
    for (const RecordedSample& sample : walk) {
      map.Update(Observation{.t_s = sample.t_s, .sample = 0, .sensors = sample.sensors, .robot = &sample.robot});
    }
    update_s = std::min(update_s, Since(start) / static_cast<double>(walk.size()));
    // the OctoMap tree fed the same rays (what the run's recorder does), apart
    OctomapRecorder octomap(with_map.map.resolution_m);
    map.Reset();
    double insert_s = 0;
    for (const RecordedSample& sample : walk) {
      map.Update(Observation{.t_s = sample.t_s, .sample = 0, .sensors = sample.sensors, .robot = &sample.robot});
      start = Clock::now();
      for (const RayEvidence& evidence : map.last_evidence()) octomap.Add(evidence);
      insert_s += Since(start);
    }
    octomap_s = std::min(octomap_s, insert_s / static_cast<double>(walk.size()));
    // scoring at the end of the run: the truth's rays over the extent (no files)
    start = Clock::now();
    RecordTerrain(map, sim.world().caster(), "", nullptr);
    score_s = std::min(score_s, Since(start));
  }
  section["samples"] = walk.size();
  section["step_with_map_s"] = step_with_s;
  section["step_without_map_s"] = step_without_s;
  section["map_update_s"] = update_s;
  section["map_update_share"] = update_s / step_with_s;
  section["octomap_insert_s"] = octomap_s;
  section["score_s"] = score_s;
  section["map_memory_bytes"] = map.grid().memory_bytes();
  std::fprintf(stderr,
               "terrain: paper-like sample %.1f us with the map, %.1f us without; the map's update %.2f us (%.1f %% of "
               "the sample); OctoMap insertion %.2f us per sample; scoring the run %.1f ms\n",
               1e6 * step_with_s, 1e6 * step_without_s, 1e6 * update_s, 100 * update_s / step_with_s, 1e6 * octomap_s,
               1e3 * score_s);
  return section;
}

std::string MapReport(const nlohmann::json& s) {
  char text[1024];
  std::snprintf(text, sizeof text,
                "\n| terrain map (paper-like walk, %zu samples) | per sample |\n|---|---|\n"
                "| Simulation::Step with the map | %.1f us |\n| Simulation::Step without it | %.1f us |\n"
                "| TerrainMap::Update alone | %.2f us (%.1f %% of the sample) |\n"
                "| OctoMap insertion (the recorder's) | %.2f us |\n| scoring the run (once, at the end) | %.1f ms |\n",
                s.at("samples").get<std::size_t>(), 1e6 * s.at("step_with_map_s").get<double>(),
                1e6 * s.at("step_without_map_s").get<double>(), 1e6 * s.at("map_update_s").get<double>(),
                100 * s.at("map_update_share").get<double>(), 1e6 * s.at("octomap_insert_s").get<double>(),
                1e3 * s.at("score_s").get<double>());
  return text;
}

}  // namespace proxsim::bench
