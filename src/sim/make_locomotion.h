// The motion a scenario's robot section asks for: its model loaded (built-in
// or URDF), walked by the kinematic gait, replaying a recorded trajectory, or
// driven from outside (robot.locomotion: external, sampled at `rate_hz`).
// A free function, so that a caller can build its own Locomotion instead and
// hand it to the simulation.
#pragma once

#include <memory>

#include "gait/locomotion.h"
#include "scenario/scenario.h"

namespace proxsim {

/// The robot's model alone (`robot.model`, `geometry`, `package_paths`), as
/// the motion loads it. Throws InputError on a bad URDF or mesh.
RobotModel LoadRobotModel(const RobotConfig& config);

/// Throws InputError on a bad robot, gait or trajectory.
std::unique_ptr<Locomotion> MakeLocomotion(const RobotConfig& config, double rate_hz);

/// The same with the robot's model given (one loaded already: several
/// simulations of one robot share its load, e.g. VecWalkEnv's environments).
std::unique_ptr<Locomotion> MakeLocomotion(const RobotConfig& config, double rate_hz, RobotModel model);

}  // namespace proxsim
