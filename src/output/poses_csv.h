// poses.csv: the robot's links in the world at every sample, for replay
// (`t_s,link,x,y,z,qw,qx,qy,qz`, one row per link per sample, streamed).
#pragma once

#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "output/run_sink.h"
#include "sim/robot_in_scene.h"

namespace proxsim {

class PosesCsvWriter : public RunSink {
 public:
  /// Writes the links of `robot` (which must outlive the writer) to `path`.
  PosesCsvWriter(const std::string& path, const RobotInScene& robot);

  /// Appends every link's pose X_WL at the frame's time.
  void Add(const SampleFrame& frame) override;
  void Commit() override { file_.Commit(); }
  void AddToSummary(nlohmann::json& summary) const override { summary["outputs"].push_back("poses.csv"); }

 private:
  AtomicFile file_;
  const RobotInScene& robot_;
  std::string line_;
};

}  // namespace proxsim
