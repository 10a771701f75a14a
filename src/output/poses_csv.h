// poses.csv: the robot's links in the world at every sample, for replay
// (`t_s,link,x,y,z,qw,qx,qy,qz`, one row per link per sample, streamed).
#pragma once

#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "robot/robot_model.h"

namespace proxsim {

class PosesCsvWriter {
 public:
  PosesCsvWriter(const std::string& path, const RobotModel& model);

  /// Appends every link's pose X_WL at t_s.
  void Append(double t_s, const std::vector<Pose>& X_WL);
  void Commit() { file_.Commit(); }

 private:
  AtomicFile file_;
  const RobotModel& model_;
  std::string line_;
};

}  // namespace proxsim
