// `proxsim run --format npy`: the columns hold exactly the rows of the CSV.
// A run written both ways through the real CLI, on sensors that exercise
// every column (a beam, lookup sensors, a slow sensor with latency, a walking
// robot), must give the same value in every column, row by row; and the
// report must draw the npy run from the same data it reads from the CSV.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"
#include "core/number_format.h"
#include "scenario/scenario.h"
#include "run/run.h"

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
  const fs::path root = proxsim::testing::FreshDir("npy_writer");
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

// --- the CLI's run, written as CSV and as npy ----------------------------------------

// Every column the CSV has, with the npy dtype it must have (npy_writer.h).
const std::map<std::string, std::string> kDtypes = {
    {"t_s", "<f8"},           {"sensor", "<i4"},        {"type", "|u1"},         {"status", "|u1"},
    {"detected", "|b1"},      {"d_m", "<f8"},           {"d_true_m", "<f8"},     {"incidence_deg", "<f8"},
    {"signal", "<f8"},        {"hit_x_m", "<f8"},       {"hit_y_m", "<f8"},      {"hit_z_m", "<f8"},
    {"origin_x_m", "<f8"},    {"origin_y_m", "<f8"},    {"origin_z_m", "<f8"},   {"dir_x", "<f8"},
    {"dir_y", "<f8"},         {"dir_z", "<f8"},         {"object", "<i4"},       {"gait_phase", "<f8"},
    {"support_leg", "|u1"},   {"ray", "<i4"},           {"output", "<f8"},       {"t_reported_s", "<f8"}};

// The biped walking toward the dining room's obstacle, with sensors on its
// left tibia: a 37-ray ultrasonic cone (`ray` off the axis or -1), the Sharp part and a
// table lookup sensor (`output`), a 30 Hz laser with 25 ms latency
// (`t_reported_s`, and fewer rows than the 100 Hz sensors) and a reflectance
// sensor (`signal`).
constexpr const char* kExercisingScenario = R"(proxsim: 1
seed: 5
duration_s: 1.5
rate_hz: 100
scene:
  builtin: dining_room
robot:
  model: builtin:biped
  start: {xyz_m: [0, 0, 0], yaw_deg: 0}
  gait: {stride_m: 0.6, period_s: 1.2}
  path: {waypoints_m: [[0, 0], [4.5, 0]]}
sensors:
  - name: cone
    type: ultrasonic
    link: left_tibia
    pose: &mount {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 15, 0]}
    see_robot: false
    beam: {aperture_deg: 60, rays: 37, pattern: {gaussian: {width_deg: 15}}}
  - name: sharp
    type: sharp_gp2y0a21
    link: left_tibia
    pose: *mount
  - name: table
    type: lookup
    link: left_tibia
    pose: *mount
    lookup_table: [[0.05, 5, 0.01], [1.5, 1, 0.02]]
  - name: slow_late
    type: laser
    link: left_tibia
    pose: *mount
    rate_hz: 30
    latency_s: 0.025
  - name: reflectance
    type: reflectance
    link: left_tibia
    pose: *mount
)";

/// A .npy column: its dtype, its row count and its raw little-endian data.
struct NpyColumn {
  std::string descr;
  std::size_t rows = 0;
  std::string data;

  template <typename T>
  T At(std::size_t i) const {
    T value;
    std::memcpy(&value, data.data() + sizeof(T) * i, sizeof(T));
    return value;
  }
};

NpyColumn ReadNpyColumn(const fs::path& path) {
  const Npy file = ReadNpy(path);
  NpyColumn column;
  const std::string descr_key = "'descr': '";
  const std::size_t descr_at = file.header.find(descr_key);
  const std::string shape_key = "'shape': (";
  const std::size_t shape_at = file.header.find(shape_key);
  EXPECT_NE(descr_at, std::string::npos) << path;
  EXPECT_NE(shape_at, std::string::npos) << path;
  if (descr_at == std::string::npos || shape_at == std::string::npos) return column;
  column.descr = file.header.substr(descr_at + descr_key.size(), 3);
  column.rows = std::stoull(file.header.substr(shape_at + shape_key.size()));
  column.data = file.data;
  return column;
}

/// The npy value of one row as the CSV writes it ("" for NaN, −1 or 255 as "none",
/// codes as their names), so that a mismatch prints both sides.
std::string AsCsvText(const std::string& name, const NpyColumn& column, std::size_t i,
                      const nlohmann::json& codes) {
  static const std::map<std::string, std::string> code_lists = {
      {"sensor", "sensors"}, {"type", "types"}, {"status", "statuses"},
      {"object", "objects"}, {"support_leg", "support_legs"}};
  if (column.descr == "<f8") {
    std::string text;
    proxsim::AppendNumber(text, column.At<double>(i));
    return text;
  }
  if (column.descr == "|b1") return column.At<std::uint8_t>(i) ? "1" : "0";
  const long long code = column.descr == "<i4" ? column.At<std::int32_t>(i) : column.At<std::uint8_t>(i);
  if (name == "ray") return std::to_string(code);
  if (code == -1 || (name == "support_leg" && code == 255)) return "";
  const auto& list = codes[code_lists.at(name)];
  if (code < 0 || static_cast<std::size_t>(code) >= list.size()) return "code " + std::to_string(code) + "?";
  return list[code].get<std::string>();
}

/// A fresh folder holding the exercising scenario and its CSV run (report off)
/// in root/csv; the caller runs the npy run it wants beside it.
fs::path ScenarioWithItsCsvRun(const std::string& name) {
  const fs::path root = proxsim::testing::FreshDir(name);
  fs::create_directories(root);
  std::ofstream(root / "exercise.yaml") << kExercisingScenario;
  const auto csv_run = proxsim::testing::RunProxsim("run " + (root / "exercise.yaml").string() +
                                                    " --no-report --out " + (root / "csv").string());
  EXPECT_EQ(csv_run.exit_code, 0) << csv_run.output;
  return root;
}

TEST(NpyWriter, CliRunGivesTheCsvValuesInEveryColumn) {
  using proxsim::testing::ReadCsv;
  using proxsim::testing::RunProxsim;
  const fs::path root = ScenarioWithItsCsvRun("npy_cli");
  const fs::path scenario = root / "exercise.yaml";
  const auto npy_run =
      RunProxsim("run " + scenario.string() + " --no-report --format npy --out " + (root / "npy").string());
  ASSERT_EQ(npy_run.exit_code, 0) << npy_run.output;

  const proxsim::testing::Csv csv = ReadCsv(root / "csv" / "readings.csv");
  const fs::path readings = root / "npy" / "readings";
  ASSERT_TRUE(fs::is_directory(readings));
  const auto codes = nlohmann::json::parse(std::ifstream(readings / "columns.json"));
  const std::size_t rows = csv.rows.size();
  ASSERT_GT(rows, 0u);
  EXPECT_EQ(codes["rows"].get<std::size_t>(), rows);

  // the same columns in the same order, each with the dtype that fits it
  std::vector<std::string> npy_names;
  for (const auto& column : codes["columns"]) {
    npy_names.push_back(column["name"].get<std::string>());
    const auto dtype = kDtypes.find(npy_names.back());
    ASSERT_NE(dtype, kDtypes.end()) << "npy column not in the CSV: " << npy_names.back();
    EXPECT_EQ(column["dtype"].get<std::string>(), dtype->second) << npy_names.back();
  }
  EXPECT_EQ(npy_names, csv.header);
  ASSERT_EQ(csv.header.size(), kDtypes.size()) << "the CSV has a column this test does not know";

  // every value of every column: floats bit for bit (the CSV's shortest
  // decimal reads back to the same double), NaN where the CSV is empty; codes by name
  for (const std::string& name : csv.header) {
    const NpyColumn column = ReadNpyColumn(readings / (name + ".npy"));
    ASSERT_EQ(column.descr, kDtypes.at(name)) << name;
    ASSERT_EQ(column.rows, rows) << name;
    ASSERT_EQ(column.data.size(), rows * (column.descr.back() - '0')) << name;
    std::size_t mismatches = 0, first = 0;
    for (std::size_t i = 0; i < rows; ++i) {
      const std::string& text = csv.rows[i].at(name);
      bool same;
      if (column.descr == "<f8") {
        const double value = column.At<double>(i);
        same = text.empty() ? std::isnan(value) : value == std::stod(text);
      } else {
        same = AsCsvText(name, column, i, codes) == text;
      }
      if (!same && mismatches++ == 0) first = i;
    }
    EXPECT_EQ(mismatches, 0u) << "column " << name << ", first at row " << first << ": CSV '"
                              << csv.rows[first].at(name) << "', npy '" << AsCsvText(name, column, first, codes)
                              << "'";
  }

  // the run exercised what the new columns carry, in the npy files themselves
  const NpyColumn sensor = ReadNpyColumn(readings / "sensor.npy");
  const NpyColumn ray = ReadNpyColumn(readings / "ray.npy");
  const NpyColumn output = ReadNpyColumn(readings / "output.npy");
  const NpyColumn t_s = ReadNpyColumn(readings / "t_s.npy");
  const NpyColumn t_reported = ReadNpyColumn(readings / "t_reported_s.npy");
  const NpyColumn signal = ReadNpyColumn(readings / "signal.npy");
  const NpyColumn gait_phase = ReadNpyColumn(readings / "gait_phase.npy");
  ASSERT_EQ(codes["sensors"], nlohmann::json({"cone", "sharp", "table", "slow_late", "reflectance"}));
  std::map<std::string, int> rows_of;
  int off_axis_rays = 0, no_ray = 0, bad_outputs = 0, bad_reports = 0, signals = 0, phases = 0;
  for (std::size_t i = 0; i < rows; ++i) {
    const std::string name = codes["sensors"][sensor.At<std::int32_t>(i)].get<std::string>();
    ++rows_of[name];
    off_axis_rays += ray.At<std::int32_t>(i) > 0;
    no_ray += ray.At<std::int32_t>(i) == -1;
    // an output for the lookup sensors only; reported latency_s after the sample
    const bool lookup = name == "sharp" || name == "table";
    bad_outputs += std::isfinite(output.At<double>(i)) != lookup;
    const double latency_s = name == "slow_late" ? 0.025 : 0.0;
    bad_reports += !(std::abs(t_reported.At<double>(i) - (t_s.At<double>(i) + latency_s)) <= 1e-12);
    signals += std::isfinite(signal.At<double>(i));
    phases += std::isfinite(gait_phase.At<double>(i));
  }
  EXPECT_GT(off_axis_rays, 0) << "the cone's echo never came from an off-axis ray";
  EXPECT_GT(no_ray, 0);
  EXPECT_EQ(bad_outputs, 0) << "rows whose output is NaN for a lookup sensor or finite for another";
  EXPECT_EQ(bad_reports, 0) << "rows whose t_reported_s is not t_s + latency_s";
  EXPECT_GT(signals, 0);
  EXPECT_EQ(phases, static_cast<int>(rows));
  EXPECT_EQ(rows_of["cone"], 150);
  EXPECT_EQ(rows_of["slow_late"], 45) << "a 30 Hz sensor in a 100 Hz run: one row per own sample";
  fs::remove_all(root);
}

// --- the report of an npy run ---------------------------------------------------------

TEST(NpyWriter, ReportOfAnNpyRunIsDrawnFromTheCsvsData) {
  using proxsim::testing::RunCommand;
  using proxsim::testing::RunProxsim;
  const fs::path root = ScenarioWithItsCsvRun("npy_report");
  const fs::path scenario = root / "exercise.yaml";
  const fs::path csv = root / "csv", npy = root / "npy";
  ASSERT_TRUE(fs::exists(csv / "readings.csv"));

  // the whole run, report included, exits 0 with the figures and the viewer
  const auto npy_run = RunProxsim("run " + scenario.string() + " --format npy --out " + npy.string());
  ASSERT_EQ(npy_run.exit_code, 0) << npy_run.output;
  EXPECT_FALSE(fs::exists(npy / "readings.csv"));
  const std::vector<std::string> report_files = {"paper_figures.png", "curve_cone.png", "profile_cone.png",
                                                 "curve_slow_late.png", "index.html", "data.js", "viewer.js"};
  for (const std::string& name : report_files) {
    EXPECT_TRUE(fs::is_regular_file(npy / "report" / name)) << name << "\n" << npy_run.output;
  }

  // the report reads the same arrays from both runs (every field of every sensor)
  const fs::path compare = fs::path(PROXSIM_TEST_DATA_DIR).parent_path() / "report" / "same_run_data.py";
  const auto same = RunCommand("/usr/bin/python3 " + compare.string() + " " + csv.string() + " " + npy.string());
  EXPECT_EQ(same.exit_code, 0) << same.output;

  // `proxsim plot` redraws it
  fs::remove_all(npy / "report");
  const auto plot = RunProxsim("plot " + npy.string());
  ASSERT_EQ(plot.exit_code, 0) << plot.output;
  EXPECT_TRUE(fs::is_regular_file(npy / "report" / "paper_figures.png")) << plot.output;
  fs::remove_all(root);
}

}  // namespace
