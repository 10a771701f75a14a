// A whole run: step the simulation to the end, stream the readings and the
// profile to the output folder, and write the summary. Every file appears
// under its final name only when it is complete.
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "scenario/scenario.h"
#include "run/run_recorder.h"

namespace proxsim {

struct RunOptions {
  std::string out_dir = "proxsim-out";
  ReadingsFormat format = ReadingsFormat::kCsv;
  int threads = 1;        ///< ray-casting threads, >= 1
  bool force = false;     ///< write into a non-empty folder that holds no previous run (--force)
  bool progress = false;  ///< print a progress line to stderr while running
  /// When set and non-zero (a signal number, say), the run stops after the
  /// current sample, commits every file and marks summary.json interrupted.
  const std::atomic<int>* stop_signal = nullptr;
  /// Receives warnings about suspicious but legal input (a sensor that starts
  /// inside an object); they are also listed in summary.json.
  std::function<void(const std::string&)> warn;
  /// Called when loading is over, before the output folder is touched.
  std::function<void()> on_loaded;
};

struct RunResult {
  nlohmann::json summary;  ///< what was written to summary.json
  double wall_s = 0.0;     ///< wall time of the simulation loop and its outputs
  bool interrupted = false;  ///< stopped early through RunOptions::stop_signal
  /// The output folder, still locked: hold it while drawing the report; null without files.
  std::shared_ptr<OutputFolder> folder;
};

/// Runs a validated scenario; throws std::runtime_error on I/O failure.
/// `on_loaded` (when set) is called once the scenario's world is built, just
/// before the folder is touched: the CLI arms its interruptible stop there.
RunResult RunScenario(const Scenario& scenario, const RunOptions& options);

/// timings.json: wall times and simulated seconds per wall second, listed in the run's manifest.
void WriteTimings(const std::string& out_dir, double wall_s, double loop_wall_s, int threads, std::int64_t samples,
                  double rate_hz);

}  // namespace proxsim
