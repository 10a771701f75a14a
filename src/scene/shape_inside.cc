#include "scene/shape_inside.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace proxsim {

namespace {

Vec3 Vertex(const TriangleMesh& mesh, std::uint32_t i) { return mesh.vertices_O[i].cast<double>(); }

// Closest point to p on triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 ClosestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// Where the line p + t·dir crosses triangle abc, t of either sign (Möller–Trumbore).
std::optional<double> LineCrossing(const Vec3& p, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 h = dir.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) < 1e-18) return std::nullopt;  // parallel, or a degenerate triangle
  const double inv = 1.0 / det;
  const Vec3 s = p - a;
  const double u = inv * s.dot(h);
  if (u < 0 || u > 1) return std::nullopt;
  const Vec3 q = s.cross(e1);
  const double v = inv * dir.dot(q);
  if (v < 0 || u + v > 1) return std::nullopt;
  return inv * e2.dot(q);
}

// Does the ray p + t·dir (t > 0) cross triangle abc?
bool RayCrosses(const Vec3& p, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto t = LineCrossing(p, dir, a, b, c);
  return t && *t > 0;
}

// The larger root of a·t² + b·t + c = 0, nullopt when there is none.
std::optional<double> LargerRoot(double a, double b, double c) {
  const double disc = b * b - 4 * a * c;
  if (a == 0 || disc < 0) return std::nullopt;
  return (-b + std::sqrt(disc)) / (2 * a);
}

double MeshDepthInside_m(const TriangleMesh& mesh, const Vec3& p_O) {
  // outside the bounding box: outside, by at least the distance to the box
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3f& v : mesh.vertices_O) {
    lo = lo.cwiseMin(v.cast<double>());
    hi = hi.cwiseMax(v.cast<double>());
  }
  const Vec3 outside = (lo - p_O).cwiseMax(p_O - hi).cwiseMax(0.0);
  if (outside.norm() > 0) return -outside.norm();
  // the distance to the surface
  double d2_min = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.triangles) {
    const Vec3 q = ClosestOnTriangle(p_O, Vertex(mesh, t[0]), Vertex(mesh, t[1]), Vertex(mesh, t[2]));
    d2_min = std::min(d2_min, (q - p_O).squaredNorm());
  }
  // enclosed when most of three rays (irrational-ish directions, so that none
  // runs along an axis-aligned edge of a typical mesh) cross the surface an odd number of times
  const Vec3 directions[3] = {Vec3(0.5773, 0.5774, 0.5775).normalized(), Vec3(-0.2673, 0.8018, -0.5345).normalized(),
                              Vec3(0.8729, -0.2182, 0.4364).normalized()};
  int odd = 0;
  for (const Vec3& dir : directions) {
    int crossings = 0;
    for (const auto& t : mesh.triangles)
      crossings += RayCrosses(p_O, dir, Vertex(mesh, t[0]), Vertex(mesh, t[1]), Vertex(mesh, t[2]));
    odd += crossings % 2;
  }
  const double d_m = std::sqrt(d2_min);
  return odd >= 2 ? d_m : -d_m;
}

}  // namespace

std::optional<double> FarthestAlongLine_m(const Shape& shape, const Vec3& p, const Vec3& d) {
  if (const auto* box = std::get_if<Box>(&shape)) {
    // slabs: the line is inside every slab for t in [t_in, t_out]
    const Vec3 half = box->size_m / 2;
    double t_in = -std::numeric_limits<double>::infinity(), t_out = -t_in;
    for (int i = 0; i < 3; ++i) {
      if (d[i] == 0) {
        if (std::abs(p[i]) > half[i]) return std::nullopt;
        continue;
      }
      const double t1 = (-half[i] - p[i]) / d[i], t2 = (half[i] - p[i]) / d[i];
      t_in = std::max(t_in, std::min(t1, t2));
      t_out = std::min(t_out, std::max(t1, t2));
    }
    if (t_in > t_out) return std::nullopt;
    return t_out;
  }
  if (const auto* sphere = std::get_if<Sphere>(&shape)) {
    return LargerRoot(d.squaredNorm(), 2 * p.dot(d), p.squaredNorm() - sphere->radius_m * sphere->radius_m);
  }
  if (const auto* cylinder = std::get_if<Cylinder>(&shape)) {
    // the infinite cylinder's interval, cut by the caps' slab
    const double half = cylinder->length_m / 2;
    double t_in = -std::numeric_limits<double>::infinity(), t_out = -t_in;
    const double a = d.head<2>().squaredNorm();
    if (a == 0) {
      if (p.head<2>().norm() > cylinder->radius_m) return std::nullopt;
    } else {
      const double b = 2 * p.head<2>().dot(d.head<2>());
      const double c = p.head<2>().squaredNorm() - cylinder->radius_m * cylinder->radius_m;
      const double disc = b * b - 4 * a * c;
      if (disc < 0) return std::nullopt;
      t_in = (-b - std::sqrt(disc)) / (2 * a);
      t_out = (-b + std::sqrt(disc)) / (2 * a);
    }
    if (d.z() == 0) {
      if (std::abs(p.z()) > half) return std::nullopt;
    } else {
      const double t1 = (-half - p.z()) / d.z(), t2 = (half - p.z()) / d.z();
      t_in = std::max(t_in, std::min(t1, t2));
      t_out = std::min(t_out, std::max(t1, t2));
    }
    if (t_in > t_out) return std::nullopt;
    return t_out;
  }
  if (std::holds_alternative<Plane>(shape)) {
    if (d.z() == 0) return std::nullopt;
    return -p.z() / d.z();
  }
  const TriangleMesh& mesh = *std::get<Mesh>(shape).data;
  std::optional<double> farthest;
  for (const auto& t : mesh.triangles) {
    const auto crossing = LineCrossing(p, d, Vertex(mesh, t[0]), Vertex(mesh, t[1]), Vertex(mesh, t[2]));
    if (crossing && (!farthest || *crossing > *farthest)) farthest = crossing;
  }
  return farthest;
}

double DepthInside_m(const Shape& shape, const Vec3& p_O) {
  if (const auto* box = std::get_if<Box>(&shape)) {
    const Vec3 excess = p_O.cwiseAbs() - box->size_m / 2;  // > 0 on the axes where p_O is beyond a face
    if ((excess.array() <= 0).all()) return -excess.maxCoeff();
    return -excess.cwiseMax(0.0).norm();
  }
  if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere->radius_m - p_O.norm();
  if (const auto* cylinder = std::get_if<Cylinder>(&shape)) {
    const double radial_m = p_O.head<2>().norm() - cylinder->radius_m;
    const double axial_m = std::abs(p_O.z()) - cylinder->length_m / 2;
    if (radial_m <= 0 && axial_m <= 0) return -std::max(radial_m, axial_m);
    return -Vec2(std::max(radial_m, 0.0), std::max(axial_m, 0.0)).norm();
  }
  if (std::holds_alternative<Plane>(shape)) return -std::abs(p_O.z());
  return MeshDepthInside_m(*std::get<Mesh>(shape).data, p_O);
}

}  // namespace proxsim
