// Points spread over a triangle mesh's surface, about one per spacing² of
// area: every triangle is covered by a lattice at half the spacing (its
// corners included), and one point is kept per cube of the spacing's side.
// A mesh surface point is then within about the spacing of a sample (at most
// √3 times it, the cube's diagonal). Used for the robot's clearance truth,
// as the primitives' grids are.
#pragma once

#include <vector>

#include "scene/shape.h"

namespace proxsim {

/// Surface samples of `mesh` in its frame O, in a deterministic order.
std::vector<Vec3> MeshSurfaceSamples_O(const TriangleMesh& mesh, double spacing_m);

}  // namespace proxsim
