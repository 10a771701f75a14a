// One of a run's outputs: fed every sample as it is taken, completed at the
// end, and reporting what it wrote in summary.json. The readings (CSV or
// npy), the profile, the poses, the terrain map and the statistics are each a
// sink; the run keeps a list of them and names none.
#pragma once

#include <nlohmann/json.hpp>

#include "sim/sample_frame.h"

namespace proxsim {

class RunSink {
 public:
  virtual ~RunSink() = default;

  /// The sample just taken.
  virtual void Add(const SampleFrame& frame) = 0;

  /// Completes the sink's files under their final names (a sink that writes
  /// none has nothing to do).
  virtual void Commit() {}

  /// Adds what the sink reports to summary.json: its files to "outputs", its
  /// figures under its own keys. Called before or after Commit().
  virtual void AddToSummary(nlohmann::json& summary) const = 0;
};

}  // namespace proxsim
