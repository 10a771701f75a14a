// Google Benchmark micro-benchmarks of one sample step's fixed costs, apart
// from the rays: moving the robot's link bodies and rebuilding the top-level
// scene (RayCaster::Commit), and one whole Simulation::Step of the paper's
// scenario, of a 64-beam one, and of the bench's heavy scenario in the
// 1M-triangle room, and the paper's walk whole with and without a multi-zone
// sensor on each shin. Run: build/release/proxsim_microbench
#include <benchmark/benchmark.h>

#include <string>

#include "bench/bench_scene.h"
#include "scenario/scenario.h"
#include "raycast/ray_caster.h"
#include "sim/make_locomotion.h"
#include "sim/robot_in_scene.h"
#include "sim/simulation.h"

namespace {

using proxsim::Scenario;

/// The paper's scenario, or the same walk with 64 beams of 32 rays at 1 kHz.
Scenario StepScenario(bool beams) {
  Scenario scenario = proxsim::LoadBuiltinScenario("paper");
  scenario.duration_s = 1000.0;  // never done within a benchmark
  if (!beams) return scenario;
  scenario.rate_hz = 1000;
  const proxsim::SensorConfig model = scenario.sensors[2];  // the ultrasonic sensor
  scenario.sensors.clear();
  for (int m = 0; m < 64; ++m) {
    proxsim::SensorConfig sensor = model;
    sensor.name = "m" + std::to_string(m);
    sensor.link = m % 2 ? "left_tibia" : "right_tibia";
    sensor.spec.beam = proxsim::BeamSpec{.aperture_deg = 25.0, .rays = 32, .pattern = proxsim::BeamPattern::kUniform,
                                         .width_deg = 10.0, .table = {}};
    scenario.sensors.push_back(sensor);
  }
  return scenario;
}

void BM_MoveRobotAndCommit(benchmark::State& state) {
  const Scenario scenario = StepScenario(false);
  proxsim::RayCaster caster;
  const auto locomotion = proxsim::MakeLocomotion(*scenario.robot, scenario.rate_hz);
  proxsim::RobotInScene robot(locomotion->model(), caster, 0);
  double t_s = 0;
  std::vector<proxsim::Hit> hit(1);
  for (auto _ : state) {
    robot.Place(locomotion->Advance(t_s += 0.001));
    caster.Commit();
    // one ray down onto the pelvis, which is cast into the pelvis's own scene
    // (the robot has no top-level scene to commit: ray_caster_internal.h)
    const proxsim::Vec3 p_W = robot.X_WL(robot.model().root_link()).translation() + proxsim::Vec3(0, 0, 1);
    const proxsim::Ray ray{.origin_W = p_W.cast<float>(), .direction_W = -proxsim::Vec3f::UnitZ(), .max_range_m = 2.0f};
    caster.Cast({&ray, 1}, hit);
    benchmark::DoNotOptimize(hit[0].distance_m);
  }
}
BENCHMARK(BM_MoveRobotAndCommit);

void BM_MoveRobotOnly(benchmark::State& state) {
  const Scenario scenario = StepScenario(false);
  proxsim::RayCaster caster;
  const auto locomotion = proxsim::MakeLocomotion(*scenario.robot, scenario.rate_hz);
  proxsim::RobotInScene robot(locomotion->model(), caster, 0);
  double t_s = 0;
  for (auto _ : state) robot.Place(locomotion->Advance(t_s += 0.001));
}
BENCHMARK(BM_MoveRobotOnly);

void BM_SimulationStep(benchmark::State& state) {
  const Scenario scenario = StepScenario(state.range(0) != 0);
  proxsim::Simulation simulation(scenario, static_cast<int>(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(simulation.Step());
  state.SetLabel(state.range(0) ? "64 beams x 32 rays" : "paper, 4 sensors");
}
BENCHMARK(BM_SimulationStep)->Args({0, 1})->Args({1, 1})->Args({1, 2})->UseRealTime();

// The paper's walk with a VL53L5CX on each shin, read at every sample (the
// `multizone` line of `proxsim bench --only e2e`): the whole 5 s walk.
void BM_MultizoneWalk(benchmark::State& state) {
  const Scenario scenario = proxsim::bench::ZonedPaperScenario(static_cast<double>(state.range(0)));
  for (auto _ : state) {
    proxsim::Simulation simulation(scenario, 1);
    while (!simulation.done()) simulation.Step();
  }
}
BENCHMARK(BM_MultizoneWalk)->Arg(0)->Arg(15)->Unit(benchmark::kMillisecond);

// The paper's own walk, the same way: what the `multizone` line compares against.
void BM_PaperWalk(benchmark::State& state) {
  const Scenario scenario = proxsim::LoadBuiltinScenario("paper");
  for (auto _ : state) {
    proxsim::Simulation simulation(scenario, 1);
    while (!simulation.done()) simulation.Step();
  }
}
BENCHMARK(BM_PaperWalk)->Unit(benchmark::kMillisecond);

// The heavy scenario of `proxsim bench`: 64 beams of 32 rays in the 1M-triangle room.
void BM_HeavyStep1M(benchmark::State& state) {
  static const proxsim::bench::BenchScene scene = proxsim::bench::MakeBenchDiningRoom(1'000'000);
  const Scenario scenario = proxsim::bench::HeavyScenario(scene, 64, 32, 1000.0);
  proxsim::Simulation simulation(scenario, static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(simulation.Step());
}
BENCHMARK(BM_HeavyStep1M)->Arg(1)->Arg(2)->UseRealTime()->Iterations(1000);

}  // namespace
