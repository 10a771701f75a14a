// The scenario's sections declared by a schema (core/config_schema.h), by the
// name `proxsim columns --keys NAME` takes: their keys for the docs' tables
// and the Python package. A section declared in its own module joins here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/config_schema.h"

namespace proxsim {

/// "material" (a scene object's), "map", "robot", "robot.gait",
/// "strategy.stop", "strategy.circumvent", in that order.
std::vector<std::string> ConfigSectionNames();

/// The keys of section `name`; nullopt for a name not in ConfigSectionNames().
std::optional<std::vector<ParamDescription>> ConfigSectionParams(const std::string& name);

}  // namespace proxsim
