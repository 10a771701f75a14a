#include "output/readings_columns.h"

#include <array>
#include <limits>
#include <string>

#include "sensors/range_inverse.h"

namespace proxsim {

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

bool IsHit(const ReadingRow& row) { return row.sample.object_id >= 0; }

// one entry per column, in the files' order; a value is a double whatever
// the column's type (codes and 32-bit integers are exact in a double)
const std::array<ReadingsColumn, 24> kColumns = {{
    {"t_s", ColumnType::kFloat64, ColumnCodes::kNone, "s", "sample time",
     [](const ReadingRow& r) { return r.frame.t_s; }},
    {"sensor", ColumnType::kCode32, ColumnCodes::kSensors, "", "the sensor's name",
     [](const ReadingRow& r) { return static_cast<double>(r.sensor); }},
    {"type", ColumnType::kCode8, ColumnCodes::kTypes, "",
     "its physics: `ideal`, `laser`, `ultrasonic`, `reflectance`, `lookup` or `multizone` (a named part reports its physics)",
     [](const ReadingRow& r) { return static_cast<double>(r.config.spec.type); }},
    {"status", ColumnType::kCode8, ColumnCodes::kStatuses, "",
     "`ok`, `no_echo`, `too_close`, `grazing`, `self`, `dropout`, `crosstalk` ([sensors.md](sensors.md))",
     [](const ReadingRow& r) { return static_cast<double>(r.sample.reading.status); }},
    {"detected", ColumnType::kBool, ColumnCodes::kNone, "0/1", "1 only for `ok`",
     [](const ReadingRow& r) { return r.sample.reading.detected() ? 1.0 : 0.0; }},
    {"d_m", ColumnType::kFloat64, ColumnCodes::kNone, "m",
     "what the sensor reports: the measured distance, d_max when it detects nothing",
     [](const ReadingRow& r) { return r.sample.reading.d_m; }},
    {"d_true_m", ColumnType::kFloat64, ColumnCodes::kNone, "m",
     "the noise-free distance of the ray's first hit within d_max; none when the ray hit nothing",
     [](const ReadingRow& r) { return IsHit(r) ? r.sample.echo.distance_m : kNone; }},
    {"incidence_deg", ColumnType::kFloat64, ColumnCodes::kNone, "degrees",
     "the incidence at that hit, in [0, 90]; none without a hit",
     [](const ReadingRow& r) { return IsHit(r) ? r.sample.echo.incidence_deg : kNone; }},
    {"signal", ColumnType::kFloat64, ColumnCodes::kNone, "",
     "the reflectance signal s of the paper's Eq. (1); none for the time-of-flight sensors",
     [](const ReadingRow& r) { return r.sample.reading.signal; }},
    {"hit_x_m", ColumnType::kFloat64, ColumnCodes::kNone, "m, world", "the true hit point's x; none without a hit",
     [](const ReadingRow& r) { return r.sample.p_WH.x(); }},
    {"hit_y_m", ColumnType::kFloat64, ColumnCodes::kNone, "m, world", "its y",
     [](const ReadingRow& r) { return r.sample.p_WH.y(); }},
    {"hit_z_m", ColumnType::kFloat64, ColumnCodes::kNone, "m, world", "its z",
     [](const ReadingRow& r) { return r.sample.p_WH.z(); }},
    {"origin_x_m", ColumnType::kFloat64, ColumnCodes::kNone, "m, world", "the sensor's origin at the sample, x",
     [](const ReadingRow& r) { return r.sample.p_WS.x(); }},
    {"origin_y_m", ColumnType::kFloat64, ColumnCodes::kNone, "m, world", "its y",
     [](const ReadingRow& r) { return r.sample.p_WS.y(); }},
    {"origin_z_m", ColumnType::kFloat64, ColumnCodes::kNone, "m, world", "its z",
     [](const ReadingRow& r) { return r.sample.p_WS.z(); }},
    {"dir_x", ColumnType::kFloat64, ColumnCodes::kNone, "unit vector, world",
     "the sensor's axis, x (for a beam too: what the device knows; a multi-zone sensor: its nearest target's zone axis)",
     [](const ReadingRow& r) { return r.sample.dir_W.x(); }},
    {"dir_y", ColumnType::kFloat64, ColumnCodes::kNone, "unit vector, world", "its y",
     [](const ReadingRow& r) { return r.sample.dir_W.y(); }},
    {"dir_z", ColumnType::kFloat64, ColumnCodes::kNone, "unit vector, world", "its z",
     [](const ReadingRow& r) { return r.sample.dir_W.z(); }},
    {"object", ColumnType::kCode32, ColumnCodes::kObjects, "",
     "the hit object's name (a scene object or a robot link); none without a hit",
     [](const ReadingRow& r) { return IsHit(r) ? static_cast<double>(r.sample.object_id) : -1.0; }},
    {"gait_phase", ColumnType::kFloat64, ColumnCodes::kNone, "[0, 1)",
     "the left leg's phase, 0 at its heel strike; none without a robot",
     [](const ReadingRow& r) { return r.frame.robot.present ? r.frame.robot.gait_phase : kNone; }},
    {"support_leg", ColumnType::kCode8, ColumnCodes::kSupportLegs, "",
     "`left`, `right` or `double`; none without a robot",
     [](const ReadingRow& r) {
       return r.frame.robot.present ? static_cast<double>(r.frame.robot.support) : -1.0;
     }},
    {"ray", ColumnType::kInt32, ColumnCodes::kNone, "", "the beam's ray that gave the reading, 0 the axis, −1 none",
     [](const ReadingRow& r) { return static_cast<double>(r.sample.ray); }},
    {"output", ColumnType::kFloat64, ColumnCodes::kNone, "",
     "a lookup sensor's output (volts for the Sharp part); none for the other types",
     [](const ReadingRow& r) { return r.sample.reading.output; }},
    {"t_reported_s", ColumnType::kFloat64, ColumnCodes::kNone, "s",
     "when the reading is reported: `t_s` + the sensor's `latency_s`",
     [](const ReadingRow& r) { return r.sample.t_reported_s; }},
}};

// REP 117 (sensor_msgs/Range): what the device says, without a status beside it
double Rep117Range_m(const ReadingRow& r) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  switch (r.sample.reading.status) {
    case ReadingStatus::kOk:
    case ReadingStatus::kCrosstalk: return r.sample.reading.d_m;  // the device reports it, whoever's echo it was
    case ReadingStatus::kTooClose: return -kInf;                 // "an object too close to measure"
    case ReadingStatus::kNoEcho:
    case ReadingStatus::kGrazing: return kInf;                   // no echo came back: nothing in range for the device
    case ReadingStatus::kSelf:
    case ReadingStatus::kDropout:
    case ReadingStatus::kNotSampled: return kNone;               // not a valid reading of the world
  }
  return kNone;
}

// the reading's variance from the sensor's noise model (sensors/range_inverse.h); none without a detection
double Rep117Variance_m2(const ReadingRow& r) {
  if (!r.sample.reading.detected()) return kNone;
  const double sigma_m = RangeSigma_m(r.config.spec, UnbiasedDistance_m(r.config.spec, r.sample.reading.d_m));
  return sigma_m * sigma_m;
}

// the columns with outputs.range_convention: rep117: d_m as REP 117 states it, variance_m2 after it
std::vector<ReadingsColumn> Rep117Columns() {
  std::vector<ReadingsColumn> columns(kColumns.begin(), kColumns.end());
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (std::string(columns[i].name) != "d_m") continue;
    columns[i].meaning =
        "REP 117: the measured distance for `ok`; −inf for `too_close`; +inf for `no_echo` and `grazing` (no echo "
        "came back); NaN (empty) for `self` and `dropout`";
    columns[i].value = Rep117Range_m;
    columns.insert(columns.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                   ReadingsColumn{"variance_m2", ColumnType::kFloat64, ColumnCodes::kNone, "m²",
                                  "REP 117's variance of d_m from the sensor's noise model (σ² of the reported "
                                  "distance, with resolution²/12); none without a detection",
                                  Rep117Variance_m2});
    break;
  }
  return columns;
}

const char* TypeName(ColumnType type) {
  switch (type) {
    case ColumnType::kFloat64: return "float64, NaN for none";
    case ColumnType::kInt32: return "int32";
    case ColumnType::kCode32: return "int32 code, −1 for none";
    case ColumnType::kCode8: return "uint8 code, 255 for none";
    case ColumnType::kBool: return "bool";
  }
  return "?";
}

}  // namespace

std::span<const ReadingsColumn> ReadingsColumns(RangeConvention convention) {
  if (convention == RangeConvention::kProxsim) return kColumns;
  static const std::vector<ReadingsColumn> rep117 = Rep117Columns();
  return rep117;
}

const char* NpyDtype(ColumnType type) {
  switch (type) {
    case ColumnType::kFloat64: return "<f8";
    case ColumnType::kInt32:
    case ColumnType::kCode32: return "<i4";
    case ColumnType::kCode8: return "|u1";
    case ColumnType::kBool: return "|b1";
  }
  return "?";
}

const char* ColumnCodesKey(ColumnCodes codes) {
  switch (codes) {
    case ColumnCodes::kNone: break;
    case ColumnCodes::kSensors: return "sensors";
    case ColumnCodes::kTypes: return "types";
    case ColumnCodes::kStatuses: return "statuses";
    case ColumnCodes::kObjects: return "objects";
    case ColumnCodes::kSupportLegs: return "support_legs";
  }
  return "";
}

ColumnNames::ColumnNames(const Scenario& scenario, std::vector<std::string> object_names)
    : convention_(scenario.range_convention),
      types_(SensorTypeNames()),
      statuses_(ReadingStatusNames()),
      objects_(std::move(object_names)),
      support_legs_(SupportLegNames()) {
  for (const SensorConfig& sensor : scenario.sensors) sensors_.push_back(sensor.name);
}

const std::vector<std::string>& ColumnNames::operator[](ColumnCodes codes) const {
  switch (codes) {
    case ColumnCodes::kSensors: return sensors_;
    case ColumnCodes::kTypes: return types_;
    case ColumnCodes::kStatuses: return statuses_;
    case ColumnCodes::kObjects: return objects_;
    case ColumnCodes::kSupportLegs: return support_legs_;
    case ColumnCodes::kNone: break;
  }
  static const std::vector<std::string> none;
  return none;
}

std::string ReadingsCsvHeader(RangeConvention convention) {
  std::string header;
  for (const ReadingsColumn& column : ReadingsColumns(convention)) {
    if (!header.empty()) header += ',';
    header += column.name;
  }
  return header;
}

nlohmann::json ColumnsJson(const ColumnNames& names) {
  nlohmann::json columns = nlohmann::json::array();
  for (const ReadingsColumn& column : ReadingsColumns(names.convention())) {
    nlohmann::json entry = {{"name", column.name},
                            {"dtype", NpyDtype(column.type)},
                            {"unit", column.unit},
                            {"meaning", column.meaning}};
    if (column.codes != ColumnCodes::kNone) entry["codes"] = ColumnCodesKey(column.codes);
    columns.push_back(std::move(entry));
  }
  nlohmann::json document = {{"columns", std::move(columns)}};
  // only with REP 117, so that the paper's columns.json stays as it was
  if (names.convention() == RangeConvention::kRep117) document["range_convention"] = "rep117";
  for (ColumnCodes codes : {ColumnCodes::kSensors, ColumnCodes::kTypes, ColumnCodes::kStatuses,
                            ColumnCodes::kObjects, ColumnCodes::kSupportLegs}) {
    document[ColumnCodesKey(codes)] = names[codes];
  }
  return document;
}

std::string ReadingsColumnsMarkdown() {
  std::string table = "| column | type | unit | meaning |\n|---|---|---|---|\n";
  for (const ReadingsColumn& column : kColumns) {
    table += std::string("| `") + column.name + "` | " + TypeName(column.type) + " | " + column.unit + " | " +
             column.meaning + " |\n";
  }
  return table;
}

}  // namespace proxsim
