// Normative sagittal joint angles of human walking over one gait cycle, as the
// gait generator's reference (the paper's robot copied a child's gait, its
// Fig. 7). Key points (listed in docs/robots.md) read from Perry &
// Burnfield, "Gait Analysis" (2010) and Winter, "Biomechanics and Motor Control
// of Human Movement" (2009): hip flexion, knee flexion, ankle dorsiflexion in
// degrees against % of the cycle from heel strike.
//
// Between key points we use a periodic cubic Hermite spline with Catmull-Rom
// tangents (C1, through every key point) instead of straight lines between them.
//
// Departures, all on purpose:
//  - The pelvis is kept upright, so the ≈10° pelvic tilt included in the hip
//    curve is subtracted: the hip joint angle is the thigh's angle from the
//    vertical, hip − 10°.
//  - Amplitude k scales every angle (k = 1 is the normative adult gait, k → 0
//    standing straight); the walker picks k so the walked stride is stride_m.
//  - During stance the foot pitch implied by the three curves rocks heel → toe
//    → heel → toe (linear key points do not keep the foot flat). We impose the
//    clinical rocker instead: the curves' foot pitch before foot-flat (heel
//    rocker) and after heel-off (toe rocker), exactly 0 in between, joined by C1
//    ramps; the stance ankle angle is derived from that pitch. Foot-flat and
//    heel-off are the zero crossings of the curves' own foot pitch.
//
// Sign conventions (sagittal plane of the pelvis, x forward, z up): segment
// angles are measured from the downward vertical, positive when the lower end
// moves forward: thigh = hip, shank = hip − knee, foot pitch (toe up +) =
// shank + ankle. (Not ankle − θS, as one may find it written: with these
// definitions the toe-up pitch is θS + ankle, which is what a URDF chain composes.)
#pragma once

#include <utility>
#include <vector>

namespace proxsim {

/// A periodic C1 curve through key points (phase in [0, 1), value), cubic
/// Hermite with Catmull-Rom tangents; phase wraps.
class PeriodicCurve {
 public:
  /// `key_points` sorted by phase in [0, 1); at least 3.
  explicit PeriodicCurve(std::vector<std::pair<double, double>> key_points);
  double operator()(double phase) const;

 private:
  std::vector<double> phase_;
  std::vector<double> value_;
  std::vector<double> slope_;
};

/// Normative curves, degrees against phase in [0, 1) from heel strike.
const PeriodicCurve& NormativeHipFlexionDeg();
const PeriodicCurve& NormativeKneeFlexionDeg();
const PeriodicCurve& NormativeAnkleDorsiflexionDeg();

/// Pelvic tilt folded out of the hip curve, degrees.
constexpr double kPelvicTiltDeg = 10.0;

/// Stance runs from heel strike (0) to toe-off; the other foot strikes at 0.5.
constexpr double kToeOffPhase = 0.6;

/// Sagittal angles of one leg in radians (see the sign conventions above).
struct LegAnglesRad {
  double hip = 0;    ///< hip flexion (thigh angle from the vertical)
  double knee = 0;   ///< knee flexion, ≥ 0
  double pitch = 0;  ///< foot pitch from horizontal, toe up positive
};

/// The curves at `phase` scaled by amplitude k: hip = k(hip − tilt), knee = k·knee,
/// pitch = k × curves' foot pitch; for phase in [0, 0.5] the stance pitch
/// (flattened between foot-flat and heel-off) instead, its toe rocker (after
/// heel-off) further scaled by `push_off_gain` in [0, 1] (see gait_steps.h).
LegAnglesRad CurveLegAngles(double phase, double amplitude, double push_off_gain = 1.0);

/// Phases of foot-flat and heel-off: the foot is exactly flat in between.
double FootFlatPhase();
double HeelOffPhase();

}  // namespace proxsim
