#include "output/npy_writer.h"

#include <cstring>
#include <filesystem>
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

NpyReadingsWriter::NpyReadingsWriter(const std::string& out_dir, const Scenario& scenario,
                                     std::vector<std::string> object_names)
    : dir_((std::filesystem::path(out_dir) / "readings").string()),
      scenario_(scenario),
      names_(scenario, std::move(object_names)) {
  // each column is its own atomic file in readings/ (a folder that is a link
  // is refused by AtomicFile); nothing else in the folder is touched: a
  // user's files there stay, the previous run's went by its manifest
  std::filesystem::create_directories(dir_);
  for (const ReadingsColumn& column : ReadingsColumns(scenario.range_convention)) {
    columns_.push_back(std::make_unique<Column>(dir_ + "/" + column.name + ".npy", NpyDtype(column.type)));
  }
}

NpyReadingsWriter::~NpyReadingsWriter() = default;  // each uncommitted AtomicFile removes its temporary file

void NpyReadingsWriter::Add(const SampleFrame& frame) {
  const std::span<const ReadingsColumn> spec = ReadingsColumns(scenario_.range_convention);
  for (std::size_t i = 0; i < frame.sensors.size(); ++i) {
    const SensorSample& s = frame.sensors[i];
    if (s.reading.status == ReadingStatus::kNotSampled) continue;  // no row between a sensor's own samples
    const ReadingRow row{frame, i, scenario_.sensors[i], s};
    for (std::size_t k = 0; k < spec.size(); ++k) {
      const double value = spec[k].value(row);
      Column& column = *columns_[k];
      switch (spec[k].type) {
        case ColumnType::kFloat64: column.Put(value); break;
        case ColumnType::kInt32:
        case ColumnType::kCode32: column.Put(static_cast<std::int32_t>(value)); break;
        case ColumnType::kCode8: column.Put(static_cast<std::uint8_t>(value >= 0 ? value : 255)); break;
        case ColumnType::kBool: column.Put(static_cast<std::uint8_t>(value != 0)); break;
      }
    }
    ++rows_;
  }
  if (columns_.front()->pending.size() >= kFlushBytes) {
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

  nlohmann::json codes = ColumnsJson(names_);
  codes["rows"] = rows_;
  WriteFileAtomically(dir_ + "/columns.json", codes.dump(1) + "\n");
}

void NpyReadingsWriter::AddToSummary(nlohmann::json& summary) const { summary["outputs"].push_back("readings/"); }

}  // namespace proxsim
