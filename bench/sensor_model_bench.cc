// Google Benchmark micro-benchmarks of the per-ray work on top of the ray
// caster: the sensor model (Measure, per preset) and the keyed noise
// (Philox4x32-10 + Box–Muller). Run: build/release/proxsim_microbench
// The whole-pipeline race against Embree, Bullet and MuJoCo is `proxsim bench`.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "sensors/noise.h"
#include "sensors/sensor_model.h"
#include "sensors/sensor_spec.h"

namespace {

using proxsim::Echo;
using proxsim::SensorSpec;
using proxsim::SensorType;

/// 1024 echoes spread over distance and incidence, some misses (inputs to Measure).
std::vector<Echo> SampleEchoes() {
  std::vector<Echo> echoes(1024);
  for (std::size_t i = 0; i < echoes.size(); ++i) {
    if (i % 8 == 7) continue;  // a miss
    echoes[i].distance_m = 0.02 + 2.2 * static_cast<double>(i) / echoes.size();
    echoes[i].incidence_deg = static_cast<double>((i * 37) % 90);
  }
  return echoes;
}

void BM_Measure(benchmark::State& state) {
  const SensorSpec spec = SensorSpec::Preset(static_cast<SensorType>(state.range(0)));
  const std::vector<Echo> echoes = SampleEchoes();
  std::size_t i = 0;
  for (auto _ : state) {
    const Echo& echo = echoes[i++ & 1023];
    benchmark::DoNotOptimize(proxsim::Measure(spec, echo, 0.3));
  }
  state.SetLabel(proxsim::SensorTypeName(spec.type));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Measure)
    ->Arg(static_cast<int>(SensorType::kIdeal))
    ->Arg(static_cast<int>(SensorType::kLaser))
    ->Arg(static_cast<int>(SensorType::kUltrasonic))
    ->Arg(static_cast<int>(SensorType::kReflectance));

void BM_IncidenceDeg(benchmark::State& state) {
  double x = 0.3;
  for (auto _ : state) {
    x += 1e-9;
    benchmark::DoNotOptimize(proxsim::IncidenceDeg(0.8, 0.6, 0.0, x, 0.0, 0.95));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_IncidenceDeg);

void BM_KeyedUniforms(benchmark::State& state) {
  std::uint64_t sample = 0;
  for (auto _ : state) benchmark::DoNotOptimize(proxsim::KeyedUniforms({7, 3, sample++, 0}));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_KeyedUniforms);

void BM_BoxMuller(benchmark::State& state) {
  double u = 0.25;
  for (auto _ : state) {
    u = u < 0.99 ? u + 1e-7 : 0.25;
    benchmark::DoNotOptimize(proxsim::BoxMuller(u, 1 - u));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_BoxMuller);

void BM_KeyedGaussian(benchmark::State& state) {
  std::uint64_t sample = 0;
  for (auto _ : state) benchmark::DoNotOptimize(proxsim::KeyedGaussian({7, 3, sample++, 0}));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_KeyedGaussian);

/// The model's part of proxsim's per-ray cost: draw + Measure, as the simulation does it.
void BM_DrawAndMeasure(benchmark::State& state) {
  const SensorSpec spec = SensorSpec::Preset(SensorType::kLaser);
  const std::vector<Echo> echoes = SampleEchoes();
  std::uint64_t sample = 0;
  for (auto _ : state) {
    const double g = proxsim::KeyedGaussian({7, 3, sample, 0});
    benchmark::DoNotOptimize(proxsim::Measure(spec, echoes[sample++ & 1023], g));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_DrawAndMeasure);

}  // namespace

BENCHMARK_MAIN();
