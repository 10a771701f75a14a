#include "fidelity/recording_csv.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "core/input_error.h"
#include "core/input_limits.h"
#include "core/nearest_key.h"
#include "core/text_fields.h"

namespace proxsim {

namespace {

// The columns, in the order of the documented header; `zone` may be left out
// by a single-zone part.
enum RecordingColumn { kColT, kColX, kColY, kColZ, kColQw, kColQx, kColQy, kColQz, kColZone, kColD, kColValid, kRecordingColumns };
const std::vector<std::string>& RecordingColumnNames() {
  static const std::vector<std::string> names = {"t_s", "x_m", "y_m", "z_m", "qw",  "qx",
                                                 "qy",  "qz",  "zone", "d_m", "valid"};
  return names;
}
constexpr const char* kRecordingHeader = "t_s,x_m,y_m,z_m,qw,qx,qy,qz,zone,d_m,valid";
constexpr std::size_t kMaxRecordingProblems = 20;
// A quaternion further than this from unit length is a wrong column, not rounding.
constexpr double kUnitQuaternionTolerance = 1e-3;
// Rows of one sample repeat its pose: the same text, so the same number to rounding.
constexpr double kSamePoseTolerance = 1e-9;

// A recorded time in messages, to the digits a recording gives.
std::string FormatRecordedTime(double t_s) {
  std::ostringstream text;
  text.precision(9);
  text << t_s;
  return text.str();
}

// Collects "FILE:LINE: column 'NAME' (N): message" problems up to the cap.
class RecordingProblems {
 public:
  explicit RecordingProblems(std::string source) : source_(std::move(source)) {}
  void At(int line, const std::string& message) {
    const std::string where = line > 0 ? source_ + ":" + std::to_string(line) : source_;
    if (problems_.size() < kMaxRecordingProblems) problems_.push_back(where + ": " + message);
    ++count_;
  }
  void InColumn(int line, int column_index, int column, const std::string& message) {
    At(line, "column '" + RecordingColumnNames()[column] + "' (" + std::to_string(column_index + 1) + "): " + message);
  }
  bool full() const { return count_ >= kMaxRecordingProblems; }
  void ThrowIfAny() {
    if (problems_.empty()) return;
    if (count_ > problems_.size()) problems_.push_back(source_ + ": more problems not listed (the first " +
                                                       std::to_string(problems_.size()) + " are)");
    throw InputError(problems_);
  }

 private:
  std::string source_;
  std::vector<std::string> problems_;
  std::size_t count_ = 0;
};

// The header: each column's cell index (-1: absent); problems for unknown,
// repeated and missing columns.
std::array<int, kRecordingColumns> ReadRecordingHeader(const std::vector<std::string>& cells, int line, int zone_count,
                                                       RecordingProblems& problems) {
  std::array<int, kRecordingColumns> index;
  index.fill(-1);
  const auto& names = RecordingColumnNames();
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const auto known = std::find(names.begin(), names.end(), cells[c]);
    if (known == names.end()) {
      const auto nearest = NearestKey(cells[c], names);
      problems.At(line, "column " + std::to_string(c + 1) + ": unknown column '" + cells[c] + "'" +
                            (nearest ? " (did you mean '" + *nearest + "'?)" : "") + "; expected the header " +
                            kRecordingHeader);
      continue;
    }
    int& slot = index[known - names.begin()];
    if (slot >= 0) problems.At(line, "column " + std::to_string(c + 1) + ": '" + cells[c] + "' appears twice");
    slot = static_cast<int>(c);
  }
  for (int column = 0; column < kRecordingColumns; ++column) {
    if (index[column] >= 0 || (column == kColZone && zone_count == 1)) continue;
    problems.At(line, "missing column '" + names[column] + "'" +
                          (column == kColZone ? " (the part has " + std::to_string(zone_count) + " zones)" : "") +
                          "; expected the header " + kRecordingHeader);
  }
  return index;
}

// The sample being read: where its rows started and which zones it has listed.
struct OpenSample {
  int first_line = 0;
  std::vector<char> listed;  // [zone]
};

// A sample without every zone is a recording of another grid, or a cut file.
void CheckSampleComplete(const OpenSample& open, const Recording& recording, RecordingProblems& problems) {
  std::string missing;
  int missing_count = 0;
  for (int zone = 0; zone < recording.zone_count; ++zone) {
    if (open.listed[zone]) continue;
    if (++missing_count <= 8) missing += (missing.empty() ? "" : ", ") + std::to_string(zone);
  }
  if (missing_count == 0) return;
  problems.At(open.first_line, "the sample at t_s = " + FormatRecordedTime(recording.t_s.back()) + " lists " +
                                   std::to_string(recording.zone_count - missing_count) + " of the part's " +
                                   std::to_string(recording.zone_count) + " zones (missing " + missing +
                                   (missing_count > 8 ? ", …" : "") + "); expected one row per zone per sample");
}

// One data row, read and checked.
struct RecordingRow {
  double t_s;
  Pose X_WM;
  int zone;
  double d_m;  // NaN where not valid
  bool valid;
};

// The row's cells (`column`: each column's cell) as a RecordingRow; nullopt
// after reporting every problem it has.
std::optional<RecordingRow> ReadRecordingRow(const std::vector<std::string>& cells,
                                             const std::array<int, kRecordingColumns>& column, int line, int zone_count,
                                             RecordingProblems& problems) {
  // the numbers of the row (d_m may be empty where the reading is not valid)
  std::array<double, kRecordingColumns> value{};
  bool row_ok = true;
  for (int c = 0; c < kRecordingColumns; ++c) {
    if (column[c] < 0 || c == kColValid) continue;
    const std::string& cell = cells[column[c]];
    if (c == kColD && cell.empty()) {
      value[c] = std::numeric_limits<double>::quiet_NaN();
    } else if (!ParseFiniteNumber(cell, &value[c])) {
      problems.InColumn(line, column[c], c, "expected a finite number, got '" + cell + "'");
      row_ok = false;
    }
  }
  const std::string& valid_cell = cells[column[kColValid]];
  const bool valid = valid_cell == "1" || valid_cell == "true";
  if (!valid && valid_cell != "0" && valid_cell != "false") {
    problems.InColumn(line, column[kColValid], kColValid, "expected 1 (a valid target) or 0, got '" + valid_cell + "'");
    row_ok = false;
  }
  if (!row_ok) return std::nullopt;
  // each field within its bounds
  for (const int c : {kColX, kColY, kColZ}) {
    if (std::abs(value[c]) > kMaxCoordinate_m) {
      problems.InColumn(line, column[c], c,
                        "expected a coordinate within ±100000 m (rays are cast in single precision), got " +
                            cells[column[c]]);
      row_ok = false;
    }
  }
  const double zone_value = column[kColZone] >= 0 ? value[kColZone] : 0.0;
  if (!(zone_value >= 0 && zone_value < zone_count && zone_value == std::floor(zone_value))) {
    problems.InColumn(line, column[kColZone], kColZone,
                      "expected a zone index, a whole number in [0, " + std::to_string(zone_count - 1) + "], got " +
                          cells[column[kColZone]]);
    row_ok = false;
  }
  if (valid && !(value[kColD] >= 0)) {
    problems.InColumn(line, column[kColD], kColD,
                      "expected the reported distance, >= 0 m, where valid is 1, got '" + cells[column[kColD]] + "'");
    row_ok = false;
  }
  const Eigen::Quaterniond q(value[kColQw], value[kColQx], value[kColQy], value[kColQz]);
  if (std::abs(q.norm() - 1.0) > kUnitQuaternionTolerance) {
    problems.InColumn(line, column[kColQw], kColQw,
                      "qw, qx, qy, qz: expected a unit quaternion (w first), got one of norm " + std::to_string(q.norm()));
    row_ok = false;
  }
  if (!row_ok) return std::nullopt;
  RecordingRow row{
      .t_s = value[kColT], .X_WM = Pose::Identity(), .zone = static_cast<int>(zone_value), .d_m = value[kColD], .valid = valid};
  row.X_WM.translation() = Vec3(value[kColX], value[kColY], value[kColZ]);
  row.X_WM.linear() = q.normalized().toRotationMatrix();
  if (!valid) row.d_m = std::numeric_limits<double>::quiet_NaN();
  return row;
}

}  // namespace

Recording ParseRecording(const std::string& text, const std::string& source, int zone_count) {
  Recording recording;
  recording.source = source;
  recording.zone_count = zone_count;
  RecordingProblems problems(source);
  std::istringstream in(text);
  std::string line_text;
  int line = 0;
  std::optional<std::array<int, kRecordingColumns>> column;
  std::size_t header_cells = 0;
  OpenSample open;
  while (!problems.full() && std::getline(in, line_text)) {
    ++line;
    const std::size_t first = line_text.find_first_not_of(" \t\r");
    if (first == std::string::npos || line_text[first] == '#') continue;  // blank lines and comments
    const std::vector<std::string> cells = SplitCsvLine(line_text);
    if (!column) {
      column = ReadRecordingHeader(cells, line, zone_count, problems);
      header_cells = cells.size();
      problems.ThrowIfAny();
      continue;
    }
    if (cells.size() != header_cells) {
      problems.At(line, std::to_string(cells.size()) + " cells, expected " + std::to_string(header_cells) +
                            " as the header has");
      continue;
    }
    const std::optional<RecordingRow> row = ReadRecordingRow(cells, *column, line, zone_count, problems);
    if (!row) continue;

    // a new sample where the time moves on; its rows share its pose
    const double t_s = row->t_s;
    const bool same_sample = !recording.t_s.empty() && t_s == recording.t_s.back();
    if (!same_sample) {
      if (!recording.t_s.empty()) {
        CheckSampleComplete(open, recording, problems);
        if (!(t_s > recording.t_s.back())) {
          problems.InColumn(line, (*column)[kColT], kColT, "expected a time after the previous sample's (" +
                                                         FormatRecordedTime(recording.t_s.back()) + " s), got " +
                                                         cells[(*column)[kColT]]);
          continue;
        }
      }
      recording.t_s.push_back(t_s);
      recording.X_WM.push_back(row->X_WM);
      recording.first_line.push_back(line);
      recording.d_m.resize(recording.d_m.size() + zone_count, std::numeric_limits<double>::quiet_NaN());
      recording.valid.resize(recording.valid.size() + zone_count, 0);
      open = OpenSample{line, std::vector<char>(zone_count, 0)};
    } else if ((row->X_WM.matrix() - recording.X_WM.back().matrix()).cwiseAbs().maxCoeff() > kSamePoseTolerance) {
      problems.At(line, "the pose differs from the one on line " + std::to_string(open.first_line) +
                            " of the same sample (t_s = " + cells[(*column)[kColT]] + "); a sample's rows share its pose");
      continue;
    }
    const int zone = row->zone;
    if (open.listed[zone]) {
      problems.InColumn(line, (*column)[kColZone], kColZone, "zone " + std::to_string(zone) + " appears twice in the "
                                                           "sample at t_s = " + cells[(*column)[kColT]]);
      continue;
    }
    open.listed[zone] = 1;
    const std::size_t slot = (recording.t_s.size() - 1) * static_cast<std::size_t>(zone_count) + zone;
    recording.valid[slot] = row->valid ? 1 : 0;
    recording.d_m[slot] = row->d_m;
  }
  if (!column) problems.At(0, "no header; expected " + std::string(kRecordingHeader) + " and one row per zone per sample");
  if (column && recording.t_s.empty()) problems.At(line, "no data rows after the header");
  if (!recording.t_s.empty()) CheckSampleComplete(open, recording, problems);
  problems.ThrowIfAny();
  return recording;
}

Recording LoadRecording(const std::string& path, int zone_count) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot open the recording (missing or unreadable)");
  std::ostringstream text;
  text << file.rdbuf();
  return ParseRecording(text.str(), path, zone_count);
}

}  // namespace proxsim
