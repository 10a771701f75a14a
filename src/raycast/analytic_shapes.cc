// Exact ray intersections and point distances for spheres, cylinders, planes,
// boxes and triangles, in the shape's frame O (see analytic_shapes.h).
//
// Quadratics are solved in the cancellation-free form (q = −(b ± √disc),
// roots q/a and c/q) so that a ray starting far from a small sphere keeps its
// precision. A ray parameter counts when it lies in [t_min, t_max].
#include "raycast/analytic_shapes.h"

#include <algorithm>
#include <cmath>

namespace proxsim {

namespace {

bool InRange(double t, double t_min, double t_max) { return t >= t_min && t <= t_max; }

/// Real roots of a·t² + 2·b·t + c = 0 (a > 0), smaller first; false when none.
bool SolveHalfBQuadratic(double a, double b, double c, double* t0, double* t1) {
  const double disc = b * b - a * c;
  if (disc < 0) return false;
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  if (q == 0) {
    // b = 0 and disc = 0: a double root at t = 0 (tangent from a point on the surface)
    *t0 = *t1 = 0;
    return true;
  }
  *t0 = q / a;
  *t1 = c / q;
  if (*t0 > *t1) std::swap(*t0, *t1);
  return true;
}

/// Distance from p to the segment [a, b].
double DistanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length_sq = ab.squaredNorm();
  const double s = length_sq > 0 ? std::clamp((p - a).dot(ab) / length_sq, 0.0, 1.0) : 0.0;
  return (p - (a + s * ab)).norm();
}

}  // namespace

std::optional<ShapeHit> IntersectSphere(const Sphere& sphere, const Vec3& origin_O,
                                        const Vec3& direction_O, double t_min, double t_max) {
  // |o + t·d|² = r²
  const double a = direction_O.squaredNorm();
  const double b = origin_O.dot(direction_O);
  const double c = origin_O.squaredNorm() - sphere.radius_m * sphere.radius_m;
  double t0 = 0, t1 = 0;
  if (a <= 0 || !SolveHalfBQuadratic(a, b, c, &t0, &t1)) return std::nullopt;

  // the entry point when it is in range, else the exit point (ray starts inside)
  for (double t : {t0, t1}) {
    if (!InRange(t, t_min, t_max)) continue;
    const Vec3 p_O = origin_O + t * direction_O;
    return ShapeHit{t, p_O / sphere.radius_m};
  }
  return std::nullopt;
}

std::optional<ShapeHit> IntersectCylinder(const Cylinder& cylinder, const Vec3& origin_O,
                                          const Vec3& direction_O, double t_min, double t_max) {
  const double r = cylinder.radius_m;
  const double half_length = 0.5 * cylinder.length_m;
  std::optional<ShapeHit> best;
  auto keep = [&](double t, const Vec3& normal_O) {
    if (InRange(t, t_min, t_max) && (!best || t < best->t)) best = ShapeHit{t, normal_O};
  };

  // side: (ox + t·dx)² + (oy + t·dy)² = r², with |z| within the caps
  const double a = direction_O.head<2>().squaredNorm();
  if (a > 0) {
    const double b = origin_O.head<2>().dot(direction_O.head<2>());
    const double c = origin_O.head<2>().squaredNorm() - r * r;
    double t0 = 0, t1 = 0;
    if (SolveHalfBQuadratic(a, b, c, &t0, &t1)) {
      for (double t : {t0, t1}) {
        const Vec3 p_O = origin_O + t * direction_O;
        if (std::abs(p_O.z()) <= half_length) keep(t, Vec3(p_O.x() / r, p_O.y() / r, 0));
      }
    }
  }

  // caps: z = ±length/2, within the radius
  if (direction_O.z() != 0) {
    for (double side : {-1.0, 1.0}) {
      const double t = (side * half_length - origin_O.z()) / direction_O.z();
      const Vec3 p_O = origin_O + t * direction_O;
      if (p_O.head<2>().squaredNorm() <= r * r) keep(t, Vec3(0, 0, side));
    }
  }
  return best;
}

std::optional<ShapeHit> IntersectPlane(const Vec3& origin_O, const Vec3& direction_O,
                                       double t_min, double t_max) {
  // a ray parallel to the plane never meets it (even one lying in it)
  if (direction_O.z() == 0) return std::nullopt;
  const double t = -origin_O.z() / direction_O.z();
  if (!InRange(t, t_min, t_max)) return std::nullopt;

  // the "infinite" plane stops at its documented bound
  const Vec3 p_O = origin_O + t * direction_O;
  if (std::abs(p_O.x()) > kPlaneHalfExtent_m || std::abs(p_O.y()) > kPlaneHalfExtent_m) {
    return std::nullopt;
  }
  return ShapeHit{t, Vec3::UnitZ()};
}

double DistanceToBox(const Box& box, const Vec3& p_O) {
  // per axis, how far outside the slab the point is (0 when within it)
  const Vec3 outside = (p_O.cwiseAbs() - 0.5 * box.size_m).cwiseMax(0.0);
  return outside.norm();
}

double DistanceToSphere(const Sphere& sphere, const Vec3& p_O) {
  return std::max(p_O.norm() - sphere.radius_m, 0.0);
}

double DistanceToCylinder(const Cylinder& cylinder, const Vec3& p_O) {
  // radial and axial excess; the exterior distance of a capped cylinder is their hypot
  const double radial = std::max(p_O.head<2>().norm() - cylinder.radius_m, 0.0);
  const double axial = std::max(std::abs(p_O.z()) - 0.5 * cylinder.length_m, 0.0);
  return std::hypot(radial, axial);
}

double DistanceToPlane(const Vec3& p_O) { return std::abs(p_O.z()); }

double DepthInside(const Shape& shape, const Vec3& p_O) {
  if (const auto* box = std::get_if<Box>(&shape)) {
    // inside every slab: the nearest face is the one with the least margin
    const Vec3 margin = 0.5 * box->size_m - p_O.cwiseAbs();
    return std::max(margin.minCoeff(), 0.0);
  }
  if (const auto* sphere = std::get_if<Sphere>(&shape)) return std::max(sphere->radius_m - p_O.norm(), 0.0);
  if (const auto* cylinder = std::get_if<Cylinder>(&shape)) {
    const double radial = cylinder->radius_m - p_O.head<2>().norm();
    const double axial = 0.5 * cylinder->length_m - std::abs(p_O.z());
    return std::max(std::min(radial, axial), 0.0);
  }
  if (std::holds_alternative<Plane>(shape)) return std::max(-p_O.z(), 0.0);
  return 0.0;
}

double DistanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double n_sq = n.squaredNorm();

  // the foot of the perpendicular lies inside when p is on the inner side of all three edges
  if (n_sq > 0) {
    const bool inside = (b - a).cross(p - a).dot(n) >= 0 && (c - b).cross(p - b).dot(n) >= 0 &&
                        (a - c).cross(p - c).dot(n) >= 0;
    if (inside) return std::abs((p - a).dot(n)) / std::sqrt(n_sq);
  }

  // otherwise (or for a degenerate triangle) the nearest point is on an edge
  return std::min({DistanceToSegment(p, a, b), DistanceToSegment(p, b, c),
                   DistanceToSegment(p, c, a)});
}

}  // namespace proxsim
