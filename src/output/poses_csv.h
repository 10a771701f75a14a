// poses.csv: the robot's links in the world at every sample, for replay
// (`t_s,link,x,y,z,qw,qx,qy,qz`, one row per link per sample, streamed);
// objects_poses.csv: the scene's moving objects likewise
// (`t_s,object,x,y,z,qw,qx,qy,qz`), for scenes that have any; joints.csv:
// the robot's joint positions at every sample (`t_s,joint,position`), which
// poses.csv gives only through the URDF (a ROS 2 bag's JointState reads them).
#pragma once

#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "gait/locomotion.h"
#include "output/run_sink.h"
#include "scene/scene.h"
#include "sim/robot_in_scene.h"

namespace proxsim {

/// Appends one row `t_s,name,x,y,z,qw,qx,qy,qz` of pose X to `line`.
void AppendPoseRow(std::string& line, double t_s, const std::string& name, const Pose& X);

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

class JointsCsvWriter : public RunSink {
 public:
  /// Writes the moving joints of `model` (every one but the fixed ones, in
  /// joint order) as `state` holds them at each sample; both must outlive the writer.
  JointsCsvWriter(const std::string& path, const RobotModel& model, const RobotState& state);

  /// Appends one row per moving joint: its position, rad (m for a prismatic joint).
  void Add(const SampleFrame& frame) override;
  void Commit() override { file_.Commit(); }
  void AddToSummary(nlohmann::json& summary) const override { summary["outputs"].push_back("joints.csv"); }

 private:
  AtomicFile file_;
  const RobotModel& model_;
  const RobotState& state_;
  std::vector<int> joints_;
  std::string line_;
};

class ObjectPosesCsvWriter : public RunSink {
 public:
  /// Whether the scene has a moving object (the file is written only then).
  static bool Needed(const Scene& scene);
  /// Writes the moving objects of `scene` (which must outlive the writer) to `path`.
  ObjectPosesCsvWriter(const std::string& path, const Scene& scene);

  /// Appends every moving object's pose X_WO at the frame's time (MotionPoseAt: as the world placed it).
  void Add(const SampleFrame& frame) override;
  void Commit() override { file_.Commit(); }
  void AddToSummary(nlohmann::json& summary) const override { summary["outputs"].push_back("objects_poses.csv"); }

 private:
  AtomicFile file_;
  const Scene& scene_;
  std::string line_;
};

}  // namespace proxsim
