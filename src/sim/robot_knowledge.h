// What the robot knows of itself at a sample, for strategies: its state (the
// locomotion's odometry and joints), where its kinematics put its feet, and
// the few quantities every strategy derives from them (heading, leading toe,
// the ground it stands on). Nothing here comes from the scene.
//
// Frames: W world, P pelvis (root link), L a link.
#pragma once

#include <span>

#include "gait/locomotion.h"
#include "sim/robot_in_scene.h"
#include "strategy/strategy.h"

namespace proxsim {

/// Fills `out` from the robot's state and its placed links; `feet` as
/// Locomotion::Feet() gives them (empty: the lowest and foremost of the
/// robot's surface points stand in for the soles and toes).
void KnowRobot(const RobotState& state, const RobotInScene& body, std::span<const FootFrame> feet,
               double half_width_m, RobotKnowledge& out);

/// The robot's half-width at its reference pose (every joint at 0): the
/// largest |y| of its surface points in the pelvis frame, m.
double ReferenceHalfWidth_m(const RobotInScene& body);

}  // namespace proxsim
