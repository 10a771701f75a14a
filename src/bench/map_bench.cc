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
#include "output/octomap_recorder.h"
#include "output/terrain_archive.h"
#include "output/terrain_files.h"
#include "knowledge/terrain_map.h"

namespace proxsim::bench {

namespace {

// The paper run without its stop rule: every sample walks and reads.
Scenario PaperWalk(bool with_map) {
  Scenario scenario = LoadBuiltinScenario("paper");
  scenario.robot->strategy.reset();
  scenario.map.enabled = with_map;
  return scenario;
}

// A straight walk on a floor with the paper's four tibia sensors (the one of
// tests/data/cli/long_walk.yaml), `length_m` long, with the map's window.
Scenario LongWalk(double length_m, double window_m) {
  Scenario scenario = LoadScenarioText(
      "proxsim: 1\nseed: 1\nrate_hz: 50\nduration_s: " + std::to_string(length_m / 0.5 + 2) +
          "\nscene:\n  builtin: empty\n  objects:\n    - {name: floor, plane: {}}\n"
          "robot:\n  model: builtin:biped\n  gait: {stride_m: 0.6, period_s: 1.2}\n"
          "  path: {waypoints_m: [[0, 0], [" + std::to_string(length_m) + ", 0]]}\n"
          "sensors:\n"
          "  - {name: ideal, type: ideal, link: left_tibia, pose: &mount {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 15, 0]}}\n"
          "  - {name: laser, type: laser, link: left_tibia, pose: *mount}\n"
          "  - {name: ultrasonic, type: ultrasonic, link: left_tibia, pose: *mount}\n"
          "  - {name: reflectance, type: reflectance, link: left_tibia, pose: *mount}\n",
      "bench long walk");
  scenario.map.window_m = window_m;
  return scenario;
}

// What the map and the OctoMap tree hold in memory along a long walk, every
// `every_m` walked: bytes of the grid's tiles, and the tree's nodes.
struct MemoryAlongWalk {
  std::vector<double> walked_m;
  std::vector<std::size_t> grid_bytes, octomap_nodes;
};

MemoryAlongWalk MeasureLongWalk(double length_m, double window_m, double every_m) {
  MemoryAlongWalk out;
  Simulation sim(LongWalk(length_m, window_m), 1);
  TerrainArchive archive(*sim.terrain_map(), true);
  double next_m = every_m;
  while (!sim.done()) {
    sim.Step();
    archive.Add();
    const double walked_m = sim.terrain_map()->last_position().p_W_pelvis.x();
    if (walked_m < next_m) continue;
    next_m += every_m;
    out.walked_m.push_back(walked_m);
    out.grid_bytes.push_back(sim.terrain_map()->grid().memory_bytes());
    out.octomap_nodes.push_back(archive.octomap()->node_count());
  }
  return out;
}

// Growth per metre walked over the second half of the walk (after a window fills).
template <class T>
double PerMetre(const MemoryAlongWalk& m, const std::vector<T>& values) {
  const std::size_t half = values.size() / 2, last = values.size() - 1;
  return (static_cast<double>(values[last]) - static_cast<double>(values[half])) / (m.walked_m[last] - m.walked_m[half]);
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
    TerrainArchive archive(map, false);
    archive.Add();  // (the track of the last sample only: the extent is the map's)
    start = Clock::now();
    RecordTerrain(archive, sim.world().caster(), "");
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

  // memory along a long straight walk: the default window against one that never retires
  const double long_m = quick ? 60.0 : 200.0, every_m = 5.0;
  for (const auto& [key, window_m] : {std::pair{"windowed", with_map.map.window_m}, std::pair{"unbounded", 1e9}}) {
    const MemoryAlongWalk m = MeasureLongWalk(long_m, key == std::string("windowed") && quick ? 10.0 : window_m, every_m);
    section["long_walk"][key] = {{"window_m", key == std::string("windowed") && quick ? 10.0 : window_m},
                                 {"walked_m", m.walked_m},
                                 {"grid_bytes", m.grid_bytes},
                                 {"octomap_nodes", m.octomap_nodes},
                                 {"grid_bytes_per_m", PerMetre(m, m.grid_bytes)},
                                 {"octomap_nodes_per_m", PerMetre(m, m.octomap_nodes)}};
  }
  std::fprintf(stderr,
               "terrain: paper-like sample %.1f us with the map, %.1f us without; the map's update %.2f us (%.1f %% of "
               "the sample); OctoMap insertion %.2f us per sample; scoring the run %.1f ms\n",
               1e6 * step_with_s, 1e6 * step_without_s, 1e6 * update_s, 100 * update_s / step_with_s, 1e6 * octomap_s,
               1e3 * score_s);
  for (const char* key : {"windowed", "unbounded"}) {
    const nlohmann::json& w = section["long_walk"][key];
    std::fprintf(stderr, "terrain: %.0f m walk, window %g m: grid %zu bytes at the end, %.0f bytes and %.1f OctoMap nodes per metre over its second half\n",
                 w["walked_m"].back().get<double>(), w["window_m"].get<double>(), w["grid_bytes"].back().get<std::size_t>(),
                 w["grid_bytes_per_m"].get<double>(), w["octomap_nodes_per_m"].get<double>());
  }
  return section;
}

std::string MapReport(const nlohmann::json& s) {
  char text[2048];
  std::snprintf(text, sizeof text,
                "\n| terrain map (paper-like walk, %zu samples) | per sample |\n|---|---|\n"
                "| Simulation::Step with the map | %.1f us |\n| Simulation::Step without it | %.1f us |\n"
                "| TerrainMap::Update alone | %.2f us (%.1f %% of the sample) |\n"
                "| OctoMap insertion (the recorder's) | %.2f us |\n| scoring the run (once, at the end) | %.1f ms |\n"
                "\n| memory along a %.0f m straight walk | window %g m | window %g m (never retires) |\n|---|---|---|\n"
                "| grid bytes at the end | %zu | %zu |\n| grid bytes per metre (second half) | %.0f | %.0f |\n"
                "| OctoMap nodes held at the end | %zu | %zu |\n| OctoMap nodes per metre (second half) | %.1f | %.1f |\n",
                s.at("samples").get<std::size_t>(), 1e6 * s.at("step_with_map_s").get<double>(),
                1e6 * s.at("step_without_map_s").get<double>(), 1e6 * s.at("map_update_s").get<double>(),
                100 * s.at("map_update_share").get<double>(), 1e6 * s.at("octomap_insert_s").get<double>(),
                1e3 * s.at("score_s").get<double>(), s["long_walk"]["windowed"]["walked_m"].back().get<double>(),
                s["long_walk"]["windowed"]["window_m"].get<double>(), s["long_walk"]["unbounded"]["window_m"].get<double>(),
                s["long_walk"]["windowed"]["grid_bytes"].back().get<std::size_t>(),
                s["long_walk"]["unbounded"]["grid_bytes"].back().get<std::size_t>(),
                s["long_walk"]["windowed"]["grid_bytes_per_m"].get<double>(),
                s["long_walk"]["unbounded"]["grid_bytes_per_m"].get<double>(),
                s["long_walk"]["windowed"]["octomap_nodes"].back().get<std::size_t>(),
                s["long_walk"]["unbounded"]["octomap_nodes"].back().get<std::size_t>(),
                s["long_walk"]["windowed"]["octomap_nodes_per_m"].get<double>(),
                s["long_walk"]["unbounded"]["octomap_nodes_per_m"].get<double>());
  return text;
}

}  // namespace proxsim::bench
