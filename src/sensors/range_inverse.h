// The sensor models' inverse, for whoever reads a reading back into the
// world (the terrain map, knowledge/ray_evidence.h): how far a reported
// distance may lie from the truth (the noise model's σ at d, per type), the
// distance a reading stands for once the datasheet's bias is taken out, and
// the incidence beyond which a surface gives no echo. They sit beside the
// forward models (sensor_model.h) so that a type's physics and its inverse
// change together.
#pragma once

#include "sensors/sensor_spec.h"

namespace proxsim {

/// The standard deviation of a reported distance d_m from the sensor's noise
/// model, m: σ·d (multiplicative), σ (additive) or σ·d² (distance-scaled) for
/// time of flight; the reflectance inversion's |dd/ds|·σ_s; a lookup table's
/// σ_output over its slope; plus resolution²/12 for a quantised output.
double RangeSigma_m(const SensorSpec& spec, double d_m);

/// The distance a detection's reported d_m stands for once the noise's mean
/// (a bias the datasheet states) is taken out.
double UnbiasedDistance_m(const SensorSpec& spec, double d_m);

/// The half-angle of the cone a reported distance's echo may come from,
/// radians: half a beam's aperture, half a zone's angular size for a
/// multizone sensor (its larger side), 0 for the paper's single ray.
double SpreadHalfAngleRad(const SensorSpec& spec);

/// The largest incidence, degrees, at which a surface still echoes: the
/// window α* of the paper's model, or, for the physical echo model of a
/// time-of-flight sensor, the angle where a white Lambertian surface's cos α
/// falls to echo_threshold.
double EchoIncidenceLimitDeg(const SensorSpec& spec);

}  // namespace proxsim
