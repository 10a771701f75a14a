// The small interface between a robot's motion source (the kinematic gait or a
// replayed trajectory) and the simulation loop or a strategy: step it in time,
// read the robot's state, and command it (stop, resume, change stride).
#pragma once

#include <vector>

#include "core/geometry.h"
#include "robot/robot_model.h"

namespace proxsim {

enum class SupportLeg { kLeft, kRight, kDouble };

/// "left", "right" or "double".
const char* SupportLegName(SupportLeg s);

/// The robot at one sample time.
struct RobotState {
  double t_s = 0;                   ///< sample time
  Pose X_WP = Pose::Identity();     ///< root link (pelvis) pose in the world
  std::vector<double> q;            ///< joint positions by joint index, rad (m for prismatic)
  double gait_phase = 0;            ///< left leg's phase in [0, 1), 0 at left heel strike
  SupportLeg support = SupportLeg::kDouble;
  bool stopped = false;             ///< standing still (commanded stop or end of path)
  double distance_walked_m = 0;     ///< path length of the pelvis on the floor since t = 0
};

/// What moves the robot. Advance() is called with non-decreasing times.
class Locomotion {
 public:
  virtual ~Locomotion() = default;
  /// The state at t_s (≥ the previous call's).
  virtual RobotState Advance(double t_s) = 0;
  /// Stop at the next double support and stand still there, both feet down.
  virtual void RequestStop() = 0;
  /// Walk again after a stop.
  virtual void Resume() = 0;
  /// Stride (heel strike to heel strike of one foot) to walk from the next step on, metres.
  virtual void SetStride(double stride_m) = 0;
  virtual const RobotModel& model() const = 0;
};

}  // namespace proxsim
