// outputs.range_convention: rep117 — readings.csv's d_m as ROS REP 117
// (sensor_msgs/Range) states a reading: the distance for a detection, −inf
// too close, +inf nothing in range, NaN invalid; and a variance_m2 column from
// the noise model. Without the key the paper's columns stay as they were.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_helpers.h"
#include "output/readings_columns.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadFile;
using testing::RunProxsim;

// one sensor per status: a laser facing a wall 1 m away (ok), one facing
// away (no_echo), an ultrasonic 1 cm under a box (too_close, its dead zone is
// 0.1 m), a laser meeting the wall at 50° (grazing, beyond its 45°)
constexpr const char* kScenario = R"(proxsim: 1
duration_s: 0.1
rate_hz: 10
outputs: {range_convention: rep117}
scene:
  objects:
    - {name: wall, plane: {}, pose: {xyz_m: [1, 0, 0], rpy_deg: [0, -90, 0]}}
    - {name: near, box: {size_m: [0.1, 0.1, 0.1]}, pose: {xyz_m: [0.06, 0, 2]}}
sensors:
  - {name: ok, type: laser, pose: {xyz_m: [0, 0, 1]}}
  - {name: far, type: laser, pose: {xyz_m: [0, 0, 1], rpy_deg: [0, 0, 180]}}
  - {name: close, type: ultrasonic, pose: {xyz_m: [0, 0, 2]}}
  - {name: grazing, type: laser, pose: {xyz_m: [0, 0, 1], rpy_deg: [0, 0, 50]}}
)";

TEST(Rep117Test, EveryStatusIsStatedAsRep117AndTheVarianceIsTheNoiseModels) {
  const fs::path dir = FreshDir("rep117");
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << kScenario;
  const auto run = RunProxsim("run " + (dir / "s.yaml").string() + " --no-report --out " + (dir / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto csv = testing::ReadCsv(dir / "out" / "readings.csv");
  EXPECT_EQ(csv.header, [] {
    std::vector<std::string> names;
    for (const ReadingsColumn& column : ReadingsColumns(RangeConvention::kRep117)) names.push_back(column.name);
    return names;
  }());
  ASSERT_EQ(csv.rows.size(), 4u);
  const auto& ok = csv.rows[0];
  EXPECT_EQ(ok.at("status"), "ok");
  const double d = std::stod(ok.at("d_m"));
  EXPECT_NEAR(d, 1.0, 0.05);
  // the laser's multiplicative σ = 0.01: σ_d = 0.01·d
  EXPECT_NEAR(std::stod(ok.at("variance_m2")), (0.01 * d) * (0.01 * d), 1e-15);
  EXPECT_EQ(csv.rows[1].at("status"), "no_echo");
  EXPECT_EQ(csv.rows[1].at("d_m"), "inf");
  EXPECT_EQ(csv.rows[2].at("status"), "too_close");
  EXPECT_EQ(csv.rows[2].at("d_m"), "-inf");
  EXPECT_EQ(csv.rows[3].at("status"), "grazing");
  EXPECT_EQ(csv.rows[3].at("d_m"), "inf");
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(csv.rows[i].at("variance_m2"), "") << i;

  const auto columns = nlohmann::json::parse(ReadFile(dir / "out" / "columns.json"));
  EXPECT_EQ(columns["range_convention"], "rep117");
  const auto summary = nlohmann::json::parse(ReadFile(dir / "out" / "summary.json"));
  EXPECT_EQ(summary["inputs"]["outputs"]["range_convention"], "rep117");
}

TEST(Rep117Test, TheDefaultKeepsThePapersColumnsAndAnUnknownConventionIsRefused) {
  EXPECT_EQ(ReadingsCsvHeader(), ReadingsCsvHeader(RangeConvention::kProxsim));
  EXPECT_EQ(ReadingsCsvHeader().find("variance_m2"), std::string::npos);
  const fs::path dir = FreshDir("rep117_bad");
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << "proxsim: 1\noutputs: {range_convention: rep118}\nsensors: [{name: a, type: laser}]\n";
  const auto result = RunProxsim("validate " + (dir / "s.yaml").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("outputs.range_convention: expected proxsim or rep117, got 'rep118'"), std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace proxsim
