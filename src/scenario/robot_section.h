// The scenario's `robot` section declared once (core/config_schema.h): every
// key, in the docs' order. The choices (geometry, model_scene, on_collision,
// locomotion) and geom_group are read, echoed and written by the declaration;
// the maps and paths (model, legs, start, gait, path, strategy, …) by the
// section's own code (scenario_robot.cc), declared here for its key list and
// docs/scenario.md's table.
#pragma once

#include "core/config_schema.h"
#include "scenario/scenario.h"

namespace proxsim {

/// `robot`'s keys.
const ConfigSchema<RobotConfig>& RobotSectionSchema();

}  // namespace proxsim
