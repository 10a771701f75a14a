// A run's files, written while a Simulation is stepped: readings (CSV or
// npy), profile.ply, poses.csv, the terrain map's rays into the OctoMap tree,
// then terrain/ (terrain/terrain_files.h), scene.json and summary.json at the end.
// Used by `proxsim run` and by the Python package's Simulation(out=DIR), so
// that both write the same files for the same scenario and seed. Each file
// appears under its final name only when it is complete.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/simulation.h"

namespace proxsim {

/// How the readings are written: readings.csv, or one .npy per column in readings/.
enum class ReadingsFormat { kCsv, kNpy };

class RunRecorder {
 public:
  /// Creates `out_dir` and opens the streamed files (an empty out_dir: no
  /// files, the statistics only); `sim` must outlive the recorder. `warn`
  /// receives warnings about suspicious but legal input.
  RunRecorder(const Simulation& sim, const std::string& out_dir, ReadingsFormat format,
              std::function<void(const std::string&)> warn = {});
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

 private:
  struct Writers;
  nlohmann::json SummaryWith(bool interrupted, nlohmann::json terrain) const;
  const Simulation& sim_;
  std::string out_dir_;
  ReadingsFormat format_;
  std::function<void(const std::string&)> warn_;
  std::unique_ptr<Writers> writers_;
  std::vector<std::string> warnings_;
  std::int64_t samples_ = 0;
  std::int64_t profile_points_ = 0;  // detections: the points profile.ply holds
  double last_t_s_ = 0;
};

}  // namespace proxsim
