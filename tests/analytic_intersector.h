// A tiny, slow, obviously-correct ray intersector for the tests: a reference
// that the Embree-backed RayCaster must agree with. It knows only boxes
// (slab method), spheres, capped cylinders and infinite planes, each posed in
// the world, and loops over all of them for every ray. It shares no code with
// src/raycast on purpose, so that a mistake there cannot hide here.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <variant>
#include <vector>

#include "core/geometry.h"
#include "scene/shape.h"

namespace proxsim::testing {

/// One shape posed in the world.
struct ReferenceShape {
  Shape shape;  ///< Box, Sphere, Cylinder or Plane (meshes are not supported)
  Pose X_WO = Pose::Identity();
  std::int32_t object_id = 0;
};

/// The nearest hit of a ray, or object_id −1.
struct ReferenceHit {
  double distance_m = std::numeric_limits<double>::infinity();
  Vec3 normal_W = Vec3::Zero();
  std::int32_t object_id = -1;
};

namespace detail {

/// Smallest root of the quadratic a·t² + b·t + c in [lo, hi] that passes `accept`.
template <typename Accept>
double SmallestRoot(double a, double b, double c, double lo, double hi, Accept accept) {
  const double disc = b * b - 4 * a * c;
  if (a == 0 || disc < 0) return -1;
  const double root = std::sqrt(disc);
  for (double t : {(-b - root) / (2 * a), (-b + root) / (2 * a)}) {
    if (t >= lo && t <= hi && accept(t)) return t;
  }
  return -1;
}

/// t and outward normal in O of the first hit with the shape, or t < 0.
inline double HitInShapeFrame(const Shape& shape, const Vec3& o, const Vec3& d, double max_t,
                              Vec3* n) {
  if (const auto* box = std::get_if<Box>(&shape)) {
    // slab method: the latest entry over the three slabs, unless past the first exit
    const Vec3 half = 0.5 * box->size_m;
    double t_enter = -std::numeric_limits<double>::infinity();
    double t_exit = std::numeric_limits<double>::infinity();
    int enter_axis = -1;
    for (int i = 0; i < 3; ++i) {
      if (d[i] == 0) {
        if (std::abs(o[i]) > half[i]) return -1;
        continue;
      }
      double t0 = (-half[i] - o[i]) / d[i];
      double t1 = (half[i] - o[i]) / d[i];
      if (t0 > t1) std::swap(t0, t1);
      if (t0 > t_enter) {
        t_enter = t0;
        enter_axis = i;
      }
      t_exit = std::min(t_exit, t1);
    }
    if (t_enter > t_exit || enter_axis < 0) return -1;
    if (t_enter >= 0 && t_enter <= max_t) {
      *n = Vec3::Zero();
      (*n)[enter_axis] = d[enter_axis] > 0 ? -1 : 1;
      return t_enter;
    }
    return -1;  // the tests never start a ray inside a box
  }
  if (const auto* sphere = std::get_if<Sphere>(&shape)) {
    const double t = SmallestRoot(d.dot(d), 2 * o.dot(d), o.dot(o) - sphere->radius_m * sphere->radius_m,
                                  0, max_t, [](double) { return true; });
    if (t >= 0) *n = (o + t * d).normalized();
    return t;
  }
  if (const auto* cylinder = std::get_if<Cylinder>(&shape)) {
    const double r = cylinder->radius_m, h = cylinder->length_m / 2;
    double best = -1;
    // side
    const double a = d.x() * d.x() + d.y() * d.y();
    const double t_side = SmallestRoot(a, 2 * (o.x() * d.x() + o.y() * d.y()),
                                       o.x() * o.x() + o.y() * o.y() - r * r, 0, max_t,
                                       [&](double t) { return std::abs(o.z() + t * d.z()) <= h; });
    if (t_side >= 0) {
      best = t_side;
      const Vec3 p = o + t_side * d;
      *n = Vec3(p.x(), p.y(), 0).normalized();
    }
    // caps
    for (double z : {-h, h}) {
      if (d.z() == 0) break;
      const double t = (z - o.z()) / d.z();
      const Vec3 p = o + t * d;
      if (t >= 0 && t <= max_t && p.x() * p.x() + p.y() * p.y() <= r * r && (best < 0 || t < best)) {
        best = t;
        *n = Vec3(0, 0, z > 0 ? 1 : -1);
      }
    }
    return best;
  }
  // plane z = 0, two-sided, normal +z
  if (d.z() == 0) return -1;
  const double t = -o.z() / d.z();
  if (t < 0 || t > max_t) return -1;
  *n = Vec3::UnitZ();
  return t;
}

}  // namespace detail

/// The nearest hit of the ray origin_W + t·direction_W, t in [0, max_range_m].
inline ReferenceHit ReferenceCast(const std::vector<ReferenceShape>& shapes, const Vec3& origin_W,
                                  const Vec3& direction_W, double max_range_m) {
  ReferenceHit best;
  for (const ReferenceShape& s : shapes) {
    const Pose X_OW = s.X_WO.inverse();
    Vec3 normal_O;
    const double t = detail::HitInShapeFrame(s.shape, X_OW * origin_W, X_OW.linear() * direction_W,
                                             max_range_m, &normal_O);
    if (t >= 0 && t < best.distance_m) {
      best.distance_m = t;
      best.normal_W = s.X_WO.linear() * normal_O;
      best.object_id = s.object_id;
    }
  }
  return best;
}

}  // namespace proxsim::testing
