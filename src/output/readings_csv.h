// readings.csv: the distance curves, one row per sensor per sample, streamed
// as the run goes (docs/outputs.md), and columns.json beside it describing
// its columns. Empty fields mean "none": no hit, no reflectance signal for a
// time-of-flight sensor, no robot. The columns are output/readings_columns.h's.
#pragma once

#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "output/readings_columns.h"
#include "output/run_sink.h"
#include "scenario/scenario.h"

namespace proxsim {

class ReadingsCsvWriter : public RunSink {
 public:
  /// Writes `out_dir`/readings.csv and `out_dir`/columns.json; `object_names[id]`
  /// names the objects a hit may report.
  ReadingsCsvWriter(const std::string& out_dir, const Scenario& scenario, std::vector<std::string> object_names);

  void Add(const SampleFrame& frame) override;
  void Commit() override;
  void AddToSummary(nlohmann::json& summary) const override;

 private:
  std::string out_dir_;
  AtomicFile file_;
  const Scenario& scenario_;
  ColumnNames names_;
  std::string line_;  // reused for every row
};

}  // namespace proxsim
