// One folder holds one run: a second run into a folder removes the first run's
// files (known from the manifest every run writes) and never a user's own;
// `proxsim plot` refuses a folder whose files disagree with its manifest; a
// scenario with no sensors is an input error, not an empty report.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "cli_helpers.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadFile;
using testing::RunProxsim;

const std::string kWorldDemo = std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/world_sensors_demo.yaml";

std::set<std::string> FilesUnder(const fs::path& dir) {
  std::set<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) files.insert(fs::relative(entry.path(), dir).generic_string());
  }
  return files;
}

std::set<std::string> ManifestFiles(const fs::path& dir) {
  std::set<std::string> files;
  const nlohmann::json manifest = nlohmann::json::parse(ReadFile(dir / "manifest.json"));
  for (const auto& f : manifest["files"]) files.insert(f["path"].get<std::string>());
  return files;
}

class RunFolderTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = FreshDir("run_folder"); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(RunFolderTest, ASecondRunLeavesExactlyItsOwnFilesAndTheUsersOwn) {
  const fs::path out = dir_ / "D";
  const auto paper = RunProxsim("run --out " + out.string());  // the paper run, with its report
  ASSERT_EQ(paper.exit_code, 0) << paper.output;
  ASSERT_TRUE(fs::exists(out / "poses.csv"));
  std::set<std::string> first_report;
  for (const std::string& f : ManifestFiles(out))
    if (f.starts_with("report/")) first_report.insert(f);
  ASSERT_FALSE(first_report.empty()) << ReadFile(out / "manifest.json");
  std::ofstream(out / "my_notes.txt") << "a user's own file\n";

  const auto world = RunProxsim("run " + kWorldDemo + " --out " + out.string());
  ASSERT_EQ(world.exit_code, 0) << world.output;
  EXPECT_FALSE(fs::exists(out / "poses.csv")) << "the paper run's poses beside a robotless summary";
  std::set<std::string> expected = ManifestFiles(out);
  expected.insert("manifest.json");
  expected.insert("my_notes.txt");
  EXPECT_EQ(FilesUnder(out), expected);
  // the first run's figures that the second did not draw are gone
  for (const std::string& f : first_report) {
    if (!expected.contains(f)) EXPECT_FALSE(fs::exists(out / f)) << f;
  }
  EXPECT_EQ(ReadFile(out / "my_notes.txt"), "a user's own file\n");
  const auto plot = RunProxsim("plot " + out.string());
  EXPECT_EQ(plot.exit_code, 0) << plot.output;
}

TEST_F(RunFolderTest, PlotRefusesAFolderWhoseFilesComeFromTwoRuns) {
  const fs::path a = dir_ / "A", b = dir_ / "B";
  ASSERT_EQ(RunProxsim("run --no-report --out " + a.string()).exit_code, 0);
  ASSERT_EQ(RunProxsim("run " + kWorldDemo + " --no-report --out " + b.string()).exit_code, 0);
  // another run's poses and summary copied in by hand
  fs::copy_file(a / "poses.csv", b / "poses.csv");
  fs::copy_file(a / "summary.json", b / "summary.json", fs::copy_options::overwrite_existing);
  const auto plot = RunProxsim("plot " + b.string());
  EXPECT_EQ(plot.exit_code, 2) << plot.output;
  EXPECT_NE(plot.output.find("poses.csv"), std::string::npos) << plot.output;
  EXPECT_NE(plot.output.find("summary.json"), std::string::npos) << plot.output;
  EXPECT_FALSE(fs::exists(b / "report")) << "nothing drawn";
}

TEST_F(RunFolderTest, AScenarioWithNoSensorsIsAnInputError) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "empty.yaml") << "proxsim: 1\nduration_s: 1\nrate_hz: 100\nscene: {builtin: dining_room}\n";
  const auto run = RunProxsim("run " + (dir_ / "empty.yaml").string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("no sensors: nothing to measure"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  const auto validate = RunProxsim("validate " + (dir_ / "empty.yaml").string());
  EXPECT_EQ(validate.exit_code, 2) << validate.output;
}

}  // namespace
}  // namespace proxsim
