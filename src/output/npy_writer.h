// The readings as columns (`proxsim run --format npy`): one NumPy .npy file
// per column of readings.csv in OUT/readings/, for runs too large for a CSV
// (thousands of rays at kHz rates). Same rows (none between a sensor's own
// samples), same order, same meaning as the CSV; what the CSV writes as text
// is a code here, named in columns.json:
//   t_s, d_m, d_true_m, incidence_deg, signal, hit_{x,y,z}_m, origin_{x,y,z}_m,
//   dir_{x,y,z}, gait_phase, output, t_reported_s
//                                  float64 (<f8); NaN where the CSV is empty
//                                  (output: a lookup sensor's output, NaN for the other
//                                  types; t_reported_s: t_s plus the sensor's latency)
//   sensor                         int32 (<i4): index into columns.json "sensors"
//   object                         int32: index into "objects"; −1 where the CSV is empty
//   ray                            int32: the beam's ray that gave the reading, −1 without
//   type, status, support_leg      uint8 (|u1): index into "types", "statuses", "support_legs";
//                                  support_leg 255 when there is no robot
//   detected                       bool (|b1)
// numpy.load(OUT/readings/d_m.npy) reads a column; every file has `rows` rows.
// The folder is written as OUT/readings.tmp/ and renamed when complete.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "scenario/scenario.h"
#include "sim/sample_frame.h"

namespace proxsim {

class NpyReadingsWriter {
 public:
  /// `dir` is the folder to create (OUT/readings); `object_names[id]` names hit objects.
  NpyReadingsWriter(const std::string& dir, const Scenario& scenario, std::vector<std::string> object_names);
  ~NpyReadingsWriter();
  NpyReadingsWriter(const NpyReadingsWriter&) = delete;
  NpyReadingsWriter& operator=(const NpyReadingsWriter&) = delete;

  void Append(const SampleFrame& frame);
  /// Writes the headers (with the final row count) and columns.json, then renames the folder into place.
  void Commit();

  std::int64_t rows() const { return rows_; }

 private:
  struct Column;
  std::string dir_, tmp_dir_;
  const Scenario& scenario_;
  std::vector<std::string> object_names_;
  std::vector<std::unique_ptr<Column>> columns_;
  std::int64_t rows_ = 0;
  bool committed_ = false;
};

}  // namespace proxsim
