// Where the robot starts, checked before the run (docs/scenario.md, `robot.start`):
// a start that puts the robot's geometry inside a scene object other than its
// ground, or that stands it on an object's top rather than on the ground
// (the gait stands a robot on whatever surface lies below its start: a box
// under its feet, a table it starts at), is an input error naming the object
// and the links — unless `robot.start.on` names that object, to start on it
// on purpose. Without the check the robot was silently lifted onto the
// object, and the first step down from it was blamed on the legs.
//
// The check reads what the motion really does at t = 0 (the gait's own
// placement, or a trajectory's first row), so it never disagrees with the run.
//
// Frames: W world, L a link, O an object's own frame.
#pragma once

#include <string>
#include <vector>

#include "gait/locomotion.h"
#include "scenario/scenario.h"
#include "sim/world.h"

namespace proxsim {

/// The problems with the robot's start (InputError lines), none when it is
/// fine. Advances `locomotion` to t = 0 and places the robot there, then
/// resets the locomotion (a fresh episode); `world` must hold the robot.
std::vector<std::string> StartProblems(const Scenario& scenario, World& world, Locomotion& locomotion);

}  // namespace proxsim
