// Co-simulation from Python (docs/cosimulation.md): the robot's state as a
// script gives it to sim.step(q=..., X_WP=...), read into an ExternalState,
// and the robot's state of the last sample as a dict (sim.robot_state()),
// the same quantities the other way.
#pragma once

#include <pybind11/pybind11.h>

#include "gait/external_drive.h"
#include "gait/locomotion.h"
#include "robot/robot_model.h"

namespace proxsim {

/// q: {joint name: value} or a sequence in drive.joint_names() order (rad, m);
/// X_WP: (xyz, quat_wxyz) or (xyz, 3×3 rotation matrix); gait_phase and
/// support_leg ("left", "right", "double"): None when the caller has none.
/// Throws ValueError/TypeError on a malformed argument, InputError for
/// missing or unknown joint names (the state's values are Set()'s to check).
ExternalState ExternalStateFromPython(const ExternalDrive& drive, const pybind11::object& q,
                                      const pybind11::object& X_WP, const pybind11::object& gait_phase,
                                      const pybind11::object& support_leg);

/// {t_s, xyz, quat_wxyz (w >= 0), R, q (moving joints in model order), gait_phase,
/// support_leg, stopped, distance_walked_m} of `state` for `model`.
pybind11::dict RobotStateDict(const RobotModel& model, const RobotState& state);

}  // namespace proxsim
