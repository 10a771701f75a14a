// A sensor's beam as a cone of rays (beyond the paper, which casts
// one ray): a deterministic layout that covers the cone evenly in solid
// angle — the axis ray, then K rings at θ_k = (aperture/2)·k/K holding a
// number of rays proportional to k (6, 12, 18, … for 7, 19, 37 rays) — and per
// ray the pattern's gain g(θ) (peak 1) and a weight w ∝ g(θ)·Ω, Ω the solid
// angle the ray stands for, normalised to Σw = 1. The paper's single ray is
// the layout of one ray: the axis, g = 1, w = 1.
//
// Frames: W world, S the sensor (its +x is the beam's axis).
#pragma once

#include <vector>

#include "core/geometry.h"
#include "sensors/sensor_spec.h"

namespace proxsim {

struct BeamRay {
  Vec3 dir_S = Vec3::UnitX();  ///< unit direction in the sensor frame
  double off_axis_deg = 0.0;   ///< θ, angle from the axis
  double gain = 1.0;           ///< pattern gain g(θ), relative to the pattern's peak
  double weight = 1.0;         ///< solid-angle weight, Σ over the beam = 1
};

/// The pattern's gain at θ degrees off the axis, relative to its peak (in [0, 1]).
double BeamGain(const BeamSpec& beam, double off_axis_deg);

/// How far off the axis, degrees, an echo from d_m away is heard: the
/// `reach` rows at d_m (piecewise linear, held beyond the ends), at most the
/// cone's half-aperture; the half-aperture when there are no rows.
double BeamReachDeg(const BeamSpec& beam, double d_m);
/// Whether a ray off_axis_deg off the axis whose echo comes from d_m away is
/// heard (always, without a beam or a reach table, and on the axis).
bool BeamReaches(const std::optional<BeamSpec>& beam, double off_axis_deg, double d_m);

/// The rays of a beam; one axis ray for a sensor without one.
std::vector<BeamRay> MakeBeamRays(const std::optional<BeamSpec>& beam);

/// The direction in W of `ray` for a sensor at pose X_WS. The axis ray is the
/// sensor's +x column as it stands (the paper's single ray), not a product
/// that could round it.
Vec3 BeamRayDir_W(const Pose& X_WS, const BeamRay& ray);

}  // namespace proxsim
