// Trajectory player: interpolation between rows, holding the ends, pausing,
// and every kind of bad file refused with its file and line.
#include <gtest/gtest.h>

#include "input_error_helpers.h"

#include "core/input_error.h"
#include "gait/trajectory_player.h"

namespace proxsim {
namespace {

const std::string kDir = PROXSIM_TEST_DATA_DIR "/trajectories/";
const char* kHeader = "t_s,x_m,y_m,z_m,roll_deg,pitch_deg,yaw_deg,left_knee_pitch\n";

using testing::ErrorOf;

std::string ErrorOfText(const std::string& text) {
  return ErrorOf([&] { TrajectoryPlayer::FromCsvText(RobotModel::Builtin("biped"), text, "mem.csv"); });
}

TEST(TrajectoryPlayer, InterpolatesAtMidTimesAndHoldsTheEnds) {
  TrajectoryPlayer player(RobotModel::Builtin("biped"), kDir + "two_rows.csv");
  EXPECT_EQ(player.row_count(), 3);
  const RobotModel& m = player.model();
  const int knee = m.JointIndex("left_knee_pitch"), hip = m.JointIndex("right_hip_pitch");
  RobotState s = player.Advance(0.0);
  EXPECT_NEAR(s.q[hip], DegToRad(10), 1e-12);
  s = player.Advance(0.5);
  // halfway: positions and joints linear, yaw slerped to 45°
  EXPECT_NEAR(s.X_WP.translation().x(), 0.5, 1e-12);
  EXPECT_NEAR(s.X_WP.translation().y(), 0.25, 1e-12);
  EXPECT_NEAR(s.X_WP.translation().z(), 0.94, 1e-12);
  EXPECT_NEAR(RpyFromRotation(s.X_WP.linear()).z(), DegToRad(45), 1e-9);
  EXPECT_NEAR(s.q[knee], DegToRad(20), 1e-12);
  EXPECT_NEAR(s.q[hip], 0.0, 1e-12);
  EXPECT_EQ(s.q[m.JointIndex("left_hip_pitch")], 0.0);  // not in the file
  s = player.Advance(0.25);  // a time going back is held, not replayed
  EXPECT_NEAR(s.X_WP.translation().x(), 0.5, 1e-12);
  s = player.Advance(5.0);  // after the end: the last row
  EXPECT_NEAR(s.X_WP.translation().x(), 1.0, 1e-12);
  EXPECT_NEAR(s.q[knee], DegToRad(40), 1e-12);
  EXPECT_NEAR(s.distance_walked_m, std::hypot(1.0, 0.5), 1e-9);
}

TEST(TrajectoryPlayer, StopFreezesThePlaybackClock) {
  TrajectoryPlayer player(RobotModel::Builtin("biped"), kDir + "two_rows.csv");
  player.Advance(0.0);
  player.Advance(0.25);
  player.RequestStop();
  RobotState s = player.Advance(0.75);
  EXPECT_TRUE(s.stopped);
  EXPECT_NEAR(s.X_WP.translation().x(), 0.25, 1e-12);
  player.Resume();
  s = player.Advance(1.0);  // 0.25 s of play since the resume
  EXPECT_NEAR(s.X_WP.translation().x(), 0.5, 1e-12);
}

TEST(TrajectoryPlayer, RefusesBadFilesNamingFileAndLine) {
  EXPECT_NE(ErrorOf([] { TrajectoryPlayer(RobotModel::Builtin("biped"), kDir + "no_such.csv"); }).find("no_such.csv"),
            std::string::npos);
  const std::string bad_cell = ErrorOf([] { TrajectoryPlayer(RobotModel::Builtin("biped"), kDir + "bad_cell.csv"); });
  EXPECT_NE(bad_cell.find("bad_cell.csv:3"), std::string::npos) << bad_cell;
  EXPECT_NE(bad_cell.find("left_knee_pitch"), std::string::npos) << bad_cell;

  const std::string missing = ErrorOfText("t_s,x_m,y_m,roll_deg,pitch_deg\n0,0,0,0,0\n");
  EXPECT_NE(missing.find("missing column 'z_m'"), std::string::npos) << missing;
  EXPECT_NE(missing.find("missing column 'yaw_deg'"), std::string::npos) << missing;

  const std::string unknown = ErrorOfText("t_s,x_m,y_m,z_m,roll_deg,pitch_deg,yaw_deg,elbow\n0,0,0,0,0,0,0,0\n");
  EXPECT_NE(unknown.find("mem.csv:1: column 'elbow'"), std::string::npos) << unknown;

  const std::string not_increasing = ErrorOfText(std::string(kHeader) + "0,0,0,1,0,0,0,0\n1,0,0,1,0,0,0,0\n1,0,0,1,0,0,0,0\n");
  EXPECT_NE(not_increasing.find("mem.csv:4"), std::string::npos) << not_increasing;
  EXPECT_NE(not_increasing.find("strictly increase"), std::string::npos) << not_increasing;

  const std::string short_row = ErrorOfText(std::string(kHeader) + "0,0,0,1,0,0,0\n");
  EXPECT_NE(short_row.find("mem.csv:2: 7 cells, expected 8"), std::string::npos) << short_row;

  EXPECT_NE(ErrorOfText(kHeader).find("no data rows"), std::string::npos);
  EXPECT_NE(ErrorOfText("").find("empty"), std::string::npos);
  EXPECT_EQ(ErrorOfText(std::string(kHeader) + "0,0,0,1,0,0,0,5\n"), "");
}

}  // namespace
}  // namespace proxsim
