// readings.csv: the distance curves, one row per sensor per sample, streamed
// as the run goes (docs/outputs.md). Empty fields mean "none": no hit,
// no reflectance signal for a time-of-flight sensor, no robot.
#pragma once

#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "scenario/scenario.h"
#include "sim/sample_frame.h"

namespace proxsim {

/// The header line, without its newline.
extern const char* const kReadingsCsvHeader;

class ReadingsCsvWriter {
 public:
  /// `object_names[id]` names the objects a hit may report.
  ReadingsCsvWriter(const std::string& path, const Scenario& scenario, std::vector<std::string> object_names);

  void Append(const SampleFrame& frame);
  void Commit() { file_.Commit(); }

 private:
  AtomicFile file_;
  const Scenario& scenario_;
  std::vector<std::string> object_names_;
  std::string line_;  // reused for every row
};

}  // namespace proxsim
