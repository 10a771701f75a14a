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
// docs/sensors.md: each reading carries a status; an echo from the robot's own body
// is flagged `self` and never counts as a detection; the reflectance root is
// evaluated in the equivalent form 2·d_max / (1 + √(1 + 4·s·d_max)), which
// has no cancellation for small s and gives 0 at d = 0.
//
// Beyond the paper (docs/sensors.md; each part off unless the sensor's spec asks for
// it, so the paper's presets give the paper's readings bit for bit):
//   - noise variants (additive, distance-scaled), quantisation to
//     resolution_m, and a dropout probability (status `dropout`);
//   - materials: with use_material, Eq. (1)'s s is scaled by the surface's IR
//     albedo ρ: s = ρ·(d_max − d)/d²·cos²α·(1 + N);
//   - echo_model physical (time of flight): instead of the window α <= α*, the
//     echo returns when g·E >= echo_threshold, with the returned energy of a
//     Phong-like lobe for a sensor that is emitter and receiver at once (as
//     HELIOS++ does for lidar): E = r·((1 − s)·cos α + s·max(0, cos 2α)^n),
//     r the surface's reflectivity for the modality, s its specular fraction,
//     n the lobe's exponent, g the beam pattern's gain for the ray; 2α is the
//     angle between the mirror direction and the way back to the sensor;
//   - the receiver's motion during the flight (Echo::flight_shift_m);
//   - a lookup sensor: output = table(d) + σ·G with σ = fraction·output
//     (Webots' lookupTable), and the distance it implies, read off the table's
//     far branch;
//   - a beam of several rays (beam.h): time of flight reports the nearest echo
//     that counts (a sonar's threshold detector), or, for a part whose
//     readout is kSignalWeighted (ST's VL53L0X, VL53L1X), its rays' returns
//     weighed by their signal and resolved into targets as a multi-zone
//     zone resolves its own, the nearest target's weighted centre;
//     reflectance sums the weighted signals and inverts the sum.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "sensors/beam.h"
#include "sensors/noise.h"
#include "sensors/sensor_spec.h"

namespace proxsim {

enum class ReadingStatus : std::uint8_t {
  kOk,        ///< a detection
  kNoEcho,    ///< nothing within d_max (or a reflectance signal ≤ 0)
  kTooClose,  ///< first hit nearer than d_min (the dead zone)
  kGrazing,   ///< incidence outside [0, α*]: the echo does not come back
  kSelf,      ///< the echo came from the robot's own body
  kDropout,   ///< an echo that counted, lost to the noise model's dropout
  kNotSampled,  ///< the sensor took no sample at this time (its rate_hz is below the run's)
  kCrosstalk,   ///< the device reports an echo, but of another sensor's ping (sensors/crosstalk.h); a detection to the robot
  kLast = kCrosstalk,  ///< the highest status: tables indexed by status have kLast + 1 slots
};

/// "ok", "no_echo", "too_close", "grazing", "self", "dropout", "not_sampled" or "crosstalk".
const char* ReadingStatusName(ReadingStatus status);
/// Every status's name, in code order (the output files' codes).
const std::vector<std::string>& ReadingStatusNames();

/// What the ray found: the noise-free truth a sensor works from.
struct Echo {
  double distance_m = std::numeric_limits<double>::infinity();  ///< d; +inf when nothing was hit
  double incidence_deg = 0.0;  ///< α in [0, 90]: angle between the reversed ray and the surface normal
  bool from_robot = false;     ///< the hit surface belongs to the robot
  // the surface's material (scene/scene.h); the robot's links are 1, 1, 0
  double ir_albedo = 1.0;              ///< ρ, the diffuse reflectance in the infrared
  double acoustic_reflectivity = 1.0;  ///< fraction of the sound energy the surface returns
  double specular = 0.0;               ///< s, the specular fraction of the reflection
  /// The time-of-flight distance minus d: half the change in the way back while
  /// the sensor moved during the flight (0 unless flight_time is on).
  double flight_shift_m = 0.0;
};

/// The draws of ray `ray` of a reading, made when the model asks for them: a
/// reading uses the draws of at most one ray (the echo it reports), so a beam
/// of 32 rays pays for one draw, and a sample with no echo for none. The
/// draws must be a pure function of the ray (keyed noise), so that asking
/// lazily gives the reading it would give with every draw made up front.
using DrawOfRay = std::function<NoiseDraw(int ray)>;

struct Reading {
  ReadingStatus status = ReadingStatus::kNoEcho;
  double d_m = 0.0;  ///< d_r, the distance the sensor reports
  /// Reflectance signal s of Eq. (1), 0 when there is none; NaN for the
  /// time-of-flight sensors, which report a distance directly.
  double signal = std::numeric_limits<double>::quiet_NaN();
  /// A lookup sensor's output (the table's unit); NaN for the other types.
  double output = std::numeric_limits<double>::quiet_NaN();

  /// The device reports an echo (crosstalk included: the device cannot tell).
  bool detected() const { return status == ReadingStatus::kOk || status == ReadingStatus::kCrosstalk; }
};

/// Incidence α in degrees, in [0, 90], between a ray of unit direction `dir`
/// and a surface of unit normal `normal`, for a two-sided surface.
double IncidenceDeg(double dir_x, double dir_y, double dir_z, double normal_x, double normal_y,
                    double normal_z);

/// The reading of a sensor given its echo and a standard normal draw G (the
/// noise N = σ·G + m is formed here) and a uniform for the dropout (1: never
/// dropped). Pure: same inputs, same reading.
Reading Measure(const SensorSpec& spec, const Echo& echo, double gaussian_g, double dropout_uniform = 1.0);

/// The same reading, with the draws of ray 0 made only if the echo counts.
Reading Measure(const SensorSpec& spec, const Echo& echo, const DrawOfRay& draw);

/// A time-of-flight reading of a noise-free distance d: d·(1 + N), d + N or
/// d + N·d² with N = σ·G + m, rounded to the resolution (the draw of §4.3).
double TimeOfFlightReading_m(const NoiseSpec& noise, double d, double gaussian_g);

/// Whether the echo of one ray of pattern gain `gain` counts: kOk or kSelf
/// when it does, otherwise why not (range, dead zone, incidence window or,
/// in the physical model or below echo_threshold, kGrazing / kNoEcho).
ReadingStatus EchoStatus(const SensorSpec& spec, const Echo& echo, double gain);
/// As EchoStatus, with the longest range for this echo's target given (a
/// multi-zone zone's, which depends on its place in the grid; +inf: none).
ReadingStatus EchoStatusWithin(const SensorSpec& spec, const Echo& echo, double gain, double target_range_m);

/// Returned energy E of the physical echo model for a surface hit at the
/// echo's incidence (see the top of this file); r per the sensor's modality.
double PhysicalEchoEnergy(const SensorSpec& spec, const Echo& echo);

/// The reflectance a part whose range depends on the target sees in an echo
/// met at incidence θ by a ray φ = `off_axis_deg` off its axis: its range
/// tables are a datasheet's, measured on a flat target facing the part,
/// which that ray meets at φ; relative to it the surface returns E(θ)/E(φ)
/// of the light (E the physical echo model's energy: ρ·cos θ for a matte
/// surface), so ρ·E(θ)/E(φ) — a grazing floor is a dark target. 0 when the
/// facing target would return nothing.
double IncidentReflectance(const SensorSpec& spec, const Echo& echo, double off_axis_deg = 0.0);

/// What one ray's echo returns, the measure of an echo's signal (several
/// echoes, a zone's targets): E of the physical model, or else the
/// surface's reflectivity per the sensor's modality.
double ReturnedEnergy(const SensorSpec& spec, const Echo& echo);

/// A lookup table's output at distance d: linear between rows, the first
/// row's value before the table and the last row's beyond it (and on a miss).
/// `noise_fraction` receives the interpolated noise fraction when not null.
double LookupOutput(const std::vector<LookupRow>& table, double distance_m, double* noise_fraction = nullptr);

/// The distance a lookup output implies, searched from the far end of the
/// table (the branch a datasheet's user calibrates): the farthest d with
/// LookupOutput(d) = output; the distance of the closest output if none.
double LookupDistance(const std::vector<LookupRow>& table, double output);

/// The time of flight's distance minus d when the sensor moves: it emits at t
/// from p_WS moving at v_W, the echo leaves p_WH (d from p_WS) and comes back
/// to the sensor at t + τ where c·τ = d + |p_WH − (p_WS + v_W·τ)|; the sensor
/// reports c·τ/2, so the shift is half the change of the way back (moving
/// straight at the surface at v: c·τ/2 = d·c/(c + v), i.e. −v·τ/2).
double FlightTimeShift(const Vec3& p_WS, const Vec3& v_W, const Vec3& p_WH, double d_m, double c_m_s);

/// How far along a ray the outgoing wave meets a surface that moves: the ray
/// leaves at t along unit dir_W and meets the surface at d when it stands
/// still; the surface (unit normal n_W, either side) moves at v_W, taken as
/// a plane moving at constant velocity over the flight (first order in the
/// flight time): the wave meets it at r = d / (1 − (n·v)/(c·(n·dir))), and
/// r = d·c/(c + v) for a surface coming straight at the sensor at v. d when
/// the ray grazes the surface (n·dir = 0).
double MovingSurfaceMeeting_m(double d_m, const Vec3& dir_W, const Vec3& n_W, const Vec3& v_W, double c_m_s);

/// The reading of a whole beam: echoes[i] and draws[i] belong to rays[i].
/// `ray` is the ray whose echo gave the reading (time of flight: the nearest
/// echo that counts, or with spec.beam_readout kSignalWeighted the nearest
/// ray of the target read; reflectance: the largest weighted signal), -1
/// without a detection; `truth_ray` the ray whose truth stands beside the
/// reading (the same ray when there is one).
struct BeamReading {
  Reading reading;
  int ray = -1;
  int truth_ray = 0;
};
BeamReading MeasureBeam(const SensorSpec& spec, std::span<const Echo> echoes, std::span<const BeamRay> rays,
                        std::span<const NoiseDraw> draws);

/// The same beam reading, with the one ray's draws it needs made on demand.
BeamReading MeasureBeam(const SensorSpec& spec, std::span<const Echo> echoes, std::span<const BeamRay> rays,
                        const DrawOfRay& draw);

}  // namespace proxsim
