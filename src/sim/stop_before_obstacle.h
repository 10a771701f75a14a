// The built-in avoidance strategy: stop before an obstacle. It looks only at
// what the robot can know — its sensors' readings, and its own kinematics (where
// its sensors and feet are) — never at the scene: a detection whose measured
// point stands higher than a threshold above the ground the robot stands on,
// inside the corridor it is walking along and within stop_distance_m ahead of
// its leading foot, asks the walker to stop at its next double support.
#pragma once

#include "core/geometry.h"
#include "sim/sample_frame.h"

namespace proxsim {

struct StopRule {
  double stop_distance_m = 0.5;         ///< look-ahead from the leading toe, > 0
  double min_height_m = 0.03;           ///< above the stance ground: lower points are floor
  double corridor_half_width_m = 0.30;  ///< lateral half-width of the path the feet sweep
};

/// What the robot knows of itself at a sample, from its own kinematics.
struct RobotSelfKnowledge {
  Vec3 heading_W = Vec3::UnitX();   ///< unit, horizontal: the walking direction
  Vec3 p_W_front = Vec3::Zero();    ///< the leading point of the feet (toe of the front foot)
  double ground_z_m = 0.0;          ///< height of the sole of the stance foot
};

/// The first sensor index whose detection calls for a stop, or -1.
int FindStopTrigger(const SampleFrame& frame, const RobotSelfKnowledge& self, const StopRule& rule);

}  // namespace proxsim
