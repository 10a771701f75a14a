// Google Benchmark micro-benchmarks of a closed-loop study's episode (issue
// 26's runs per second per core, `proxsim bench --only outcomes`) and of its
// hottest query, the robot's clearance to a generated room's furniture
// (RayCaster::DistanceToWorld: the bounding-sphere culls of bodies and
// shapes). Run: build/release/proxsim_microbench --benchmark_filter=Outcome\|Room
#include <benchmark/benchmark.h>

#include <string>

#include "bench/outcome_bench.h"
#include "scenario/scenario.h"
#include "scenario/scenario_generate.h"
#include "sim/world.h"
#include "study/outcome_runner.h"

namespace {

// A 10 x 10 m room at difficulty 0.5 (seed `seed`), the builtin biped with
// 8 lasers on its shins and the stop rule: the bench's outcome study's run.
std::string EpisodeText(int seed) {
  return "proxsim: 1\nseed: " + std::to_string(seed) +
         "\nduration_s: 10.0\nrate_hz: 50\nscene: {generate: {kind: room, difficulty: 0.5, seed: " +
         std::to_string(seed) +
         "}}\nrobot:\n  model: builtin:biped\n  gait: {stride_m: 0.6, period_s: 1.2}\n  strategy: {name: stop}\n"
         "sensors: " + proxsim::bench::EightShinLasers() + "\n";
}

// One whole episode (generate, load, build, walk to its end) per iteration,
// over 20 rooms in turn.
void BM_OutcomeEpisode(benchmark::State& state) {
  int seed = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(proxsim::RunEpisode(EpisodeText(1 + seed), "bench"));
    seed = (seed + 1) % 20;
  }
}
BENCHMARK(BM_OutcomeEpisode)->Unit(benchmark::kMillisecond);

// A clearance query: the distance from a point 0.05–0.6 m high along the
// room's walk to everything but the ground, capped at 0.2 m.
void BM_RoomClearanceQuery(benchmark::State& state) {
  proxsim::Scenario scenario =
      proxsim::LoadScenarioText(proxsim::GeneratedScenarioText(EpisodeText(3), "bench"), "bench");
  scenario.sensors.clear();  // the room alone (the sensors' links are the robot's)
  const proxsim::World world(scenario, nullptr, 1);
  int i = 0;
  for (auto _ : state) {
    const proxsim::Vec3 p_W(0.01 * (i % 800), 0.3 * ((i / 800) % 3 - 1), 0.05 + 0.05 * (i % 12));
    benchmark::DoNotOptimize(world.caster().DistanceToWorld(p_W, world.ground_ids(), 0.2));
    ++i;
  }
}
BENCHMARK(BM_RoomClearanceQuery);

}  // namespace
