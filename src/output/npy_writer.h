// The readings as columns (`proxsim run --format npy`): one NumPy .npy file
// per column of readings.csv in OUT/readings/, for runs too large for a CSV
// (thousands of rays at kHz rates). Same rows (none between a sensor's own
// samples), same order, same meaning as the CSV; the columns, their dtypes and
// what a code stands for are output/readings_columns.h's, written into
// OUT/readings/columns.json with the row count. numpy.load(OUT/readings/d_m.npy)
// reads a column. The folder is written as OUT/readings.tmp/ and renamed when complete.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "output/readings_columns.h"
#include "output/run_sink.h"
#include "scenario/scenario.h"

namespace proxsim {

class NpyReadingsWriter : public RunSink {
 public:
  /// Writes `out_dir`/readings/; `object_names[id]` names hit objects.
  NpyReadingsWriter(const std::string& out_dir, const Scenario& scenario, std::vector<std::string> object_names);
  ~NpyReadingsWriter();
  NpyReadingsWriter(const NpyReadingsWriter&) = delete;
  NpyReadingsWriter& operator=(const NpyReadingsWriter&) = delete;

  void Add(const SampleFrame& frame) override;
  /// Writes the headers (with the final row count) and columns.json, then renames the folder into place.
  void Commit() override;
  void AddToSummary(nlohmann::json& summary) const override;

  std::int64_t rows() const { return rows_; }

 private:
  struct Column;
  std::string dir_;
  const Scenario& scenario_;
  ColumnNames names_;
  std::vector<std::unique_ptr<Column>> columns_;
  std::int64_t rows_ = 0;
};

}  // namespace proxsim
