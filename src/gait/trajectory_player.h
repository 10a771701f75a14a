// Replays a recorded robot motion instead of the kinematic gait: a CSV with a
// header `t_s,x_m,y_m,z_m,roll_deg,pitch_deg,yaw_deg,<joint names...>`, one row
// per time: the root link's pose in the world (metres, URDF roll-pitch-yaw in
// degrees) and joint positions (degrees for revolute/continuous joints, metres
// for prismatic ones). Joints of the model not in the file stay at 0.
//
// Between rows: linear interpolation of position and joints, slerp of
// orientation. Before the first row the first is held, after the last the
// last. Times are simulation times; while stopped (RequestStop) the playback
// clock stands still, so after Resume() the rest plays late by the pause.
// A recording has no gait: support is reported as double, gait_phase as 0, and
// SetStride() and SetPath() do nothing.
#pragma once

#include <string>
#include <vector>

#include "gait/locomotion.h"

namespace proxsim {

class TrajectoryPlayer : public Locomotion {
 public:
  /// Reads `csv_path`. Throws InputError (file, line, column, what was
  /// expected) for a missing file, missing base columns, unknown joint names,
  /// non-numeric or missing cells, times not strictly increasing, no rows.
  TrajectoryPlayer(RobotModel model, const std::string& csv_path);

  /// The same from CSV text; `source` names it in messages.
  static TrajectoryPlayer FromCsvText(RobotModel model, const std::string& csv_text, const std::string& source);

  RobotState Advance(double t_s) override;
  void RequestStop() override { stopped_ = true; }
  void Resume() override { stopped_ = false; }
  void SetStride(double) override {}
  void SetPath(std::vector<Vec2>) override {}
  /// A recording names no feet.
  std::vector<FootFrame> Feet() const override { return {}; }
  void Reset() override;
  const RobotModel& model() const override { return model_; }

  /// Number of rows read.
  int row_count() const { return static_cast<int>(t_s_.size()); }

 private:
  struct Tag {};
  TrajectoryPlayer(Tag, RobotModel model) : model_(std::move(model)) {}
  void Parse(const std::string& text, const std::string& source);
  RobotState Sample(double t_play_s) const;

  RobotModel model_;
  std::vector<double> t_s_;
  std::vector<Pose> X_WP_;                 // per row
  std::vector<std::vector<double>> q_;     // per row, by joint index, rad or m
  bool started_ = false;
  bool stopped_ = false;
  double last_t_s_ = 0;
  double play_t_s_ = 0;                    // playback clock
  bool has_last_ = false;
  Vec3 last_p_WP_ = Vec3::Zero();
  double distance_m_ = 0;
};

}  // namespace proxsim
