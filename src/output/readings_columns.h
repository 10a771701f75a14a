// The readings' columns, each defined once — name, type, unit, meaning and how
// its value comes out of a sample. readings.csv's header and rows, the npy
// files in readings/, columns.json (which the report's reader reads) and the
// table in docs/outputs.md (`proxsim columns`) are all made from this table.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenario/scenario.h"
#include "sim/sample_frame.h"

namespace proxsim {

/// How a column's values are stored.
enum class ColumnType {
  kFloat64,  ///< a number; NaN for none (an empty CSV field)
  kInt32,    ///< an integer, written as such in the CSV too
  kCode32,   ///< an index into a list of names (the CSV writes the name); −1 for none
  kCode8,    ///< the same in one byte; 255 for none
  kBool,     ///< 0 or 1
};

/// The lists of names that coded columns index (columns.json's keys).
enum class ColumnCodes { kNone, kSensors, kTypes, kStatuses, kObjects, kSupportLegs };

/// One sensor's row at one sample.
struct ReadingRow {
  const SampleFrame& frame;
  std::size_t sensor;  ///< index in the scenario's sensors
  const SensorConfig& config;
  const SensorSample& sample;
};

struct ReadingsColumn {
  const char* name;
  ColumnType type;
  ColumnCodes codes;  ///< for kCode32/kCode8: the names the codes index
  const char* unit;   ///< "" when the value has none
  const char* meaning;
  /// The row's value: NaN for a float with none, −1 for a code with none.
  double (*value)(const ReadingRow& row);
};

/// Every column, in the files' order: the paper's convention (the default),
/// or REP 117's (d_m ±inf/NaN without a detection, and variance_m2 after it).
std::span<const ReadingsColumn> ReadingsColumns(RangeConvention convention = RangeConvention::kProxsim);

/// The numpy dtype of a column type: "<f8", "<i4", "|u1" or "|b1".
const char* NpyDtype(ColumnType type);

/// columns.json's key for a list of names ("sensors", "types", ...).
const char* ColumnCodesKey(ColumnCodes codes);

/// The names each kind of code stands for in one run.
class ColumnNames {
 public:
  ColumnNames(const Scenario& scenario, std::vector<std::string> object_names);
  const std::vector<std::string>& operator[](ColumnCodes codes) const;
  RangeConvention convention() const { return convention_; }

 private:
  RangeConvention convention_;
  std::vector<std::string> sensors_, types_, statuses_, objects_, support_legs_;
};

/// readings.csv's header line, without its newline.
std::string ReadingsCsvHeader(RangeConvention convention = RangeConvention::kProxsim);

/// columns.json: each column (name, dtype, unit, meaning, codes) and every list of names.
nlohmann::json ColumnsJson(const ColumnNames& names);

/// The columns as a Markdown table (column, type, unit, meaning), for docs/outputs.md.
std::string ReadingsColumnsMarkdown();

}  // namespace proxsim
