// The scenario's `robot.gait` section declared once (core/config_schema.h):
// the gait's pace and shape (gait/gait_config.h) and what the legs do with
// an unsafe step and where they plan their footholds (scenario.h).
#pragma once

#include "core/config_schema.h"
#include "scenario/scenario.h"

namespace proxsim {

/// `robot.gait`'s keys: the reader, the summary echo and docs/scenario.md's
/// table follow them.
const ConfigSchema<RobotConfig>& GaitSectionSchema();

}  // namespace proxsim
