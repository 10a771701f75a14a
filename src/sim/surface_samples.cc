#include "sim/surface_samples.h"

#include <cmath>

#include "scene/mesh_samples.h"

namespace proxsim {

namespace {

// n + 1 evenly spaced values from -half to +half, at most spacing apart
std::vector<double> Ticks(double half_m, double spacing_m) {
  const int n = std::max(1, static_cast<int>(std::ceil(2 * half_m / spacing_m)));
  std::vector<double> ticks(n + 1);
  for (int i = 0; i <= n; ++i) ticks[i] = -half_m + 2 * half_m * i / n;
  return ticks;
}

void BoxSamples(const Box& box, double spacing_m, std::vector<Vec3>& out) {
  const Vec3 half = box.size_m / 2;
  // each pair of opposite faces: a grid over the two other axes
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (double a : Ticks(half[u], spacing_m)) {
      for (double b : Ticks(half[v], spacing_m)) {
        for (double side : {-1.0, 1.0}) {
          Vec3 p;
          p[axis] = side * half[axis];
          p[u] = a;
          p[v] = b;
          out.push_back(p);
        }
      }
    }
  }
}

void CylinderSamples(const Cylinder& cylinder, double spacing_m, std::vector<Vec3>& out) {
  const int around = std::max(8, static_cast<int>(std::ceil(2 * kPi * cylinder.radius_m / spacing_m)));
  // the side: rings along the axis
  for (double z : Ticks(cylinder.length_m / 2, spacing_m)) {
    for (int k = 0; k < around; ++k) {
      const double angle = 2 * kPi * k / around;
      out.emplace_back(cylinder.radius_m * std::cos(angle), cylinder.radius_m * std::sin(angle), z);
    }
  }
  // the caps: concentric rings
  const int rings = std::max(1, static_cast<int>(std::ceil(cylinder.radius_m / spacing_m)));
  for (double side : {-1.0, 1.0}) {
    out.emplace_back(0, 0, side * cylinder.length_m / 2);
    for (int r = 1; r < rings; ++r) {
      const double radius = cylinder.radius_m * r / rings;
      const int n = std::max(6, static_cast<int>(std::ceil(2 * kPi * radius / spacing_m)));
      for (int k = 0; k < n; ++k) {
        const double angle = 2 * kPi * k / n;
        out.emplace_back(radius * std::cos(angle), radius * std::sin(angle), side * cylinder.length_m / 2);
      }
    }
  }
}

void SphereSamples(const Sphere& sphere, double spacing_m, std::vector<Vec3>& out) {
  // a Fibonacci lattice: near-uniform, one point per spacing² of area
  const double area = 4 * kPi * sphere.radius_m * sphere.radius_m;
  const int n = std::max(12, static_cast<int>(std::ceil(area / (spacing_m * spacing_m))));
  const double golden_angle = kPi * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - 2 * (i + 0.5) / n;
    const double r = std::sqrt(1 - z * z);
    out.emplace_back(sphere.radius_m * r * std::cos(golden_angle * i), sphere.radius_m * r * std::sin(golden_angle * i),
                     sphere.radius_m * z);
  }
}

}  // namespace

std::vector<Vec3> SurfaceSamples_O(const Shape& shape, double spacing_m) {
  std::vector<Vec3> points;
  if (const auto* box = std::get_if<Box>(&shape)) BoxSamples(*box, spacing_m, points);
  if (const auto* cylinder = std::get_if<Cylinder>(&shape)) CylinderSamples(*cylinder, spacing_m, points);
  if (const auto* sphere = std::get_if<Sphere>(&shape)) SphereSamples(*sphere, spacing_m, points);
  if (const auto* mesh = std::get_if<Mesh>(&shape)) points = MeshSurfaceSamples_O(*mesh->data, spacing_m);
  return points;
}

}  // namespace proxsim
