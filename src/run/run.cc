#include "run/run.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "output/run_manifest.h"
#include "run/run_recorder.h"
#include "sim/simulation.h"

namespace proxsim {

namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled) : enabled_(enabled) {}
  void Update(std::int64_t done, std::int64_t total, double t_s) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (done < total && now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    std::fprintf(stderr, "\rproxsim: sample %lld/%lld  t = %.2f s  (%3.0f%%)", static_cast<long long>(done),
                 static_cast<long long>(total), t_s, total > 0 ? 100.0 * done / total : 100.0);
    if (done == total) std::fputc('\n', stderr);
  }

 private:
  bool enabled_;
  Clock::time_point last_{};
};

}  // namespace

RunResult RunScenario(const Scenario& scenario, const RunOptions& options) {
  const auto start = Clock::now();
  // everything that can fail on bad input happens before the folder is made
  if (scenario.robot && scenario.robot->locomotion == LocomotionSource::kExternal) {
    throw InputError(scenario.source + ": robot.locomotion: external: the robot's state comes from a caller every "
                     "sample (Python sim.step(q=..., X_WP=...), C++ Simulation::Step(state)); a run on its own has "
                     "none: see docs/cosimulation.md");
  }
  Simulation sim(scenario, options.threads);
  if (options.on_loaded) options.on_loaded();
  RunRecorder recorder(sim, options.out_dir, options.format, options.warn, options.force);
  ProgressLine progress(options.progress);

  // the loop: one sample per step, streamed out as it is taken
  const auto loop_start = Clock::now();
  bool interrupted = false;
  while (!sim.done()) {
    // a stop request (SIGINT, SIGTERM) ends the run between two samples
    if (options.stop_signal != nullptr && options.stop_signal->load() != 0) {
      interrupted = true;
      break;
    }
    const SampleFrame& frame = sim.Step();
    recorder.Add(frame);
    progress.Update(frame.sample + 1, sim.sample_count(), frame.t_s);
  }
  const double loop_wall_s = SecondsSince(loop_start);

  RunResult result;
  result.summary = recorder.Finish(interrupted);
  result.interrupted = interrupted;

  // timings live apart from the summary so that reruns give byte-identical summaries
  result.wall_s = SecondsSince(start);
  if (!recorder.out_dir().empty()) {
    WriteTimings(recorder.out_dir(), result.wall_s, loop_wall_s, options.threads, recorder.samples(),
                 scenario.rate_hz);
  }
  result.folder = recorder.folder();
  return result;
}

void WriteTimings(const std::string& out_dir, double wall_s, double loop_wall_s, int threads, std::int64_t samples,
                  double rate_hz) {
  const double simulated_s = static_cast<double>(samples) / rate_hz;
  const nlohmann::json timings = {{"wall_s", wall_s},
                                  {"loop_wall_s", loop_wall_s},
                                  {"threads", threads},
                                  {"simulated_s_per_wall_s", loop_wall_s > 0 ? simulated_s / loop_wall_s : 0.0}};
  WriteFileAtomically((std::filesystem::path(out_dir) / "timings.json").string(), timings.dump(2) + "\n");
  // listed like every other file of the run, so that `proxsim plot` and the
  // next run into the folder know it (a Python run writes it too)
  AddToRunManifest(out_dir, {"timings.json"});
}

}  // namespace proxsim
