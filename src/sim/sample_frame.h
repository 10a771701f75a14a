// What one sample step produces: per sensor, the reading and the noise-free
// truth beside it (every reading carries its status and the truth: docs/design.md),
// and the robot's state at that time. Buffers are sized once per run and
// overwritten in place every step.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry.h"
#include "gait/locomotion.h"
#include "sensors/measurement.h"
#include "sensors/sensor_model.h"

namespace proxsim {

struct SensorSample {
  Reading reading;           ///< what the sensor reports (status not_sampled between its samples)
  Echo echo;                 ///< the truth it came from: d, α, whether the robot was hit (of the ray `truth_ray`)
  std::int32_t ray = -1;        ///< the beam's ray that gave the reading; -1: none (0 is the axis)
  std::int32_t truth_ray = 0;   ///< the ray whose truth (echo, object_id, p_WH) is given
  double t_reported_s = 0.0;    ///< when the reading is reported: the sample time plus the sensor's latency
  std::int32_t object_id = -1;  ///< hit object (scene objects first, then robot links); -1: none
  Vec3 p_WH = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());  ///< hit point, NaN when none
  Vec3 p_WS = Vec3::Zero();       ///< ray origin: the sensor frame's origin in world
  Vec3 dir_W = Vec3::UnitX();     ///< the sensor's axis: its frame's +x in world (a beam's rays spread around it)
  /// A zone part reporting distances on its axis (sensors/measurement.h):
  /// the reading's point lies d_m / cos_to_axis along dir_W; 1 otherwise.
  double cos_to_axis = 1.0;
  /// What the sensor reports beside its reading (sensors/measurement.h): a
  /// multi-zone part's targets, a beam's echoes; empty for the others and
  /// between its own samples.
  Measurements measurements;
  /// The same list with noise-free distances (the truth beside each).
  Measurements measurements_truth;
};

struct RobotSample {
  bool present = false;     ///< false when the scenario has no robot
  double gait_phase = 0.0;  ///< of the left leg, in [0, 1), 0 at its heel strike
  SupportLeg support = SupportLeg::kDouble;
  bool stopped = false;
  double distance_walked_m = 0.0;
};

struct SampleFrame {
  std::int64_t sample = 0;  ///< index k; t_s = k / rate_hz
  double t_s = 0.0;
  std::vector<SensorSample> sensors;  ///< one per scenario sensor, in scenario order
  RobotSample robot;
};

}  // namespace proxsim
