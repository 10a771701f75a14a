#include "scene/mesh_samples.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

namespace proxsim {

std::vector<Vec3> MeshSurfaceSamples_O(const TriangleMesh& mesh, double spacing_m) {
  std::vector<Vec3> points;
  std::unordered_set<std::uint64_t> taken;  // cubes that hold a sample
  const double lattice_m = 0.5 * spacing_m;
  // a cube's key: its three integer coordinates, 21 bits each
  const auto cube_key = [&](const Vec3& p) {
    constexpr std::int64_t kOffset = std::int64_t{1} << 20, kMask = (std::int64_t{1} << 21) - 1;
    std::uint64_t key = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const auto cell = static_cast<std::int64_t>(std::floor(p[axis] / spacing_m)) + kOffset;
      key = (key << 21) | static_cast<std::uint64_t>(cell & kMask);
    }
    return key;
  };
  for (const auto& triangle : mesh.triangles) {
    const Vec3 a = mesh.vertices_O[triangle[0]].cast<double>();
    const Vec3 b = mesh.vertices_O[triangle[1]].cast<double>();
    const Vec3 c = mesh.vertices_O[triangle[2]].cast<double>();
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    // a barycentric lattice with n divisions per edge (corners at n = 1)
    const int n = std::clamp(static_cast<int>(std::ceil(longest / lattice_m)), 1, 4096);
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const Vec3 p = a + (b - a) * (static_cast<double>(i) / n) + (c - a) * (static_cast<double>(j) / n);
        if (taken.insert(cube_key(p)).second) points.push_back(p);
      }
    }
  }
  return points;
}

}  // namespace proxsim
