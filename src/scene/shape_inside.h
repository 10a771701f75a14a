// Whether a point lies inside a solid shape, and how deep: for the warnings
// about a sensor that starts inside an object or inside its own link, for
// the check that a robot does not start inside a scene object, and where a
// line leaves a shape (the front surface of a robot's shank).
//
// Boxes, spheres and cylinders are solids; a plane has no inside (only its
// z = 0 surface); a mesh is solid where it encloses the point, decided by
// the parity of a ray's crossings (three rays, the majority wins, so a ray
// through an edge or a small hole does not decide alone). Cost: a few passes
// over the mesh's triangles per point, for checks of a few points (a sensor's
// origin); sim/start_check.cc checks thousands with the ray caster instead.
//
// Frames: O the shape's own frame.
#pragma once

#include <optional>

#include "scene/shape.h"

namespace proxsim {

/// How far p_O lies inside the shape, metres: > 0 inside (the distance to
/// the nearest surface), 0 on the surface, < 0 outside (for a mesh, outside
/// its bounding box: a lower bound of the distance, never more negative than
/// the truth). A plane gives −|z|.
double DepthInside_m(const Shape& shape, const Vec3& p_O);

/// The largest t (metres along the unit direction d_O) at which the line
/// p_O + t·d_O meets the shape's surface, t of either sign; nullopt when the
/// line misses it. For a plane: where it crosses z = 0 (nullopt when parallel).
/// Where a sensor can sit on a link's front: `proxsim inspect`.
std::optional<double> FarthestAlongLine_m(const Shape& shape, const Vec3& p_O, const Vec3& d_O);

}  // namespace proxsim
