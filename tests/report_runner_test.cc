// MakeReport runs the report script on a run directory: a synthetic run without
// a robot (written by tests/data/report_sample/make_sample.py) gets its figures
// and viewer; the paper's run (a robot, so a terrain map) gets terrain.png/.svg
// and the map's layer in the viewer's data; a missing directory is refused
// with a non-zero status.
#include "report/report_runner.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "scenario/scenario.h"
#include "run/run.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;

TEST(ReportRunnerTest, DrawsFiguresAndViewerForASyntheticRun) {
  const fs::path out = fs::temp_directory_path() / "proxsim_report_runner_test";
  fs::remove_all(out);
  const std::string make_sample = std::string("/usr/bin/python3 ") + PROXSIM_TEST_DATA_DIR +
                                  "/report_sample/make_sample.py " + out.string() + " --no-robot";
  ASSERT_EQ(std::system(make_sample.c_str()), 0) << make_sample;

  ASSERT_EQ(MakeReport(out.string()), 0);

  for (const char* name : {"paper_figures.png", "paper_figures.svg", "curve_laser_box.png",
                           "profile_laser_box.png", "index.html", "data.js", "viewer.js"}) {
    EXPECT_TRUE(fs::is_regular_file(out / "report" / name)) << name;
  }
  EXPECT_EQ(fs::file_size(out / "report" / "viewer.js"), fs::file_size(PROXSIM_VIEWER_BUNDLE));
  fs::remove_all(out);
}

TEST(ReportRunnerTest, ARunWithARobotGetsItsTerrainFigureAndTheMapInTheViewer) {
  const fs::path out = fs::temp_directory_path() / ("proxsim_report_terrain_" + std::to_string(getpid()));
  fs::remove_all(out);
  RunOptions options;
  options.out_dir = out.string();
  RunScenario(LoadBuiltinScenario("paper"), options);
  ASSERT_EQ(MakeReport(out.string()), 0);
  EXPECT_TRUE(fs::is_regular_file(out / "report" / "terrain.png"));
  EXPECT_TRUE(fs::is_regular_file(out / "report" / "terrain.svg"));
  std::ifstream in(out / "report" / "data.js");
  std::stringstream data;
  data << in.rdbuf();
  EXPECT_NE(data.str().find("\"terrain\":{\"resolution\":0.02,"), std::string::npos);
  EXPECT_NE(data.str().find("\"class\":\"obstacle\""), std::string::npos);
  fs::remove_all(out);
}

TEST(ReportRunnerTest, RefusesAMissingRunDirectory) {
  EXPECT_NE(MakeReport("/nonexistent/proxsim-run"), 0);
}

}  // namespace
}  // namespace proxsim
