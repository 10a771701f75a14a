// The paper's sensor models (§4–§5) as a pure function: from the first hit of
// the sensor's ray, the sensor's parameters and one Gaussian draw, the reading.
//
//   laser, ultrasonic, ideal:  d_r = d·(1 + N)                     (§5)
//   reflectance:               s   = (d_max − d)/d² · cos²α · (1 + N)   (Eq. 1)
//                              d_r = (−1 + √(1 + 4·s·d_max)) / (2s)     (§5, positive root)
//   N = σ·G + m                                                     (§4.3)
//
// Outside the range window [d_min, d_max] or the incidence window [0, α*]
// the sensor reads d_max and the sample is not a detection (§5's "else d_r =
// d_max"); the status says why. Departures from the paper, all documented in
// the README: each reading carries a status; an echo from the robot's own body
// is flagged `self` and never counts as a detection; the reflectance root is
// evaluated in the equivalent form 2·d_max / (1 + √(1 + 4·s·d_max)), which
// has no cancellation for small s and gives 0 at d = 0.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/geometry.h"
#include "sensors/sensor_spec.h"

namespace proxsim {

enum class ReadingStatus : std::uint8_t {
  kOk,        ///< a detection
  kNoEcho,    ///< nothing within d_max (or a reflectance signal ≤ 0)
  kTooClose,  ///< first hit nearer than d_min (the dead zone)
  kGrazing,   ///< incidence outside [0, α*]: the echo does not come back
  kSelf,      ///< the echo came from the robot's own body
};

/// "ok", "no_echo", "too_close", "grazing" or "self".
const char* ReadingStatusName(ReadingStatus status);

/// What the ray found: the noise-free truth a sensor works from.
struct Echo {
  double distance_m = std::numeric_limits<double>::infinity();  ///< d; +inf when nothing was hit
  double incidence_deg = 0.0;  ///< α in [0, 90]: angle between the reversed ray and the surface normal
  bool from_robot = false;     ///< the hit surface belongs to the robot
};

struct Reading {
  ReadingStatus status = ReadingStatus::kNoEcho;
  double d_m = 0.0;  ///< d_r, the distance the sensor reports
  /// Reflectance signal s of Eq. (1), 0 when there is none; NaN for the
  /// time-of-flight sensors, which report a distance directly.
  double signal = std::numeric_limits<double>::quiet_NaN();

  bool detected() const { return status == ReadingStatus::kOk; }
};

/// Incidence α in degrees, in [0, 90], between a ray of unit direction `dir`
/// and a surface of unit normal `normal`, for a two-sided surface.
double IncidenceDeg(double dir_x, double dir_y, double dir_z, double normal_x, double normal_y,
                    double normal_z);

/// The reading of a sensor given its echo and a standard normal draw G (the
/// noise N = σ·G + m is formed here). Pure: same inputs, same reading.
Reading Measure(const SensorSpec& spec, const Echo& echo, double gaussian_g);

}  // namespace proxsim
