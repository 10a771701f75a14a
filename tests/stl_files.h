// Small STL files written by the tests themselves: a cube and a tetrahedron,
// binary (with a header that starts with "solid", as many CAD exporters
// write it) or ASCII, and a helper for URDF folders.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/geometry.h"

namespace proxsim::testing {

using StlTriangle = std::array<Vec3, 3>;

/// A cube of side 2·half centred on the origin, 12 triangles wound outward.
inline std::vector<StlTriangle> CubeTriangles(double half) {
  std::vector<StlTriangle> triangles;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (const double side : {-1.0, 1.0}) {
      // corners of the face in (u, v), counter-clockwise seen from outside
      std::array<Vec3, 4> c;
      const double uv[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (int k = 0; k < 4; ++k) {
        c[k][axis] = side * half;
        c[k][u] = uv[k][0] * half * side;
        c[k][v] = uv[k][1] * half;
      }
      triangles.push_back({c[0], c[1], c[2]});
      triangles.push_back({c[0], c[2], c[3]});
    }
  }
  return triangles;
}

/// The tetrahedron (0,0,0), (a,0,0), (0,a,0), (0,0,a), wound outward.
inline std::vector<StlTriangle> TetrahedronTriangles(double a) {
  const Vec3 o(0, 0, 0), x(a, 0, 0), y(0, a, 0), z(0, 0, a);
  return {{o, y, x}, {o, x, z}, {o, z, y}, {x, y, z}};
}

/// A binary STL; its 80-byte header starts with `header` (default "solid …").
inline void WriteBinaryStl(const std::filesystem::path& path, const std::vector<StlTriangle>& triangles,
                           const std::string& header = "solid written by a proxsim test, binary nonetheless") {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  char head[80] = {};
  std::memcpy(head, header.data(), std::min<std::size_t>(header.size(), sizeof head));
  out.write(head, sizeof head);
  const auto count = static_cast<std::uint32_t>(triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const StlTriangle& t : triangles) {
    const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
    float values[12] = {static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())};
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) values[3 + 3 * k + i] = static_cast<float>(t[k][i]);
    out.write(reinterpret_cast<const char*>(values), sizeof values);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

/// An ASCII STL.
inline void WriteAsciiStl(const std::filesystem::path& path, const std::vector<StlTriangle>& triangles) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  out << "solid test\n";
  for (const StlTriangle& t : triangles) {
    const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
    out << " facet normal " << n.x() << " " << n.y() << " " << n.z() << "\n  outer loop\n";
    for (const Vec3& p : t) out << "   vertex " << p.x() << " " << p.y() << " " << p.z() << "\n";
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid test\n";
}

/// Writes `text` to `path`, creating its folders.
inline void WriteText(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

}  // namespace proxsim::testing
