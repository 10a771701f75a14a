// A run's files, written while a Simulation is stepped: each output is a sink
// (output/run_sink.h) — the readings (CSV or npy), profile.ply, poses.csv, the
// terrain map, the statistics — fed every sample; at the end the sinks
// complete their files, then scene.json, summary.json and the manifest.
// Used by `proxsim run` and by the Python package's Simulation(out=DIR), so
// that both write the same files for the same scenario and seed. Each file
// appears under its final name only when it is complete.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/output_folder.h"
#include "output/readings_sink.h"
#include "output/run_sink.h"
#include "run/mounting_warnings.h"
#include "sim/simulation.h"

namespace proxsim {

class RunRecorder {
 public:
  /// Claims `out_dir` (core/output_folder.h: refused when it is "/", the
  /// home folder, held by another process, or not empty and not a previous
  /// run's unless `force`), removes the previous run's files and opens the
  /// streamed files (an empty out_dir: no files, the statistics only); `sim`
  /// must outlive the recorder. `warn` receives warnings about suspicious but
  /// legal input.
  RunRecorder(const Simulation& sim, const std::string& out_dir, ReadingsFormat format,
              std::function<void(const std::string&)> warn = {}, bool force = false);
  ~RunRecorder();
  RunRecorder(const RunRecorder&) = delete;
  RunRecorder& operator=(const RunRecorder&) = delete;

  /// Streams the sample just taken (the simulation's frame()).
  void Add(const SampleFrame& frame);

  /// summary.json's content for the samples added so far; `interrupted`: the
  /// episode ended before its last sample. Its `terrain` scores the map as it is.
  nlohmann::json Summary(bool interrupted) const;

  /// Commits every file, writes scene.json and summary.json and returns the summary.
  nlohmann::json Finish(bool interrupted);

  std::int64_t samples() const { return samples_; }

  /// The claimed folder's real path (empty without files); write beside the run's files through it.
  const std::string& out_dir() const { return out_dir_; }
  /// The claimed folder (its lock), to hold past the recorder (the report); null without files.
  std::shared_ptr<OutputFolder> folder() const { return folder_; }
  /// Lets the folder go (its lock ends with the last holder) once the files are written.
  void ReleaseFolder() { folder_.reset(); }

 private:
  const Simulation& sim_;
  std::shared_ptr<OutputFolder> folder_;  ///< claimed and locked while the recorder (or a holder) lives
  std::string out_dir_;                   ///< folder_'s real path
  std::function<void(const std::string&)> warn_;
  std::vector<std::unique_ptr<RunSink>> sinks_;
  std::vector<std::string> warnings_;  // said at the first sample
  MountingWatch mounting_;            // said at the end
  std::int64_t samples_ = 0;
  double last_t_s_ = 0;
};

}  // namespace proxsim
