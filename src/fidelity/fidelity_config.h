// The input of `proxsim fidelity` (docs/fidelity.md): a YAML file naming a
// scene and one sensor, in the very syntax of a scenario's `scene:` and
// `sensors:` sections (read by the scenario parser itself, so every key,
// preset and check of a run applies), and the recording to compare with:
//
//   proxsim: 1
//   seed: 7                      # the model's noise draws, when simulate_noise is on
//   scene: {objects: [...]}      # as in a scenario
//   sensors:                     # exactly one, as in a scenario (link: world)
//     - {name: tof, type: vl53l5cx, pose: {...}}   # pose: its mounting on the recorded frame
//   recording: wall.csv          # relative to this file (recording_csv.h)
//   simulate_noise: false        # the model's noise: off (its noise-free reading) or on
//   bands_m: [0.5, 1.0, 1.5, 2.0, 3.0, 4.0]   # range band edges of the statistics
//
// Frames: W world, M the frame whose pose the recording gives (the sensor's
// own when its `pose:` is left out), S the sensor (X_MS its `pose:`).
#pragma once

#include <string>
#include <vector>

#include "scenario/scenario.h"

namespace proxsim {

struct FidelityConfig {
  std::string source;             ///< the YAML file, as given
  Scenario scenario;              ///< its scene and its one sensor, as a scenario would hold them
  std::string recording_path;     ///< the CSV, resolved against the YAML's folder
  bool simulate_noise = false;    ///< false: the model's noise-free reading (σ = 0; a noise mean is kept)
  std::vector<double> band_edges_m;  ///< ascending, > 0: bands [0, e0), [e0, e1), …, [e_last, ∞)
};

/// The default range band edges, m.
std::vector<double> DefaultBandEdges_m();

/// Reads and checks the file; throws InputError listing every problem (file,
/// line, key, expectation), the scenario parser's among them.
FidelityConfig LoadFidelityFile(const std::string& path);

/// The sensor as the comparison replays it: each recorded sample is one of
/// its own measurements (no rate, latency or flight time: they belong to a
/// run's clock), and without simulate_noise its noise spread is zero.
void PrepareFidelitySensor(SensorConfig& sensor, bool simulate_noise);

}  // namespace proxsim
