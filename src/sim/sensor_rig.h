// The sensor rig: where each sensor of a scenario is fixed (the robot link,
// or the world) and its rays in its own frame, sensor after sensor. A rig is
// built on a robot model and read against a World (sim/world.h); it holds no
// bodies of its own, so one built world serves any number of rigs in turn —
// an outcome study runs every sensor set on one world per job.
//
// Frames: L a link, S a sensor.
#pragma once

#include <cstddef>
#include <vector>

#include "robot/robot_model.h"
#include "scenario/scenario.h"
#include "sensors/beam.h"

namespace proxsim {

class SensorRig {
 public:
  /// The scenario's sensors on `robot_model` (null: no robot, every sensor on
  /// the world). Throws InputError listing every sensor whose link the robot
  /// does not have.
  SensorRig(const Scenario& scenario, const RobotModel* robot_model);

  std::size_t sensor_count() const { return sensor_link_.size(); }
  /// The link sensor i is fixed on; -1 for world.
  int sensor_link(std::size_t sensor) const { return sensor_link_[sensor]; }
  /// Sensor i owns rays [ray_begin(i), ray_begin(i + 1)) of every per-ray buffer.
  std::size_t ray_begin(std::size_t sensor) const { return ray_begin_[sensor]; }
  std::size_t ray_count() const { return beam_rays_.size(); }
  /// Every sensor's rays in its own frame, sensor after sensor.
  const std::vector<BeamRay>& beam_rays() const { return beam_rays_; }

 private:
  std::vector<int> sensor_link_;
  std::vector<std::size_t> ray_begin_;
  std::vector<BeamRay> beam_rays_;
};

}  // namespace proxsim
