// The model's side of `proxsim fidelity`: the recorded part replayed through
// the very code a run reads its sensors with (sim/sensor_reader.h: the
// Embree ray caster, the scene's materials, MeasureSensorSample and the
// part's model, the noise keyed by the seed, the sensor and the sample
// index), the sensor placed at each recorded pose in turn. No second model.
//
// Frames: W world, M the recorded frame, S the sensor.
#pragma once

#include <cstdint>
#include <vector>

#include "fidelity/recording_csv.h"
#include "scenario/scenario.h"

namespace proxsim {

/// The model's reading of each recorded zone sample, laid out as Recording's.
struct ReplayedReadings {
  std::vector<double> d_m;     ///< [sample · zone_count + zone]: the reading (the maximum range where not valid)
  std::vector<char> valid;     ///< a target the part reports: a zone's first target (ST's status 5), a reading `ok`
  std::vector<std::string> status;  ///< its status: ST's code name for a zone ("range_valid", …), else the reading's
};

/// Replays `recording` with the scenario's one sensor (its mounting X_MS on
/// the recorded frame M; rate, latency and flight time off: fidelity_config.h)
/// on `threads` threads; moving objects are placed at each sample's t_s.
ReplayedReadings ReplayRecording(const Scenario& scenario, const Recording& recording, int threads);

/// The number of zones the scenario's sensor reports: its grid's, else 1.
int ReportedZoneCount(const SensorConfig& sensor);

}  // namespace proxsim
