// `proxsim inspect ROBOT` (docs/robots.md, "Your own robot"): what a robot is
// made of and how to map its legs, printed for a person or, with --json, for a
// script (the JSON's keys are documented in docs/robots.md).
#pragma once

#include <string>

namespace proxsim {

/// Inspects `target`: a URDF file, a scenario file (its robot) or
/// builtin:NAME. Prints to stdout; returns the exit code. Throws InputError on
/// bad input (a missing file, a broken URDF, a scenario without a robot).
int InspectCommand(const std::string& target, bool json);

}  // namespace proxsim
