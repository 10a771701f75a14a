// Whole runs through the real CLI: a small scenario of world-mounted sensors
// is run, its readings.csv read back and checked against closed forms; bad
// input gets exit code 2 and no output; reruns are byte-identical whatever
// the thread count.
#include <cmath>

#include <fstream>

#include <gtest/gtest.h>

#include "cli_helpers.h"

namespace proxsim {
namespace {

using testing::FreshDir;
using testing::ReadCsv;
using testing::ReadFile;
using testing::RowsOf;
using testing::RunProxsim;

const std::string kClosedForm = std::string(PROXSIM_TEST_DATA_DIR) + "/cli/world_closed_form.yaml";


TEST(CliRun, ReadingsMatchClosedForms) {
  const auto out = FreshDir("closed_form");
  const auto result = RunProxsim("run " + kClosedForm + " --no-report --out " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;

  const testing::Csv csv = ReadCsv(out / "readings.csv");
  const std::vector<std::string> expected_header = {
      "t_s", "sensor", "type", "status", "detected", "d_m", "d_true_m", "incidence_deg", "signal", "hit_x_m",
      "hit_y_m", "hit_z_m", "origin_x_m", "origin_y_m", "origin_z_m", "dir_x", "dir_y", "dir_z", "object",
      "gait_phase", "support_leg",
      // appended by the sensor physics beyond the paper (docs/sensors.md)
      "ray", "output", "t_reported_s"};
  ASSERT_EQ(csv.header, expected_header);
  ASSERT_EQ(csv.rows.size(), 10u * 6u);  // 0.2 s at 50 Hz, six sensors

  const double deg = M_PI / 180.0;
  for (const auto& row : RowsOf(csv, "ideal_floor_30deg")) {
    EXPECT_EQ(row.at("status"), "ok");
    EXPECT_EQ(row.at("object"), "floor");
    EXPECT_NEAR(std::stod(row.at("d_m")), 0.5 / std::sin(30 * deg), 1e-5);
    EXPECT_NEAR(std::stod(row.at("incidence_deg")), 60.0, 1e-3);
    EXPECT_NEAR(std::stod(row.at("hit_z_m")), 0.0, 1e-5);
  }
  for (const auto& row : RowsOf(csv, "ideal_wall_yaw20")) {
    EXPECT_EQ(row.at("object"), "wall");
    EXPECT_NEAR(std::stod(row.at("d_m")), 1.5 / std::cos(20 * deg), 1e-5);
    EXPECT_NEAR(std::stod(row.at("incidence_deg")), 20.0, 1e-3);
  }
  for (const auto& row : RowsOf(csv, "laser_wall")) {
    EXPECT_EQ(row.at("status"), "ok");
    EXPECT_NEAR(std::stod(row.at("d_true_m")), 1.5, 1e-5);
    // σ = 0.01: within 5σ of the truth
    EXPECT_NEAR(std::stod(row.at("d_m")), 1.5, 5 * 0.01 * 1.5);
    EXPECT_NE(row.at("d_m"), row.at("d_true_m"));  // noise is applied
  }
  for (const auto& row : RowsOf(csv, "ultrasonic_floor")) {
    EXPECT_EQ(row.at("status"), "grazing");
    EXPECT_EQ(row.at("detected"), "0");
    EXPECT_EQ(std::stod(row.at("d_m")), 1.0);  // d_max
    EXPECT_NEAR(std::stod(row.at("d_true_m")), 0.3 / std::sin(30 * deg), 1e-5);
  }
  for (const auto& row : RowsOf(csv, "reflectance_ball")) {
    EXPECT_EQ(row.at("status"), "ok");
    const double d = std::stod(row.at("d_true_m"));
    EXPECT_NEAR(d, 2.75, 1e-5);
    // Eq. (1) at α = 0 and its inversion, from the signal the run reports
    const double s = std::stod(row.at("signal"));
    EXPECT_NEAR(s / ((3.0 - d) / (d * d)), 1.0, 5 * 0.01);
    EXPECT_NEAR(std::stod(row.at("d_m")), (-1 + std::sqrt(1 + 4 * s * 3.0)) / (2 * s), 1e-9);
  }
  for (const auto& row : RowsOf(csv, "laser_sky")) {
    EXPECT_EQ(row.at("status"), "no_echo");
    EXPECT_EQ(row.at("d_true_m"), "");
    EXPECT_EQ(row.at("object"), "");
    EXPECT_EQ(std::stod(row.at("d_m")), 2.0);
  }

  // the profile holds exactly the detections
  const std::string ply = ReadFile(out / "profile.ply");
  std::size_t detections = 0;
  for (const auto& row : csv.rows) detections += row.at("detected") == "1";
  EXPECT_NE(ply.find("element vertex " + std::to_string(detections) + "\n"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(out / "summary.json"));
  EXPECT_FALSE(std::filesystem::exists(out / "readings.csv.tmp"));
}

TEST(CliRun, SameSeedGivesByteIdenticalFilesWhateverTheThreads) {
  const auto one = FreshDir("threads1"), two = FreshDir("threads2");
  ASSERT_EQ(RunProxsim("run " + kClosedForm + " --no-report --threads 1 --out " + one.string()).exit_code, 0);
  ASSERT_EQ(RunProxsim("run " + kClosedForm + " --no-report --threads 2 --out " + two.string()).exit_code, 0);
  for (const char* file : {"readings.csv", "profile.ply", "summary.json"}) {
    EXPECT_EQ(ReadFile(one / file), ReadFile(two / file)) << file;
  }
  // and another seed changes the noise
  const auto other = FreshDir("seed2");
  ASSERT_EQ(RunProxsim("run " + kClosedForm + " --no-report --seed 12 --out " + other.string()).exit_code, 0);
  EXPECT_NE(ReadFile(one / "readings.csv"), ReadFile(other / "readings.csv"));
}

// stderr is for progress on a terminal, warnings and errors: a good run with
// no terminal writes nothing there (OctoMap's library once added " done.")
TEST(CliRun, AGoodRunWritesNothingOnStderrWithoutATerminal) {
  const auto out = FreshDir("quiet_stderr"), logs = FreshDir("quiet_stderr_log");
  std::filesystem::create_directories(logs);
  const std::string command = std::string(PROXSIM_BINARY) + " run --no-report --out " + out.string() + " >" +
                              (logs / "out.txt").string() + " 2>" + (logs / "err.txt").string();
  ASSERT_EQ(std::system(command.c_str()), 0) << ReadFile(logs / "out.txt");
  EXPECT_EQ(ReadFile(logs / "err.txt"), "");
  ASSERT_TRUE(std::filesystem::exists(out / "terrain" / "map.bt"));  // the map was written, silently
}

TEST(CliRun, BadScenarioExitsTwoAndWritesNothing) {
  const auto dir = FreshDir("bad_input");
  std::filesystem::create_directories(dir);
  const auto scenario = dir / "bad.yaml";
  std::ofstream(scenario) << "proxsim: 1\nrate_hz: -5\nsensors:\n  - name: a\n    type: sonar\n";
  const auto out = dir / "out";
  const auto result = RunProxsim("run " + scenario.string() + " --out " + out.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("rate_hz"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("sonar"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(out));

  const auto validate = RunProxsim("validate " + scenario.string());
  EXPECT_EQ(validate.exit_code, 2);
  EXPECT_NE(validate.output.find("bad.yaml"), std::string::npos) << validate.output;
}

TEST(CliValidate, AcceptsAGoodScenario) {
  const auto result = RunProxsim("validate " + kClosedForm);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("valid"), std::string::npos);
}

TEST(CliRun, BadCommandLineExitsTwo) {
  EXPECT_EQ(RunProxsim("run --threads 0").exit_code, 2);
  EXPECT_EQ(RunProxsim("frobnicate").exit_code, 2);
  EXPECT_EQ(RunProxsim("run /no/such/file.yaml").exit_code, 2);
}

// `bench --from` draws the tables of a saved --json run; anything else is bad input.
TEST(CliBench, FromRefusesAFileThatIsNotABenchRun) {
  const auto dir = FreshDir("bench_from");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "not_bench.json") << R"({"scenes": 1})";
  const auto result = RunProxsim("bench --from " + (dir / "not_bench.json").string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("not_bench.json: not the output of `proxsim bench --json`"), std::string::npos)
      << result.output;
  EXPECT_EQ(RunProxsim("bench --from /no/such/file.json").exit_code, 2);
}

}  // namespace
}  // namespace proxsim
