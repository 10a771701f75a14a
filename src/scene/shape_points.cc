#include "scene/shape_points.h"

#include <cmath>

namespace proxsim {

std::vector<Vec3> ShapeOutlinePoints_O(const Shape& shape) {
  std::vector<Vec3> points;
  if (const auto* box = std::get_if<Box>(&shape)) {
    // the eight corners
    for (int corner = 0; corner < 8; ++corner) {
      points.emplace_back((corner & 1 ? 0.5 : -0.5) * box->size_m.x(), (corner & 2 ? 0.5 : -0.5) * box->size_m.y(),
                          (corner & 4 ? 0.5 : -0.5) * box->size_m.z());
    }
  } else if (const auto* cylinder = std::get_if<Cylinder>(&shape)) {
    // both rims, one point per degree: a cylinder's extremes lie on them
    for (const double z : {-0.5 * cylinder->length_m, 0.5 * cylinder->length_m}) {
      for (int degree = 0; degree < 360; ++degree) {
        const double angle = DegToRad(degree);
        points.emplace_back(cylinder->radius_m * std::cos(angle), cylinder->radius_m * std::sin(angle), z);
      }
    }
  } else if (const auto* sphere = std::get_if<Sphere>(&shape)) {
    // a Fibonacci lattice, with the poles and the equator's four axis points
    // exact (a sphere's lowest point is the usual question)
    constexpr int kLattice = 4000;
    const double golden_angle = kPi * (3 - std::sqrt(5.0));
    for (int i = 0; i < kLattice; ++i) {
      const double z = 1 - 2 * (i + 0.5) / kLattice;
      const double r = std::sqrt(1 - z * z);
      points.push_back(sphere->radius_m * Vec3(r * std::cos(golden_angle * i), r * std::sin(golden_angle * i), z));
    }
    for (int axis = 0; axis < 3; ++axis) {
      points.push_back(sphere->radius_m * Vec3::Unit(axis));
      points.push_back(-sphere->radius_m * Vec3::Unit(axis));
    }
  } else if (const auto* mesh = std::get_if<Mesh>(&shape)) {
    points.reserve(mesh->data->vertices_O.size());
    for (const Vec3f& v : mesh->data->vertices_O) points.push_back(v.cast<double>());
  }
  return points;
}

}  // namespace proxsim
