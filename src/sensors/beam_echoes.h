// A time-of-flight beam's several echoes from one ping (`echoes: strongest |
// all`, docs/sensors.md#several-echoes). The rays that are heard (the lobe's
// reach) and whose echo counts (range, incidence window or physical model,
// the beam's threshold) are split into echoes as a multi-zone part splits its
// targets (echo_groups.h), at the sensor's `echo_separation_m`. An echo's
// distance is its nearest ray's arrival — the leading edge a receiver times,
// so the first echo is exactly the paper's beam reading — and its signal the
// sum over its rays of w·E: w the ray's weight (the pattern's gain times the
// solid angle it stands for, Σw = 1 over the beam), E the returned energy of
// the physical echo model, or in the window model the surface's reflectivity
// for the modality (acoustic for ultrasonic, the IR albedo otherwise). No
// fall-off with distance, as in the physical model: the range stays the limit.
#pragma once

#include <span>
#include <vector>

#include "sensors/beam.h"
#include "sensors/sensor_model.h"

namespace proxsim {

/// One echo of a ping: its distance (noise-free arrival, or as reported),
/// its signal, and the sensor's ray it arrived on first.
struct BeamEcho {
  double d_m = 0.0;
  double signal = 0.0;
  int ray = -1;
  double truth_d_m = 0.0;  ///< the noise-free arrival (d_m before the noise)
};

/// The beam's echoes, nearest first, at most `max_echoes`, noise-free.
std::vector<BeamEcho> BeamEchoes(const SensorSpec& spec, std::span<const Echo> echoes, std::span<const BeamRay> rays,
                                 int max_echoes);

/// The ray of the strongest echo (the nearest of equal ones), -1 without one.
int StrongestEchoRay(const SensorSpec& spec, std::span<const Echo> echoes, std::span<const BeamRay> rays);

/// The echoes as the sensor reports them: up to kMaxEchoes, nearest first,
/// each distance with the noise of its ray's draw (σ for its surface); an echo
/// lost to the dropout is left out.
std::vector<BeamEcho> ReportedEchoes(const SensorSpec& spec, std::span<const Echo> echoes,
                                     std::span<const BeamRay> rays, const DrawOfRay& draw);

}  // namespace proxsim
