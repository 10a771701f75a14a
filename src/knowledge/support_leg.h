// Which leg carries the robot: what its gait reports and what the robot
// knows of itself (knowledge/observation.h), below both.
#pragma once

#include <string>
#include <vector>

namespace proxsim {

enum class SupportLeg { kLeft, kRight, kDouble };

/// "left", "right" or "double".
const char* SupportLegName(SupportLeg s);
/// Every support leg's name, in code order (the output files' codes).
const std::vector<std::string>& SupportLegNames();

}  // namespace proxsim
