// The angles the gait holds the joints it does not drive at (robot.joints_deg):
// arms, torso, hip yaw and roll, an ankle roll... everything but the legs'
// hip, knee and ankle pitch. They also make the reference pose from which the
// legs' geometry is read (gait/leg_kinematics.h).
#pragma once

#include <array>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gait/gait_config.h"
#include "robot/robot_model.h"

namespace proxsim {

/// One value per joint of `model` (by joint index, rad): the angle
/// `joints_rad` gives by name, 0 for every other joint. Throws InputError
/// naming robot.joints_deg and the joint for a name that is not a joint of the
/// model (nearest name suggested), a joint that is not revolute or continuous,
/// one of the legs' pitch joints (`legs`: the gait drives them), or an angle
/// outside a revolute joint's limits.
std::vector<double> HeldJointAngles(const RobotModel& model, std::span<const std::pair<std::string, double>> joints_rad,
                                    const std::array<LegNames, 2>& legs);

}  // namespace proxsim
