// The shapes proxsim can put in a scene or on a robot link. Every shape is
// centred on its own frame O: a box spans ±size/2, a cylinder's axis is its
// local z (as in URDF) with flat caps at ±length/2, a plane is the infinite
// z = 0 plane of O facing +z (rays hit it from either side), a mesh is a
// triangle soup already scaled into O.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/geometry.h"

namespace proxsim {

struct Box {
  Vec3 size_m{1, 1, 1};  ///< full extents along x, y, z of O, each > 0
};

struct Sphere {
  double radius_m = 0.5;  ///< > 0
};

struct Cylinder {
  double radius_m = 0.5;  ///< > 0
  double length_m = 1.0;  ///< along z of O, > 0; capped at both ends
};

struct Plane {};  ///< the z = 0 plane of O, unbounded

/// Triangles in the frame O, vertices already multiplied by the scenario's scale.
struct TriangleMesh {
  std::vector<Vec3f> vertices_O;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

struct Mesh {
  std::string file;                          ///< as written in the scenario (for echoing)
  Vec3 scale{1, 1, 1};                       ///< applied to the file's vertices
  std::shared_ptr<const TriangleMesh> data;  ///< loaded triangles (never null once loaded)
};

using Shape = std::variant<Box, Sphere, Cylinder, Plane, Mesh>;

/// "box", "sphere", "cylinder", "plane" or "mesh".
const char* ShapeKindName(const Shape& shape);

}  // namespace proxsim
