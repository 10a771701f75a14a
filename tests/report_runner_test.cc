// MakeReport runs the report script on a run directory: a synthetic run without
// a robot (written by tests/data/report_sample/make_sample.py) gets its figures
// and viewer; a missing directory is refused with a non-zero status.
#include "report/report_runner.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

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

TEST(ReportRunnerTest, RefusesAMissingRunDirectory) {
  EXPECT_NE(MakeReport("/nonexistent/proxsim-run"), 0);
}

}  // namespace
}  // namespace proxsim
