#include "output/readings_csv.h"

#include <filesystem>

#include "core/number_format.h"
#include "core/text_fields.h"

namespace proxsim {

ReadingsCsvWriter::ReadingsCsvWriter(const std::string& out_dir, const Scenario& scenario,
                                     std::vector<std::string> object_names)
    : out_dir_(out_dir),
      file_((std::filesystem::path(out_dir) / "readings.csv").string()),
      scenario_(scenario),
      names_(scenario, std::move(object_names)) {
  file_.Write(ReadingsCsvHeader(scenario.range_convention));
  file_.Write('\n');
  line_.reserve(512);
}

void ReadingsCsvWriter::Add(const SampleFrame& frame) {
  for (std::size_t i = 0; i < frame.sensors.size(); ++i) {
    const SensorSample& s = frame.sensors[i];
    if (s.reading.status == ReadingStatus::kNotSampled) continue;  // no row between a sensor's own samples
    const ReadingRow row{frame, i, scenario_.sensors[i], s};
    line_.clear();
    bool first = true;
    for (const ReadingsColumn& column : ReadingsColumns(scenario_.range_convention)) {
      if (!first) line_ += ',';
      first = false;
      const double value = column.value(row);
      switch (column.type) {
        case ColumnType::kFloat64: AppendNumber(line_, value); break;  // NaN: empty
        case ColumnType::kInt32: line_ += std::to_string(static_cast<long long>(value)); break;
        case ColumnType::kCode32:
        case ColumnType::kCode8:
          if (value >= 0) AppendCsvField(line_, names_[column.codes][static_cast<std::size_t>(value)]);
          break;
        case ColumnType::kBool: line_ += value != 0 ? '1' : '0'; break;
      }
    }
    line_ += '\n';
    file_.Write(line_);
  }
}

void ReadingsCsvWriter::Commit() {
  file_.Commit();
  WriteFileAtomically((std::filesystem::path(out_dir_) / "columns.json").string(), ColumnsJson(names_).dump(1) + "\n");
}

void ReadingsCsvWriter::AddToSummary(nlohmann::json& summary) const {
  summary["outputs"].push_back("readings.csv");
  summary["outputs"].push_back("columns.json");
}

}  // namespace proxsim
