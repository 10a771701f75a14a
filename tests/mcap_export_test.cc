// Runs in Foxglove (docs/foxglove.md): `proxsim run --mcap` and `proxsim export
// RUN --mcap` write an MCAP file that @mcap/core reads back with every topic,
// message count and time range the run calls for, Foxglove's schemas and the
// run's values (tests/foxglove/mcap_readback.mjs checks the file); bad input
// (a path among the run's own files too) is refused with exit 2, naming it,
// and writes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_helpers.h"

namespace proxsim {
namespace {

using testing::CommandResult;
using testing::FreshDir;
using testing::RunCommand;
using testing::RunProxsim;
namespace fs = std::filesystem;

const std::string kScenarios = std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/";

// node tests/foxglove/mcap_readback.mjs RUN FILE: every check of the file against the run
CommandResult ReadBack(const fs::path& run, const fs::path& mcap) {
  return RunCommand(std::string(PROXSIM_NODE_PROGRAM) + " " + PROXSIM_MCAP_READBACK + " " + run.string() + " " +
                    mcap.string());
}

void ExpectReadsBack(const fs::path& run, const fs::path& mcap) {
  ASSERT_TRUE(fs::is_regular_file(mcap)) << mcap;
  EXPECT_FALSE(fs::exists(mcap.string() + ".tmp")) << "the file appears whole";
  const CommandResult check = ReadBack(run, mcap);
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find(" 0 failed"), std::string::npos) << check.output;
}

TEST(McapExport, ThePaperRunWrittenByRunReadsBackWithFoxglovesSchemas) {
  const fs::path dir = FreshDir("mcap_paper");
  fs::create_directories(dir);
  const fs::path run = dir / "run", mcap = dir / "paper.mcap";
  const CommandResult result = RunProxsim("run --out " + run.string() + " --no-report --mcap " + mcap.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("mcap: " + mcap.string()), std::string::npos) << result.output;
  ExpectReadsBack(run, mcap);
  fs::remove_all(dir);
}

TEST(McapExport, ExportOfAColumnarRunWithoutARobotReadsBack) {
  const fs::path dir = FreshDir("mcap_npy");
  fs::create_directories(dir);
  const fs::path run = dir / "run", mcap = dir / "demo.mcap";
  const CommandResult ran =
      RunProxsim("run " + kScenarios + "world_sensors_demo.yaml --format npy --no-report --out " + run.string());
  ASSERT_EQ(ran.exit_code, 0) << ran.output;
  const CommandResult exported = RunProxsim("export " + run.string() + " --mcap " + mcap.string());
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  ExpectReadsBack(run, mcap);
  fs::remove_all(dir);
}

TEST(McapExport, ExportOfAStairsCourseWithHazardsAndACollisionRunReadBack) {
  const fs::path dir = FreshDir("mcap_terrain");
  fs::create_directories(dir);
  for (const std::string name : {"terrain_stairs_course", "paper_no_stop_rule"}) {
    const fs::path run = dir / name, mcap = dir / (name + ".mcap");
    const CommandResult ran = RunProxsim("run " + kScenarios + name + ".yaml --no-report --out " + run.string());
    ASSERT_EQ(ran.exit_code, 0) << ran.output;
    const CommandResult exported = RunProxsim("export " + run.string() + " --mcap " + mcap.string());
    ASSERT_EQ(exported.exit_code, 0) << exported.output;
    ExpectReadsBack(run, mcap);
  }
  fs::remove_all(dir);
}

TEST(McapExport, TheReadBackFailsOnAnotherRunsFile) {
  // the check is against the run: the paper's file is not the collision run's
  const fs::path dir = FreshDir("mcap_mismatch");
  fs::create_directories(dir);
  const fs::path paper = dir / "paper", other = dir / "other", mcap = dir / "paper.mcap";
  ASSERT_EQ(RunProxsim("run --no-report --out " + paper.string() + " --mcap " + mcap.string()).exit_code, 0);
  ASSERT_EQ(RunProxsim("run " + kScenarios + "paper_no_stop_rule.yaml --no-report --out " + other.string()).exit_code, 0);
  const CommandResult check = ReadBack(other, mcap);
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_NE(check.output.find("FAIL /events"), std::string::npos) << check.output;
  fs::remove_all(dir);
}

TEST(McapExport, BadInputIsRefusedNamingItAndWritesNothing) {
  const fs::path dir = FreshDir("mcap_bad");
  fs::create_directories(dir / "not_a_run");
  // a folder that holds no run
  CommandResult result = RunProxsim("export " + (dir / "not_a_run").string() + " --mcap " + (dir / "x.mcap").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("summary.json"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(dir / "x.mcap"));

  // an MCAP file in a folder that does not exist: refused before the run starts
  const fs::path run = dir / "run";
  result = RunProxsim("run --no-report --out " + run.string() + " --mcap " + (dir / "missing" / "x.mcap").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("missing does not exist"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(run));

  // the file in the run's own folder, which the run creates
  const fs::path inside = dir / "inside";
  result = RunProxsim("run --no-report --out " + inside.string() + " --mcap " + (inside / "run.mcap").string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(fs::is_regular_file(inside / "run.mcap"));
  EXPECT_TRUE(fs::is_regular_file(inside / "run.layout.json")) << "the layout beside it";

  // a folder given as the file
  ASSERT_EQ(RunProxsim("run --no-report --out " + run.string()).exit_code, 0);
  result = RunProxsim("export " + run.string() + " --mcap " + dir.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("a folder"), std::string::npos) << result.output;

  // one of the run's own files, or a file in one of its folders: never written over
  const auto readings_bytes = fs::file_size(run / "readings.csv");
  for (const fs::path& file : {run / "readings.csv", run / "terrain" / "x.mcap"}) {
    result = RunProxsim("export " + run.string() + " --mcap " + file.string());
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("one of the run's files"), std::string::npos) << result.output;
  }
  EXPECT_EQ(fs::file_size(run / "readings.csv"), readings_bytes);
  EXPECT_FALSE(fs::exists(run / "terrain" / "x.mcap"));

  // a run whose files are no longer one run's (a file changed behind the manifest)
  std::ofstream(run / "poses.csv", std::ios::app) << "9,pelvis,0,0,0,1,0,0,0\n";
  result = RunProxsim("export " + run.string() + " --mcap " + (dir / "y.mcap").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("poses.csv"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(dir / "y.mcap"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace proxsim
