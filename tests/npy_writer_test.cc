// `proxsim run --format npy`: the columns hold exactly the rows of the CSV.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/scenario.h"
#include "sim/run.h"

namespace {

namespace fs = std::filesystem;

/// The header dict and the raw data of a .npy file (format 1.0).
struct Npy {
  std::string header;
  std::string data;
};

Npy ReadNpy(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string bytes = buffer.str();
  EXPECT_GE(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 6), "\x93NUMPY");
  const std::size_t length = static_cast<unsigned char>(bytes[8]) | (static_cast<unsigned char>(bytes[9]) << 8);
  EXPECT_EQ((10 + length) % 64, 0u) << "data must start 64-byte aligned";
  return {bytes.substr(10, length), bytes.substr(10 + length)};
}

/// One column of readings.csv as text.
std::vector<std::string> CsvColumn(const fs::path& path, int column) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::string> values;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string field;
    for (int k = 0; k <= column; ++k) std::getline(fields, field, ',');
    values.push_back(field);
  }
  return values;
}

TEST(NpyWriter, ColumnsHoldTheRowsOfTheCsv) {
  const fs::path root = fs::temp_directory_path() / "proxsim_npy_writer_test";
  fs::remove_all(root);
  proxsim::Scenario scenario = proxsim::LoadBuiltinScenario("paper");
  scenario.duration_s = 0.5;
  proxsim::RunOptions csv;
  csv.out_dir = (root / "csv").string();
  proxsim::RunOptions npy = csv;
  npy.out_dir = (root / "npy").string();
  npy.format = proxsim::ReadingsFormat::kNpy;
  proxsim::RunScenario(scenario, csv);
  proxsim::RunScenario(scenario, npy);

  const fs::path readings = root / "npy" / "readings";
  ASSERT_TRUE(fs::is_directory(readings));
  EXPECT_FALSE(fs::exists(root / "npy" / "readings.tmp"));
  EXPECT_FALSE(fs::exists(root / "npy" / "readings.csv"));
  const auto d_csv = CsvColumn(root / "csv" / "readings.csv", 5);
  const auto status_csv = CsvColumn(root / "csv" / "readings.csv", 3);
  const std::size_t rows = d_csv.size();
  ASSERT_GT(rows, 0u);

  // every column has the CSV's row count in its header and its data
  const auto codes = nlohmann::json::parse(std::ifstream(readings / "columns.json"));
  EXPECT_EQ(codes["rows"].get<std::size_t>(), rows);
  for (const auto& column : codes["columns"]) {
    const Npy file = ReadNpy(readings / (column["name"].get<std::string>() + ".npy"));
    EXPECT_NE(file.header.find("'shape': (" + std::to_string(rows) + ",)"), std::string::npos) << file.header;
    const std::string dtype = column["dtype"];
    EXPECT_NE(file.header.find("'descr': '" + dtype + "'"), std::string::npos);
    const std::size_t item = dtype.back() - '0';
    EXPECT_EQ(file.data.size(), rows * item) << column["name"];
  }

  // the values: d_m bit for bit (the CSV's numbers read back to the same double), status by code
  const Npy d = ReadNpy(readings / "d_m.npy");
  const Npy status = ReadNpy(readings / "status.npy");
  for (std::size_t i = 0; i < rows; ++i) {
    double value;
    std::memcpy(&value, d.data.data() + 8 * i, 8);
    EXPECT_EQ(value, std::stod(d_csv[i])) << "row " << i;
    EXPECT_EQ(codes["statuses"][static_cast<unsigned char>(status.data[i])].get<std::string>(), status_csv[i]);
  }
  fs::remove_all(root);
}

}  // namespace
