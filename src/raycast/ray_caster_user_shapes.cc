// Spheres, cylinders and planes as Embree user geometry, intersected exactly
// in their own frame (analytic_shapes.h) and never tessellated: each shape's
// bounds in its body frame, the intersect and occluded callbacks Embree calls
// on the rays that reach those bounds, and the shape's geometry in its body's
// scene.
#include "raycast/ray_caster_internal.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>

#include "raycast/analytic_shapes.h"

namespace proxsim {

namespace {

using raycast_internal::GeomKind;
using raycast_internal::GeomRecord;

/// Grows a box by a hair so that float rounding of its corners never culls a
/// hit on the surface it bounds.
RTCBounds PaddedBounds(const Vec3& lower, const Vec3& upper) {
  const double pad = 1e-4 + 1e-6 * std::max(lower.cwiseAbs().maxCoeff(), upper.cwiseAbs().maxCoeff());
  return RTCBounds{static_cast<float>(lower.x() - pad), static_cast<float>(lower.y() - pad),
                   static_cast<float>(lower.z() - pad), 0.0f,
                   static_cast<float>(upper.x() + pad), static_cast<float>(upper.y() + pad),
                   static_cast<float>(upper.z() + pad), 0.0f};
}

/// Axis-aligned bounds in B of a sphere, cylinder or (bounded) plane posed at X_BO.
RTCBounds UserShapeBounds(const Shape& shape, const Pose& X_BO) {
  const Vec3& p_BO = X_BO.translation();
  const Rotation R_BO = X_BO.linear();
  Vec3 half_extent = Vec3::Zero();
  if (const auto* sphere = std::get_if<Sphere>(&shape)) {
    half_extent.setConstant(sphere->radius_m);
  } else if (const auto* cylinder = std::get_if<Cylinder>(&shape)) {
    // per axis of B: the axis' projection of the half length plus the disc's reach
    const Vec3 axis_B = R_BO.col(2);
    for (int i = 0; i < 3; ++i) {
      const double a = std::abs(axis_B[i]);
      half_extent[i] = a * 0.5 * cylinder->length_m +
                       cylinder->radius_m * std::sqrt(std::max(0.0, 1.0 - a * a));
    }
  } else {
    // plane: the square of half side kPlaneHalfExtent_m in its z = 0
    half_extent = kPlaneHalfExtent_m * (R_BO.col(0).cwiseAbs() + R_BO.col(1).cwiseAbs());
  }
  return PaddedBounds(p_BO - half_extent, p_BO + half_extent);
}

// ---- user geometry callbacks (spheres, cylinders, planes) ----

void UserShapeBoundsCallback(const RTCBoundsFunctionArguments* args) {
  *args->bounds_o = static_cast<const GeomRecord*>(args->geometryUserPtr)->bounds_B;
}

/// The analytic first hit of a ray given in B, as (t, normal in B).
std::optional<ShapeHit> IntersectUserShape(const GeomRecord& geom, const Vec3& origin_B,
                                           const Vec3& direction_B, double t_min, double t_max) {
  const Vec3 origin_O = geom.X_OB * origin_B;
  const Vec3 direction_O = geom.X_OB.linear() * direction_B;
  std::optional<ShapeHit> hit;
  switch (geom.kind) {
    case GeomKind::kSphere:
      hit = IntersectSphere(std::get<Sphere>(geom.shape), origin_O, direction_O, t_min, t_max);
      break;
    case GeomKind::kCylinder:
      hit = IntersectCylinder(std::get<Cylinder>(geom.shape), origin_O, direction_O, t_min, t_max);
      break;
    case GeomKind::kPlane:
      hit = IntersectPlane(origin_O, direction_O, t_min, t_max);
      break;
    default:
      assert(false && "triangle geometry has no user callback");
  }
  if (hit) hit->normal_O = geom.X_BO.linear() * hit->normal_O;  // now in B
  return hit;
}

void UserShapeIntersectCallback(const RTCIntersectFunctionNArguments* args) {
  const auto& geom = *static_cast<const GeomRecord*>(args->geometryUserPtr);
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned int N = args->N;

    // the ray arrives in the body frame B (Embree applied the instance transform)
    const Vec3 origin_B(RTCRayN_org_x(rays, N, i), RTCRayN_org_y(rays, N, i), RTCRayN_org_z(rays, N, i));
    const Vec3 direction_B(RTCRayN_dir_x(rays, N, i), RTCRayN_dir_y(rays, N, i), RTCRayN_dir_z(rays, N, i));
    const auto hit = IntersectUserShape(geom, origin_B, direction_B, RTCRayN_tnear(rays, N, i),
                                        RTCRayN_tfar(rays, N, i));
    if (!hit) continue;

    // record it: tfar shrinks to the hit, so later candidates must be nearer
    RTCRayN_tfar(rays, N, i) = static_cast<float>(hit->t);
    RTCHitN_Ng_x(hits, N, i) = static_cast<float>(hit->normal_O.x());
    RTCHitN_Ng_y(hits, N, i) = static_cast<float>(hit->normal_O.y());
    RTCHitN_Ng_z(hits, N, i) = static_cast<float>(hit->normal_O.z());
    RTCHitN_u(hits, N, i) = 0.0f;
    RTCHitN_v(hits, N, i) = 0.0f;
    RTCHitN_primID(hits, N, i) = args->primID;
    RTCHitN_geomID(hits, N, i) = args->geomID;
    RTCHitN_instID(hits, N, i, 0) = args->context->instID[0];
  }
}

void UserShapeOccludedCallback(const RTCOccludedFunctionNArguments* args) {
  const auto& geom = *static_cast<const GeomRecord*>(args->geometryUserPtr);
  for (unsigned int i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned int N = args->N;
    RTCRayN* rays = args->ray;
    const Vec3 origin_B(RTCRayN_org_x(rays, N, i), RTCRayN_org_y(rays, N, i), RTCRayN_org_z(rays, N, i));
    const Vec3 direction_B(RTCRayN_dir_x(rays, N, i), RTCRayN_dir_y(rays, N, i), RTCRayN_dir_z(rays, N, i));
    // Embree's convention for "occluded": tfar = −inf
    if (IntersectUserShape(geom, origin_B, direction_B, RTCRayN_tnear(rays, N, i), RTCRayN_tfar(rays, N, i))) {
      RTCRayN_tfar(rays, N, i) = -std::numeric_limits<float>::infinity();
    }
  }
}

}  // namespace

void RayCaster::Impl::AttachUserShape(Body& body, std::unique_ptr<GeomRecord> record) {
  record->bounds_B = UserShapeBounds(record->shape, record->X_BO);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, 1);
  rtcSetGeometryUserData(geometry, record.get());
  rtcSetGeometryBoundsFunction(geometry, &UserShapeBoundsCallback, nullptr);
  rtcSetGeometryIntersectFunction(geometry, &UserShapeIntersectCallback);
  rtcSetGeometryOccludedFunction(geometry, &UserShapeOccludedCallback);
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(body.scene, geometry, static_cast<unsigned int>(body.geoms.size()));
  rtcReleaseGeometry(geometry);
  body.geoms.push_back(std::move(record));
}

}  // namespace proxsim
