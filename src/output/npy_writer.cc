#include "output/npy_writer.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace proxsim {

namespace {

// the .npy header (format 1.0) is padded to this many bytes, so that the
// final row count can be written over it without moving the data
constexpr std::size_t kHeaderBytes = 128;
constexpr std::size_t kFlushBytes = 1 << 18;

std::string NpyHeader(const char* descr, std::int64_t rows) {
  std::string dict = std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': (" +
                     std::to_string(rows) + ",), }";
  std::string header = "\x93NUMPY";
  header += '\x01';
  header += '\x00';
  const std::size_t length = kHeaderBytes - 10;  // magic 6 + version 2 + length 2
  header += static_cast<char>(length & 0xFF);
  header += static_cast<char>(length >> 8);
  dict.resize(length - 1, ' ');
  header += dict;
  header += '\n';
  return header;
}

}  // namespace

struct NpyReadingsWriter::Column {
  Column(const std::string& path, const char* descr_in) : file(path), descr(descr_in) {
    file.Write(NpyHeader(descr, 0));
    pending.reserve(kFlushBytes + 64);
  }
  template <typename T>
  void Put(T value) {
    const std::size_t at = pending.size();
    pending.resize(at + sizeof(T));
    std::memcpy(pending.data() + at, &value, sizeof(T));
  }
  void Flush() {
    file.Write(std::string_view(pending.data(), pending.size()));
    pending.clear();
  }
  AtomicFile file;
  const char* descr;
  std::vector<char> pending;
};

namespace {
// column order: readings.csv's
enum Col {
  kT, kSensor, kType, kStatus, kDetected, kD, kDTrue, kIncidence, kSignal, kHitX, kHitY, kHitZ,
  kOriginX, kOriginY, kOriginZ, kDirX, kDirY, kDirZ, kObject, kGaitPhase, kSupportLeg, kRay, kOutput,
  kTReported, kColumnCount
};
struct ColumnSpec {
  const char* name;
  const char* descr;
};
constexpr ColumnSpec kColumns[kColumnCount] = {
    {"t_s", "<f8"},        {"sensor", "<i4"},     {"type", "|u1"},          {"status", "|u1"},
    {"detected", "|b1"},   {"d_m", "<f8"},        {"d_true_m", "<f8"},      {"incidence_deg", "<f8"},
    {"signal", "<f8"},     {"hit_x_m", "<f8"},    {"hit_y_m", "<f8"},       {"hit_z_m", "<f8"},
    {"origin_x_m", "<f8"}, {"origin_y_m", "<f8"}, {"origin_z_m", "<f8"},    {"dir_x", "<f8"},
    {"dir_y", "<f8"},      {"dir_z", "<f8"},      {"object", "<i4"},        {"gait_phase", "<f8"},
    {"support_leg", "|u1"}, {"ray", "<i4"},       {"output", "<f8"},        {"t_reported_s", "<f8"}};
}  // namespace

NpyReadingsWriter::NpyReadingsWriter(const std::string& dir, const Scenario& scenario,
                                     std::vector<std::string> object_names)
    : dir_(dir), tmp_dir_(dir + ".tmp"), scenario_(scenario), object_names_(std::move(object_names)) {
  std::filesystem::remove_all(tmp_dir_);
  std::filesystem::create_directories(tmp_dir_);
  for (const ColumnSpec& spec : kColumns) {
    columns_.push_back(std::make_unique<Column>(tmp_dir_ + "/" + spec.name + ".npy", spec.descr));
  }
}

NpyReadingsWriter::~NpyReadingsWriter() {
  if (committed_) return;
  columns_.clear();  // each AtomicFile removes its temporary file
  std::error_code ignored;
  std::filesystem::remove_all(tmp_dir_, ignored);
}

void NpyReadingsWriter::Append(const SampleFrame& frame) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Column* c[kColumnCount];
  for (int k = 0; k < kColumnCount; ++k) c[k] = columns_[k].get();
  for (std::size_t i = 0; i < frame.sensors.size(); ++i) {
    const SensorSample& s = frame.sensors[i];
    if (s.reading.status == ReadingStatus::kNotSampled) continue;  // no row between a sensor's own samples
    const bool hit = s.object_id >= 0;
    c[kT]->Put(frame.t_s);
    c[kSensor]->Put(static_cast<std::int32_t>(i));
    c[kType]->Put(static_cast<std::uint8_t>(scenario_.sensors[i].spec.type));
    c[kStatus]->Put(static_cast<std::uint8_t>(s.reading.status));
    c[kDetected]->Put(static_cast<std::uint8_t>(s.reading.detected()));
    c[kD]->Put(s.reading.d_m);
    c[kDTrue]->Put(hit ? s.echo.distance_m : kNaN);
    c[kIncidence]->Put(hit ? s.echo.incidence_deg : kNaN);
    c[kSignal]->Put(s.reading.signal);
    for (int k = 0; k < 3; ++k) c[kHitX + k]->Put(s.p_WH[k]);
    for (int k = 0; k < 3; ++k) c[kOriginX + k]->Put(s.p_WS[k]);
    for (int k = 0; k < 3; ++k) c[kDirX + k]->Put(s.dir_W[k]);
    c[kObject]->Put(static_cast<std::int32_t>(hit ? s.object_id : -1));
    c[kGaitPhase]->Put(frame.robot.present ? frame.robot.gait_phase : kNaN);
    c[kSupportLeg]->Put(static_cast<std::uint8_t>(frame.robot.present ? static_cast<int>(frame.robot.support) : 255));
    // beyond the paper: the beam's ray, a lookup sensor's output, the report time
    c[kRay]->Put(static_cast<std::int32_t>(s.ray));
    c[kOutput]->Put(s.reading.output);
    c[kTReported]->Put(s.t_reported_s);
    ++rows_;
  }
  if (c[kT]->pending.size() >= kFlushBytes) {
    for (auto& column : columns_) column->Flush();
  }
}

void NpyReadingsWriter::Commit() {
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    Column& column = *columns_[k];
    column.Flush();
    // the real row count over the placeholder header
    if (std::fseek(column.file.stream(), 0, SEEK_SET) != 0) {
      throw std::runtime_error("cannot rewind " + column.file.path());
    }
    column.file.Write(NpyHeader(column.descr, rows_));
    column.file.Commit();
  }

  // the codes of the integer columns
  nlohmann::json sensors = nlohmann::json::array(), types = nlohmann::json::array(),
                 statuses = nlohmann::json::array();
  for (const SensorConfig& sensor : scenario_.sensors) sensors.push_back(sensor.name);
  for (int t = 0; t < 256 && std::string(SensorTypeName(SensorType(t))) != "?"; ++t) {
    types.push_back(SensorTypeName(SensorType(t)));
  }
  // every status the enum names (it may grow), in code order
  for (int s = 0; s < 256 && std::string(ReadingStatusName(ReadingStatus(s))) != "?"; ++s) {
    statuses.push_back(ReadingStatusName(ReadingStatus(s)));
  }
  const nlohmann::json codes = {
      {"rows", rows_},
      {"columns", [] {
         nlohmann::json columns = nlohmann::json::array();
         for (const ColumnSpec& spec : kColumns) columns.push_back({{"name", spec.name}, {"dtype", spec.descr}});
         return columns;
       }()},
      {"sensors", sensors},
      {"types", types},
      {"statuses", statuses},
      {"objects", object_names_},
      {"support_legs", {SupportLegName(SupportLeg::kLeft), SupportLegName(SupportLeg::kRight),
                        SupportLegName(SupportLeg::kDouble)}}};
  WriteFileAtomically(tmp_dir_ + "/columns.json", codes.dump(1) + "\n");

  std::filesystem::remove_all(dir_);
  std::filesystem::rename(tmp_dir_, dir_);
  committed_ = true;
}

}  // namespace proxsim
