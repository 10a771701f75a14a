// The distance from a point to the world: boxes and analytic shapes by
// their closed forms (analytic_shapes.h), meshes by Embree's point query over
// the body's BVH, in a search radius that grows until a triangle lies within
// it; a body's meshes without some objects get a query scene of their own.
#include "raycast/ray_caster_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "raycast/analytic_shapes.h"
#include "scene/shape_inside.h"

namespace proxsim {

namespace {

using raycast_internal::Body;
using raycast_internal::GeomKind;
using raycast_internal::GeomRecord;

/// What the point-query callback reads and improves.
struct PointQueryState {
  const Body* body = nullptr;
  std::span<const std::int32_t> exclude_object_ids;
  Vec3 p_B = Vec3::Zero();
  double best_distance_m = std::numeric_limits<double>::infinity();
  std::int32_t best_object_id = -1;
};

bool IsExcluded(std::int32_t object_id, std::span<const std::int32_t> exclude_object_ids) {
  return std::find(exclude_object_ids.begin(), exclude_object_ids.end(), object_id) !=
         exclude_object_ids.end();
}

/// Called by rtcPointQuery for each primitive near the query point; measures
/// mesh triangles (boxes and analytic shapes are measured exactly elsewhere).
bool MeshPointQueryCallback(RTCPointQueryFunctionArguments* args) {
  auto& state = *static_cast<PointQueryState*>(args->userPtr);
  if (args->geomID >= state.body->geoms.size()) return false;
  const GeomRecord& geom = *state.body->geoms[args->geomID];
  if (geom.kind != GeomKind::kMesh || IsExcluded(geom.object_id, state.exclude_object_ids)) return false;

  // the triangle's corners from Embree's own vertex buffer, in B
  const std::uint32_t* tri = geom.indices + 3 * args->primID;
  auto corner = [&](int k) {
    const float* v = geom.vertices_B + 3 * tri[k];
    return Vec3(v[0], v[1], v[2]);
  };
  // a triangle whose bounding box lies beyond the best distance cannot win (cheap reject)
  const Vec3 a = corner(0), b = corner(1), c = corner(2);
  const Vec3 below = a.cwiseMin(b).cwiseMin(c) - state.p_B, above = state.p_B - a.cwiseMax(b).cwiseMax(c);
  if (below.cwiseMax(above).cwiseMax(0.0).squaredNorm() >= state.best_distance_m * state.best_distance_m) return false;
  const double distance_m = DistanceToTriangle(state.p_B, a, b, c);
  if (distance_m >= state.best_distance_m) return false;

  // shrink the search sphere (a hair above, so float rounding prunes nothing closer)
  state.best_distance_m = distance_m;
  state.best_object_id = geom.object_id;
  args->query->radius = static_cast<float>(distance_m * (1 + 1e-6) + 1e-6);
  return true;
}

// 0, 1, ..., n − 1 without storing them
struct AllIndices {
  std::size_t n = 0;
  struct Iterator {
    std::size_t i;
    std::size_t operator*() const { return i; }
    Iterator& operator++() { ++i; return *this; }
    bool operator!=(const Iterator& o) const { return i != o.i; }
  };
  Iterator begin() const { return {0}; }
  Iterator end() const { return {n}; }
};

}  // namespace

/// The scene a point query of `body` walks: the body's own when none of its
/// meshes is excluded, else (built once per exclusion set) a scene of the
/// meshes that are not, sharing the body's vertex and index buffers, so that
/// the walk never wades through excluded triangles (a robot's feet near a
/// finely meshed floor). Null when every mesh is excluded.
RTCScene RayCaster::Impl::MeshQueryScene(Body& body, std::span<const std::int32_t> exclude_object_ids) {
  std::lock_guard<std::mutex> lock(body.query_scenes_mutex);
  // the caller asks with the same list every time: answer it without a scan
  if (std::equal(exclude_object_ids.begin(), exclude_object_ids.end(), body.last_exclude.begin(),
                 body.last_exclude.end())) {
    return body.last_query_scene;
  }
  body.last_exclude.assign(exclude_object_ids.begin(), exclude_object_ids.end());
  std::vector<std::int32_t> key;
  for (const auto& geom : body.geoms) {
    if (geom->kind == GeomKind::kMesh && IsExcluded(geom->object_id, exclude_object_ids)) key.push_back(geom->object_id);
  }
  if (key.empty()) return body.last_query_scene = body.scene;
  std::sort(key.begin(), key.end());
  key.erase(std::unique(key.begin(), key.end()), key.end());
  if (auto found = body.query_scenes.find(key); found != body.query_scenes.end()) {
    return body.last_query_scene = found->second;
  }
  RTCScene scene = nullptr;
  for (std::size_t id = 0; id < body.geoms.size(); ++id) {
    const GeomRecord& geom = *body.geoms[id];
    if (geom.kind != GeomKind::kMesh || IsExcluded(geom.object_id, exclude_object_ids)) continue;
    if (!scene) {
      scene = rtcNewScene(device);
      rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
    }
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    std::size_t vertex_count = 0;
    for (std::size_t i = 0; i < 3 * geom.triangle_count; ++i) {
      vertex_count = std::max<std::size_t>(vertex_count, geom.indices[i] + 1);
    }
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, geom.vertices_B, 0,
                               3 * sizeof(float), vertex_count);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, geom.indices, 0,
                               3 * sizeof(std::uint32_t), geom.triangle_count);
    rtcCommitGeometry(geometry);
    // the same geometry ID as in the body's scene, so the callback finds its record
    rtcAttachGeometryByID(scene, geometry, static_cast<unsigned int>(id));
    rtcReleaseGeometry(geometry);
  }
  if (scene) rtcCommitScene(scene);
  body.query_scenes.emplace(std::move(key), scene);
  return body.last_query_scene = scene;
}

double RayCaster::DistanceToWorld(const Vec3& p_W, std::span<const std::int32_t> exclude_object_ids,
                                  double below_m) const {
  return NearestToWorld(p_W, exclude_object_ids, below_m, nullptr).distance_m;
}

double RayCaster::DistanceToWorld(const Vec3& p_W, std::span<const std::int32_t> exclude_object_ids, double below_m,
                                  const Nearby* nearby) const {
  return NearestToWorld(p_W, exclude_object_ids, below_m, nearby).distance_m;
}

RayCaster::NearestSurface RayCaster::NearestToWorld(const Vec3& p_W, std::span<const std::int32_t> exclude_object_ids,
                                                    double below_m) const {
  return NearestToWorld(p_W, exclude_object_ids, below_m, nullptr);
}

// A margin on the Nearby ball's radius, for the rounding of the points in it
// (the robot's samples moved into W), far above it.
constexpr double kNearbySlack_m = 1e-6;

void RayCaster::FindNearby(const Vec3& center_W, double radius_m, double reach_m, Nearby* nearby,
                           const Nearby* within) const {
  nearby->center_W = center_W;
  nearby->radius_m = radius_m;
  nearby->reach_m = reach_m;
  nearby->bodies.clear();
  nearby->geom_begin.clear();
  nearby->geoms.clear();
  // only a ball inside `within`'s, with no farther reach, can take its lists
  if (within != nullptr && !(reach_m <= within->reach_m &&
                             (center_W - within->center_W).norm() + radius_m <= within->radius_m)) {
    within = nullptr;
  }
  // a shape is left out when its bounding sphere or box lies beyond the ball
  // by more than the reach: from any point of the ball it is then farther
  // than any query's best (at most the reach), and the query's own tests skip it
  const double beyond_m = radius_m + kNearbySlack_m + reach_m + 1e-9;
  const auto add_body = [&](std::size_t w, const auto& geoms) {
    const Eigen::Vector4d& sphere_W = impl_->world_spheres_W[w];
    const double within_m = sphere_W.w() + beyond_m;
    if ((center_W - sphere_W.head<3>()).squaredNorm() > within_m * within_m) return;
    const Body& body = *impl_->bodies[impl_->world_bodies[w]];
    const Vec3 center_B = body.X_BW * center_W;
    nearby->bodies.push_back(static_cast<int>(w));
    nearby->geom_begin.push_back(static_cast<std::uint32_t>(nearby->geoms.size()));
    for (const std::size_t g : geoms) {
      const Eigen::Vector4d& sphere_B = body.closed_form_spheres_B[g];
      const double within_g_m = sphere_B.w() + beyond_m;
      if ((center_B - sphere_B.head<3>()).squaredNorm() > within_g_m * within_g_m) continue;
      if (body.closed_form_boxes_B[g].SquaredDistance(center_B) > beyond_m * beyond_m) continue;
      nearby->geoms.push_back(static_cast<std::uint32_t>(g));
    }
  };
  if (within != nullptr) {
    for (std::size_t k = 0; k < within->bodies.size(); ++k) {
      add_body(static_cast<std::size_t>(within->bodies[k]),
               std::span<const std::uint32_t>(within->geoms.data() + within->geom_begin[k],
                                              within->geom_begin[k + 1] - within->geom_begin[k]));
    }
  } else {
    for (std::size_t w = 0; w < impl_->world_bodies.size(); ++w)
      add_body(w, AllIndices{impl_->bodies[impl_->world_bodies[w]]->closed_form_geoms.size()});
  }
  nearby->geom_begin.push_back(static_cast<std::uint32_t>(nearby->geoms.size()));
}

namespace {

// The nearest surface of one world body to p_W (p_B in its frame), below
// the best so far in `nearest` (improved in place): its closed-form shapes
// `geoms` (indices into body.closed_form_geoms, ascending), then its meshes.
template <typename CasterImpl, typename GeomIndices>
void MeasureBody(CasterImpl& impl, const Body& body, const Vec3& p_B,
                 std::span<const std::int32_t> exclude_object_ids, const GeomIndices& geoms,
                 RayCaster::NearestSurface& nearest) {
  double& best_m = nearest.distance_m;
  // boxes and analytic shapes: exact closed forms in the shape frame
  for (const std::size_t g : geoms) {
    // beyond its bounding sphere by more than the best so far: it cannot
    // win (nor be a first touch: its distance is > best_m > 0), skip it
    // before the transform and the closed form (a margin for rounding)
    const Eigen::Vector4d& sphere_B = body.closed_form_spheres_B[g];
    const double reach_m = sphere_B.w() + best_m + 1e-9;
    if ((p_B - sphere_B.head<3>()).squaredNorm() > reach_m * reach_m) continue;
    // and the same by its box (a long wall's sphere reaches the whole room)
    if (body.closed_form_boxes_B[g].SquaredDistance(p_B) > (best_m + 1e-9) * (best_m + 1e-9)) continue;
    const GeomRecord& geom = *body.closed_form_geoms[g];
    if (IsExcluded(geom.object_id, exclude_object_ids)) continue;
    const Vec3 p_O = geom.X_OB * p_B;
    double distance_m = best_m;
    switch (geom.kind) {
      case GeomKind::kBox: distance_m = DistanceToBox(std::get<Box>(geom.shape), p_O); break;
      case GeomKind::kSphere: distance_m = DistanceToSphere(std::get<Sphere>(geom.shape), p_O); break;
      case GeomKind::kCylinder: distance_m = DistanceToCylinder(std::get<Cylinder>(geom.shape), p_O); break;
      case GeomKind::kPlane: distance_m = DistanceToPlane(p_O); break;
      case GeomKind::kMesh: break;
    }
    if (distance_m < best_m || (distance_m == 0 && nearest.object_id < 0)) {
      best_m = distance_m;
      nearest.object_id = geom.object_id;
      nearest.depth_m = distance_m > 0 ? 0.0 : std::max(DepthInside_m(geom.shape, p_O), 0.0);
    }
  }

  // meshes: Embree's point query walks the body's BVH within a search radius.
  // An unbounded query (a world of meshes only) would visit a large part of
  // the BVH before the radius shrinks, so the radius grows from 5 cm by ×2
  // until a triangle lies within it: the nearest one is then found exactly.
  // The growth stops at the best so far (the cap at first): a point far from
  // every mesh then costs a few small empty queries, not one that wades
  // through the triangles between it and the nearest.
  if (!body.has_mesh) return;
  RTCScene query_scene = impl.MeshQueryScene(const_cast<Body&>(body), exclude_object_ids);
  if (!query_scene) return;  // every mesh of the body is excluded
  PointQueryState state;
  state.body = &body;
  state.exclude_object_ids = exclude_object_ids;
  state.p_B = p_B;
  state.best_distance_m = best_m;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  constexpr double kFirstRadius_m = 0.05, kGrowth = 2.0, kLastFiniteRadius_m = 1e4;
  for (double radius_m = std::min(best_m, kFirstRadius_m);; radius_m *= kGrowth) {
    const bool last = radius_m >= best_m || radius_m > kLastFiniteRadius_m;
    RTCPointQuery query;
    query.x = static_cast<float>(p_B.x());
    query.y = static_cast<float>(p_B.y());
    query.z = static_cast<float>(p_B.z());
    query.time = 0.0f;
    const double bound_m = last ? best_m : radius_m;
    query.radius = std::isinf(bound_m) ? std::numeric_limits<float>::infinity()
                                       : static_cast<float>(bound_m * (1 + 1e-6) + 1e-6);
    rtcPointQuery(query_scene, &query, &context, &MeshPointQueryCallback, &state);
    // a triangle within the radius: nothing outside it can be nearer
    if (last || state.best_distance_m <= radius_m) break;
  }
  if (state.best_distance_m < best_m) {
    best_m = state.best_distance_m;
    nearest.object_id = state.best_object_id;
    nearest.depth_m = 0;
  }
}

}  // namespace

RayCaster::NearestSurface RayCaster::NearestToWorld(const Vec3& p_W, std::span<const std::int32_t> exclude_object_ids,
                                                    double below_m, const Nearby* nearby) const {
  NearestSurface nearest;
  nearest.distance_m = below_m;
  // no distance is below a cap <= 0 (and a point query needs a positive radius)
  if (!(below_m > 0)) return nearest;
  // the cap is the first best: nothing at or beyond it is measured
  const double& best_m = nearest.distance_m;
  // nothing of a body is nearer than its bounding sphere (a margin for rounding)
  const auto body_within_reach = [&](std::size_t w) {
    const Eigen::Vector4d& sphere_W = impl_->world_spheres_W[w];
    const double reach_m = sphere_W.w() + best_m + 1e-9;
    return (p_W - sphere_W.head<3>()).squaredNorm() <= reach_m * reach_m;
  };
  // the shapes near a ball holding p_W, when the cap is within their reach
  if (nearby != nullptr && below_m <= nearby->reach_m &&
      (p_W - nearby->center_W).norm() <= nearby->radius_m + kNearbySlack_m) {
    for (std::size_t k = 0; k < nearby->bodies.size(); ++k) {
      const auto w = static_cast<std::size_t>(nearby->bodies[k]);
      if (!body_within_reach(w)) continue;
      const Body& body = *impl_->bodies[impl_->world_bodies[w]];
      const std::span<const std::uint32_t> geoms(nearby->geoms.data() + nearby->geom_begin[k],
                                                 nearby->geom_begin[k + 1] - nearby->geom_begin[k]);
      MeasureBody(*impl_, body, body.X_BW * p_W, exclude_object_ids, geoms, nearest);
    }
    return nearest;
  }
  for (std::size_t w = 0; w < impl_->world_bodies.size(); ++w) {
    if (!body_within_reach(w)) continue;
    const Body& body = *impl_->bodies[impl_->world_bodies[w]];
    MeasureBody(*impl_, body, body.X_BW * p_W, exclude_object_ids, AllIndices{body.closed_form_geoms.size()}, nearest);
  }
  return nearest;
}

}  // namespace proxsim
