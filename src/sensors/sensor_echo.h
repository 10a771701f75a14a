// A sensor's parameters as summary.json's `inputs.sensors` echoes them: every
// key of sensor_keys.cc that the spec holds (the part it came from, the range,
// the incidence window, the whole noise model, the beam, the echo model, the
// lookup table), with the values the run used — a preset's, or the scenario's
// overrides. The mounting and timing keys are the scenario's SensorConfig's and
// are added beside these by the summary (sim/run_summary.cc).
#pragma once

#include <nlohmann/json.hpp>

#include "sensors/sensor_spec.h"

namespace proxsim {

/// The spec's keys and values (null where a spec has none: no beam, no table).
nlohmann::json SensorSpecJson(const SensorSpec& spec);

}  // namespace proxsim
