// What one delivered reading tells the map, from what the robot knows only:
// the device's output, where its kinematics put the sensor, and the sensor's
// datasheet (its SensorSpec: range, incidence window, noise model). Never the
// reading's status, the true distance or the point hit.
//
//  - A detection puts a point at p_WS + d·dir_W (d corrected for the noise's
//    known mean; dir_W the axis, or for a beam its cone's lowest direction,
//    the lowest the echo can have come from: knowledge/echo_cone.h) whose height has the variance the noise model gives along
//    the ray: σ_z² = σ_d²·dir_z² + σ_lat²·(1 − dir_z²), σ_d the range's
//    standard deviation at d (paper §4.3: σ·d for the multiplicative law; σ,
//    σ·d², the reflectance inversion's and the lookup table's slope for the
//    others; plus resolution²/12: sensors/range_inverse.h), σ_lat = d·tan(aperture/2)/2 for a beam
//    whose echo may come from anywhere in its cone (0 for one ray). The ray
//    before the point is empty: the echo is the first surface met (too close
//    a surface would have given no detection); the last 3σ before the point
//    are left out, since the point may lie that far beyond the true hit.
//  - A reading without a detection (d_m the maximum range, or the distance of
//    the robot's own body) says that nothing echoed over [d_min, d_m]. It
//    bounds the terrain's height only where a flat floor would have echoed:
//    when the ray is steeper than the sensor's incidence window allows for a
//    horizontal surface (|dir_z| >= cos α*), and when the sensor never drops
//    detections (noise.dropout 0). Shallower, its silence is the floor's
//    grazing incidence, not free space.
//
// Frames: W world, S the sensor.
#pragma once

#include <vector>

#include "core/geometry.h"
#include "sensors/measured_point.h"
#include "sensors/range_inverse.h"
#include "sensors/sensor_spec.h"
#include "knowledge/observation.h"

namespace proxsim {

struct RayEvidence {
  Vec3 p_WS = Vec3::Zero();    ///< the ray's origin
  Vec3 dir_W = Vec3::UnitX();  ///< unit
  bool detected = false;
  double d_m = 0.0;            ///< detection: distance to the point (bias-corrected); otherwise d_m as reported
  double variance_z_m2 = 0.0;  ///< detection: variance of the point's height
  double free_begin_m = 0.0;   ///< the ray is empty over [free_begin_m, free_end_m] ...
  double free_end_m = 0.0;     ///< ... (free_end_m <= free_begin_m: nothing known)
  bool bounds_height = false;  ///< the empty part may lower cells' upper bounds
  bool proves_empty = false;   ///< the empty part is certain (a detection's ray): it overrides heights

  Vec3 point_W() const { return MeasuredPoint_W(p_WS, dir_W, d_m); }
  Vec3 free_begin_W() const { return MeasuredPoint_W(p_WS, dir_W, free_begin_m); }
  Vec3 free_end_W() const { return MeasuredPoint_W(p_WS, dir_W, free_end_m); }
};

/// What InterpretReading reads of a datasheet that does not depend on the
/// reading, found once per sensor (the map reads 128 zones a read).
struct EvidenceModel {
  /// `with_zones` false: no zone's range found (InterpretReading finds the one it needs)
  explicit EvidenceModel(const SensorSpec& spec, bool with_zones = true);
  double tan_half_aperture = 0.0;      ///< of the spread of an echo across the beam
  double half_aperture_rad = 0.0;      ///< the same angle (the cone's lowest direction is turned down by it)
  double floor_echo_min_dir_z = 0.0;   ///< |dir_z| from which a flat floor would echo
  double silence_range_m = 0.0;        ///< the range the sensor's silence vouches for
  std::vector<double> zone_silence_range_m;  ///< the same per zone of a multi-zone sensor
};

/// What one measurement says (sensors/measurement.h): a fresh reading's
/// headline, a zone's target or silence, a beam's nearest echo. A multi-zone
/// sensor's measurement is read with its zone's (its group's) range.
RayEvidence InterpretMeasurement(const SensorSpec& spec, const EvidenceModel& model, const Measurement& measurement);
/// The same for a fresh reading's headline (the output must be fresh).
RayEvidence InterpretReading(const SensorSpec& spec, const SensorOutput& output);

}  // namespace proxsim
