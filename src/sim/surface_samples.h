// Points spread over the surface of a shape, for clearance checks: the robot's
// minimum distance to the scene is taken as the least distance of these points,
// which is exact to within the sample spacing.
#pragma once

#include <vector>

#include "scene/shape.h"

namespace proxsim {

/// Points on the surface of `shape` (in its own frame O), about `spacing_m`
/// apart, corners and edges included (meshes: scene/mesh_samples.h). Planes give no points.
std::vector<Vec3> SurfaceSamples_O(const Shape& shape, double spacing_m);

}  // namespace proxsim
