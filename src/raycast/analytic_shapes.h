// Exact geometry of the curved and unbounded shapes, in the shape's own frame O.
//
// The ray caster hands spheres, cylinders and planes to Embree as user
// geometry (never tessellated); these functions are the intersection and
// distance routines it calls back. They also give the exact point-to-shape
// distances used for the robot's clearance. Everything is in double precision
// and knows nothing of Embree, so it can be read and tested on its own.
//
// Frame: O, the shape's frame (a sphere centred on its origin, a cylinder with
// its axis along z and caps at z = ±length/2, a plane at z = 0, a box spanning
// ±size/2).
#pragma once

#include <optional>

#include "core/geometry.h"
#include "scene/shape.h"

namespace proxsim {

/// Half-extent in metres, along x and y of its frame, of the square that stands
/// for an "infinite" plane in the ray caster: a ray meets a plane only where
/// |x_O| and |y_O| are both within it. 100 km is far beyond any sensor range.
constexpr double kPlaneHalfExtent_m = 1e5;

/// A ray parameter and the unit outward normal at that point, both in O.
struct ShapeHit {
  double t = 0;  ///< ray parameter: p_O = origin_O + t·direction_O
  Vec3 normal_O = Vec3::Zero();
};

/// First hit of the ray origin_O + t·direction_O with t in [t_min, t_max] on
/// the sphere's surface (from outside or inside); nullopt when none.
std::optional<ShapeHit> IntersectSphere(const Sphere& sphere, const Vec3& origin_O,
                                        const Vec3& direction_O, double t_min, double t_max);

/// Same for a capped cylinder: its side or either flat cap.
std::optional<ShapeHit> IntersectCylinder(const Cylinder& cylinder, const Vec3& origin_O,
                                          const Vec3& direction_O, double t_min, double t_max);

/// Same for the z = 0 plane, bounded to ±kPlaneHalfExtent_m. Two-sided; the
/// normal is always +z (the plane's own normal, whichever side the ray comes from).
std::optional<ShapeHit> IntersectPlane(const Vec3& origin_O, const Vec3& direction_O,
                                       double t_min, double t_max);

/// Distance in metres from p_O to a solid box; 0 inside it.
double DistanceToBox(const Box& box, const Vec3& p_O);

/// Distance from p_O to a solid sphere; 0 inside it.
double DistanceToSphere(const Sphere& sphere, const Vec3& p_O);

/// Distance from p_O to a solid capped cylinder; 0 inside it.
double DistanceToCylinder(const Cylinder& cylinder, const Vec3& p_O);

/// Distance from p_O to the unbounded z = 0 plane.
double DistanceToPlane(const Vec3& p_O);

/// How deep p_O lies inside a solid box, sphere or capped cylinder: the
/// distance from p_O to its surface when inside, 0 outside or on it. For a
/// plane, how far below z = 0 (its solid side taken as z < 0, as a floor's).
/// 0 for a mesh (no inside is known for a triangle soup).
double DepthInside(const Shape& shape, const Vec3& p_O);

/// Distance from p to the triangle (a, b, c), edges and corners included.
double DistanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace proxsim
