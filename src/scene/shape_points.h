// Points that outline a shape, for extremes such as the lowest point of a
// foot or the widest point of a robot: exact for boxes (their corners) and
// meshes (their vertices), dense enough on curved shapes (cylinder rims every
// degree, a sphere's Fibonacci lattice of 4000 points: within 0.05 % of the
// radius) for millimetre decisions on robot-sized parts.
#pragma once

#include <vector>

#include "scene/shape.h"

namespace proxsim {

/// Outline points in the shape's frame O; none for a plane (it is unbounded).
std::vector<Vec3> ShapeOutlinePoints_O(const Shape& shape);

}  // namespace proxsim
