// summary.json's parts that come from the simulation: the inputs as they
// were understood (after defaults and presets), the versions of the
// libraries, and the robot's outcome (stop, goal, events, clearance).
#pragma once

#include <nlohmann/json.hpp>

#include "sim/simulation.h"

namespace proxsim {

nlohmann::json VersionsJson();

/// The scenario echoed: source, seed, robot (with its strategy), duration, rate, scene, sensors.
nlohmann::json InputsJson(const Scenario& scenario);

/// summary.json `robot`; requires sim.robot().
nlohmann::json RobotOutcomeJson(const Simulation& sim);

}  // namespace proxsim
