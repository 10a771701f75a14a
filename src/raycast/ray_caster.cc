// The Embree 3 adapter: the only file of proxsim that includes Embree.
//
// Layout of the acceleration structures:
//   - every body B is a child RTCScene holding its shapes in the body frame:
//     boxes as 12 triangles, meshes as their triangles (both moved by X_BO),
//     spheres, cylinders and planes as user geometry intersected exactly
//     (analytic_shapes.h), never tessellated;
//   - two top-level scenes instance the bodies (one level of instancing):
//     `world` the kWorld bodies and `robot` the kRobot ones. The instance ID
//     of a body is its index, so a hit maps straight back to (body, geometry)
//     → object_id. A ray is cast into the world first — straight into the
//     world body's own scene when there is one world body at the identity
//     pose (the usual case), so the big static BVH is walked without an
//     instance level — then, if it sees the robot, into `robot` up to the
//     world hit: the nearer hit wins.
// Moving a body only rewrites its instance transforms; Commit() then rebuilds
// the top-level scene that changed (the robot's, each sample), whose only
// primitives are the instances. The child scenes, and so the static world's
// BVH, are built once in AddBody.
//
// Every scene is RTC_SCENE_FLAG_ROBUST: Embree then uses its watertight
// triangle test, so a ray through a shared edge or vertex cannot slip between
// triangles. Child scenes are built once with high (world) or medium (robot)
// quality; the small top-level scenes are rebuilt at medium quality.
//
// Normals: Embree reports Ng in the instanced body's frame B and unnormalised;
// we normalise it and rotate it by R_WB. Triangle normals follow the right-hand
// rule of the vertex order (counter-clockwise seen from the front), which for
// boxes is outward.
//
// Errors: the device error callback records Embree's message; the public
// calls check it and throw std::runtime_error, so no error passes silently
// (and no exception is thrown through Embree's C frames).
#include "raycast/ray_caster.h"

#include <embree3/rtcore.h>
#include <oneapi/tbb/task_arena.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "core/parallel.h"
#include "raycast/analytic_shapes.h"

namespace proxsim {

namespace {

/// Batches at least this large are spread over the threads.
constexpr std::size_t kParallelBatchRays = 512;

enum class GeomKind { kBox, kMesh, kSphere, kCylinder, kPlane };

/// One Embree geometry of a body: what the callbacks and hit mapping need.
struct GeomRecord {
  GeomKind kind = GeomKind::kBox;
  std::int32_t object_id = 0;
  Shape shape;  ///< boxes and analytic shapes only (a mesh's triangles live in Embree)
  Pose X_BO = Pose::Identity();
  Pose X_OB = Pose::Identity();
  RTCBounds bounds_B{};  ///< user geometry only: conservative box in B
  // triangle geometry only: Embree's own buffers, in B (read by point queries)
  const float* vertices_B = nullptr;
  const std::uint32_t* indices = nullptr;
  std::size_t triangle_count = 0;
};

struct Body {
  BodyKind kind = BodyKind::kWorld;
  RTCScene scene = nullptr;
  std::vector<std::unique_ptr<GeomRecord>> geoms;  ///< index = geomID in `scene`; stable addresses
  Pose X_WB = Pose::Identity();
  Eigen::Matrix3f R_WB = Eigen::Matrix3f::Identity();
  RTCGeometry instance_robot = nullptr;  ///< null for world bodies
  RTCGeometry instance_world = nullptr;  ///< null for robot bodies
  bool has_mesh = false;
  std::vector<const GeomRecord*> closed_form_geoms;  ///< every geom but meshes, for DistanceToWorld
  // point-query scenes of this body's meshes without some objects (the
  // ground, say), keyed by the sorted excluded object ids; built on first use
  std::mutex query_scenes_mutex;
  std::map<std::vector<std::int32_t>, RTCScene> query_scenes;
  std::vector<std::int32_t> last_exclude{-1};  // the last list asked for (never a valid list: ids >= 0)
  RTCScene last_query_scene = nullptr;          // and its answer
};

/// Sets flush-to-zero and denormals-are-zero (Embree's recommendation) for
/// the life of the guard, then puts the thread's MXCSR back as it was.
class DenormalModeGuard {
 public:
  DenormalModeGuard() : saved_csr_(_mm_getcsr()) {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
  }
  ~DenormalModeGuard() { _mm_setcsr(saved_csr_); }
  DenormalModeGuard(const DenormalModeGuard&) = delete;
  DenormalModeGuard& operator=(const DenormalModeGuard&) = delete;

 private:
  unsigned int saved_csr_;
};

const char* ErrorCodeName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE: return "none";
    case RTC_ERROR_UNKNOWN: return "unknown";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
  }
  return "unrecognised";
}

/// Embree's 3×4 column-major matrix of a pose (rotation columns, then translation).
void ToColumnMajor3x4(const Pose& X, float out[12]) {
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 3; ++row) out[3 * col + row] = static_cast<float>(X.matrix()(row, col));
  }
}

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

// ---- point query (distance to meshes) ----

/// What the point-query callback reads and improves.
struct PointQueryState {
  const Body* body = nullptr;
  std::span<const std::int32_t> exclude_object_ids;
  Vec3 p_B = Vec3::Zero();
  double best_distance_m = std::numeric_limits<double>::infinity();
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
  args->query->radius = static_cast<float>(distance_m * (1 + 1e-6) + 1e-6);
  return true;
}

}  // namespace

struct RayCaster::Impl {
  RTCDevice device = nullptr;
  RTCScene scene_world = nullptr;
  RTCScene scene_robot = nullptr;
  std::vector<std::unique_ptr<Body>> bodies;  ///< index = instance ID in the top-level scenes
  // the world body cast without its instance (see the top of the file), or null
  RTCScene world_direct = nullptr;
  int world_direct_body = -1;
  bool has_robot = false;
  std::size_t triangle_count = 0;
  std::unique_ptr<ParallelRunner> runner = std::make_unique<ParallelRunner>(1);  ///< for large batches
  bool committed = true;
  // which top-level scene has a change to commit: moving a robot body leaves
  // the world's as it was, so a step rebuilds only `robot`
  bool robot_dirty = true;
  bool world_dirty = true;
  tbb::task_arena commit_arena{1};  ///< one slot: top-level commits run on the caller only

  // first error reported by Embree since the last check
  std::mutex error_mutex;
  std::string error_message;
  std::atomic<bool> has_error{false};

  static void OnDeviceError(void* user_ptr, RTCError code, const char* message) {
    auto& impl = *static_cast<Impl*>(user_ptr);
    std::lock_guard<std::mutex> lock(impl.error_mutex);
    if (impl.error_message.empty()) {
      impl.error_message = std::string("Embree error (") + ErrorCodeName(code) + "): " +
                           (message ? message : "(no message)");
    }
    impl.has_error.store(true);
  }

  /// Throws std::runtime_error if Embree reported an error since the last check.
  void ThrowIfDeviceError(const char* during) {
    if (!has_error.load()) return;
    std::string message;
    {
      std::lock_guard<std::mutex> lock(error_mutex);
      message = std::move(error_message);
      error_message.clear();
      has_error.store(false);
    }
    throw std::runtime_error(std::string("RayCaster::") + during + ": " + message);
  }

  RTCScene NewScene(RTCBuildQuality quality) {
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, quality);
    return scene;
  }

  void AttachTriangles(Body& body, std::unique_ptr<GeomRecord> record, const std::vector<Vec3>& vertices_B,
                       const std::vector<std::array<std::uint32_t, 3>>& triangles);
  void AttachUserShape(Body& body, std::unique_ptr<GeomRecord> record);
  RTCGeometry NewInstance(RTCScene top, const Body& body, unsigned int inst_id);
  RTCScene MeshQueryScene(Body& body, std::span<const std::int32_t> exclude_object_ids);
};

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

void RayCaster::Impl::AttachTriangles(Body& body, std::unique_ptr<GeomRecord> record,
                                      const std::vector<Vec3>& vertices_B,
                                      const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  if (triangles.empty()) return;  // nothing to hit (Embree refuses empty buffers)
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices_B.size()));
  auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangles.size()));
  ThrowIfDeviceError("AddBody");
  for (std::size_t i = 0; i < vertices_B.size(); ++i) {
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = static_cast<float>(vertices_B[i][k]);
  }
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      assert(triangles[i][k] < vertices_B.size() && "mesh index out of range");
      indices[3 * i + k] = triangles[i][k];
    }
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(body.scene, geometry, static_cast<unsigned int>(body.geoms.size()));
  rtcReleaseGeometry(geometry);  // the scene keeps it, and so its buffers, alive

  record->vertices_B = vertices;
  record->indices = indices;
  record->triangle_count = triangles.size();
  triangle_count += triangles.size();
  body.geoms.push_back(std::move(record));
}

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

RTCGeometry RayCaster::Impl::NewInstance(RTCScene top, const Body& body, unsigned int inst_id) {
  RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(instance, body.scene);
  rtcSetGeometryTimeStepCount(instance, 1);
  float xfm[12];
  ToColumnMajor3x4(body.X_WB, xfm);
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
  rtcCommitGeometry(instance);
  rtcAttachGeometryByID(top, instance, inst_id);
  return instance;  // we keep our reference, for SetBodyPose
}

RayCaster::RayCaster() : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) {
    throw std::runtime_error(std::string("RayCaster: cannot create the Embree device: ") +
                             ErrorCodeName(rtcGetDeviceError(nullptr)));
  }
  rtcSetDeviceErrorFunction(impl_->device, &Impl::OnDeviceError, impl_.get());
  // rebuilt every sample: medium quality, not dynamic (for a few instances
  // Embree's low-quality two-level builder costs 3× more: ~60 µs against ~20 µs
  // per commit, proxsim_microbench BM_MoveRobotAndCommit)
  impl_->scene_world = impl_->NewScene(RTC_BUILD_QUALITY_MEDIUM);
  impl_->scene_robot = impl_->NewScene(RTC_BUILD_QUALITY_MEDIUM);
  Commit();  // an empty caster answers every ray with a miss
}

RayCaster::~RayCaster() {
  for (auto& body : impl_->bodies) {
    if (body->instance_robot) rtcReleaseGeometry(body->instance_robot);
    if (body->instance_world) rtcReleaseGeometry(body->instance_world);
    for (auto& [ids, scene] : body->query_scenes) rtcReleaseScene(scene);
    rtcReleaseScene(body->scene);
  }
  rtcReleaseScene(impl_->scene_world);
  rtcReleaseScene(impl_->scene_robot);
  rtcReleaseDevice(impl_->device);
}

int RayCaster::AddBody(std::vector<BodyShape> shapes, BodyKind kind, const Pose& X_WB) {
  Impl& impl = *impl_;
  const int body_index = static_cast<int>(impl.bodies.size());
  Body& body = *impl.bodies.emplace_back(std::make_unique<Body>());
  body.kind = kind;
  body.X_WB = X_WB;
  body.R_WB = X_WB.linear().cast<float>();
  body.scene = impl.NewScene(kind == BodyKind::kWorld ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);

  for (BodyShape& body_shape : shapes) {
    assert(body_shape.object_id >= 0 && "object ids must be >= 0");
    auto record = std::make_unique<GeomRecord>();
    record->object_id = body_shape.object_id;
    record->X_BO = body_shape.X_BO;
    record->X_OB = body_shape.X_BO.inverse();

    if (const auto* box = std::get_if<Box>(&body_shape.shape)) {
      // 8 corners (bit 0: +x, bit 1: +y, bit 2: +z) and 2 outward CCW triangles per face
      std::vector<Vec3> corners_B(8);
      for (int c = 0; c < 8; ++c) {
        const Vec3 sign((c & 1) ? 1 : -1, (c & 2) ? 1 : -1, (c & 4) ? 1 : -1);
        corners_B[c] = body_shape.X_BO * (0.5 * box->size_m.cwiseProduct(sign));
      }
      static const std::vector<std::array<std::uint32_t, 3>> kBoxTriangles = {
          {0, 4, 6}, {0, 6, 2},  // −x
          {1, 3, 7}, {1, 7, 5},  // +x
          {0, 1, 5}, {0, 5, 4},  // −y
          {2, 6, 7}, {2, 7, 3},  // +y
          {0, 2, 3}, {0, 3, 1},  // −z
          {4, 5, 7}, {4, 7, 6},  // +z
      };
      record->kind = GeomKind::kBox;
      record->shape = body_shape.shape;
      impl.AttachTriangles(body, std::move(record), corners_B, kBoxTriangles);
    } else if (const auto* mesh = std::get_if<Mesh>(&body_shape.shape)) {
      assert(mesh->data && "mesh must be loaded before it is added");
      std::vector<Vec3> vertices_B;
      vertices_B.reserve(mesh->data->vertices_O.size());
      for (const Vec3f& v_O : mesh->data->vertices_O) vertices_B.push_back(body_shape.X_BO * v_O.cast<double>());
      record->kind = GeomKind::kMesh;
      body.has_mesh = true;
      impl.AttachTriangles(body, std::move(record), vertices_B, mesh->data->triangles);
    } else {
      record->kind = std::holds_alternative<Sphere>(body_shape.shape)     ? GeomKind::kSphere
                     : std::holds_alternative<Cylinder>(body_shape.shape) ? GeomKind::kCylinder
                                                                          : GeomKind::kPlane;
      record->shape = body_shape.shape;
      impl.AttachUserShape(body, std::move(record));
    }
  }

  for (const auto& geom : body.geoms) {
    if (geom->kind != GeomKind::kMesh) body.closed_form_geoms.push_back(geom.get());
  }

  // the body's BVH, built once; then its instance in the top-level scenes
  rtcCommitScene(body.scene);
  if (kind == BodyKind::kWorld) {
    body.instance_world = impl.NewInstance(impl.scene_world, body, static_cast<unsigned int>(body_index));
    impl.world_dirty = true;
  } else {
    body.instance_robot = impl.NewInstance(impl.scene_robot, body, static_cast<unsigned int>(body_index));
    impl.robot_dirty = true;
    impl.has_robot = true;
  }
  impl.committed = false;
  impl.ThrowIfDeviceError("AddBody");
  return body_index;
}

void RayCaster::SetBodyPose(int body_index, const Pose& X_WB) {
  assert(body_index >= 0 && body_index < static_cast<int>(impl_->bodies.size()));
  Body& body = *impl_->bodies[body_index];
  body.X_WB = X_WB;
  body.R_WB = X_WB.linear().cast<float>();
  float xfm[12];
  ToColumnMajor3x4(X_WB, xfm);
  for (RTCGeometry instance : {body.instance_robot, body.instance_world}) {
    if (!instance) continue;
    rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
    rtcCommitGeometry(instance);
  }
  impl_->committed = false;
  (body.instance_world ? impl_->world_dirty : impl_->robot_dirty) = true;
  impl_->ThrowIfDeviceError("SetBodyPose");
}

void RayCaster::Commit() {
  // only the instances are rebuilt, and only in the scenes that changed;
  // child scenes were committed in AddBody
  // on the calling thread alone: a parallel commit of a few instances wakes
  // Embree's TBB workers, which then spin for work every sample and take the
  // core from the sample's own threads (BM_HeavyStep1M at 2 threads: 260–400 µs
  // per step this way, 400–530 µs with the default arena)
  Impl& impl = *impl_;
  if (impl.world_dirty) {
    // one world body at the identity: cast into its own scene, no instance level
    impl.world_direct = nullptr;
    impl.world_direct_body = -1;
    int world_bodies = 0;
    for (std::size_t b = 0; b < impl.bodies.size(); ++b) {
      if (impl.bodies[b]->kind != BodyKind::kWorld) continue;
      ++world_bodies;
      impl.world_direct_body = static_cast<int>(b);
    }
    if (world_bodies == 1 && impl.bodies[impl.world_direct_body]->X_WB.matrix() == Eigen::Matrix4d::Identity()) {
      impl.world_direct = impl.bodies[impl.world_direct_body]->scene;
    }
  }
  impl.commit_arena.execute([&impl] {
    if (impl.robot_dirty) rtcCommitScene(impl.scene_robot);
    if (impl.world_dirty) rtcCommitScene(impl.scene_world);
  });
  impl.robot_dirty = impl.world_dirty = false;
  impl_->committed = true;
  impl_->ThrowIfDeviceError("Commit");
}

namespace {

/// Rays go to Embree in packets of this many consecutive rays: a beam's rays
/// share an origin and sit side by side in the batch, so a packet's rays
/// walk the same BVH nodes; for incoherent rays Embree's packet kernel costs
/// about what its single-ray one does (`proxsim bench` measures both).
constexpr std::size_t kPacketRays = 8;

/// Where a packet's rays are cast.
struct CastScenes {
  RTCScene world = nullptr;      ///< the world's top-level scene, or the world body's own (direct)
  int direct_body = -1;          ///< the body of `world` when it is direct, else -1 (hits carry the instance)
  RTCScene robot = nullptr;      ///< the robot's top-level scene; null when there is no robot
};

/// Maps the hit of `lane` to the body and its shape; Ng from B to W, unit.
void MapHit(const RTCRayHit8& packet, std::size_t lane, int direct_body,
            const std::vector<std::unique_ptr<Body>>& bodies, Hit* hit) {
  const unsigned int inst = packet.hit.instID[0][lane];
  if (packet.hit.geomID[lane] == RTC_INVALID_GEOMETRY_ID || (direct_body < 0 && inst == RTC_INVALID_GEOMETRY_ID)) {
    *hit = Hit{};  // a miss
    return;
  }
  const Body& body = *bodies[direct_body >= 0 ? static_cast<std::size_t>(direct_body) : inst];
  const GeomRecord& geom = *body.geoms[packet.hit.geomID[lane]];
  const Vec3f normal_B = Vec3f(packet.hit.Ng_x[lane], packet.hit.Ng_y[lane], packet.hit.Ng_z[lane]).normalized();
  hit->distance_m = packet.ray.tfar[lane];
  hit->normal_W = body.R_WB * normal_B;
  hit->object_id = geom.object_id;
}

/// Casts rays[0..n) (n <= 8) as one packet: into the world, then the lanes
/// that see the robot into the robot's scene up to their world hit (Embree
/// only reports a nearer one). Each lane is intersected on its own, so a
/// ray's answer does not depend on the other rays of its packet.
void CastPacket(const CastScenes& scenes, const std::vector<std::unique_ptr<Body>>& bodies, const Ray* rays,
                Hit* hits, std::size_t n) {
  alignas(32) int valid[kPacketRays];
  RTCRayHit8 packet;
  for (std::size_t lane = 0; lane < kPacketRays; ++lane) {
    valid[lane] = lane < n ? -1 : 0;
    const Ray& ray = rays[lane < n ? lane : 0];  // inactive lanes: any finite ray (Embree skips them)
    packet.ray.org_x[lane] = ray.origin_W.x();
    packet.ray.org_y[lane] = ray.origin_W.y();
    packet.ray.org_z[lane] = ray.origin_W.z();
    packet.ray.tnear[lane] = 0.0f;
    packet.ray.dir_x[lane] = ray.direction_W.x();
    packet.ray.dir_y[lane] = ray.direction_W.y();
    packet.ray.dir_z[lane] = ray.direction_W.z();
    packet.ray.time[lane] = 0.0f;
    packet.ray.tfar[lane] = ray.max_range_m;
    packet.ray.mask[lane] = 0xFFFFFFFFu;
    packet.ray.id[lane] = 0;
    packet.ray.flags[lane] = 0;
    packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);

  // the static world
  rtcIntersect8(valid, scenes.world, &context, &packet);
  for (std::size_t lane = 0; lane < n; ++lane) MapHit(packet, lane, scenes.direct_body, bodies, &hits[lane]);

  // the robot's links, nearer than the world hit (tfar now holds it)
  if (!scenes.robot) return;
  bool any = false;
  for (std::size_t lane = 0; lane < kPacketRays; ++lane) {
    valid[lane] = lane < n && rays[lane].see_robot ? -1 : 0;
    any = any || valid[lane];
    packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
  }
  if (!any) return;
  rtcIntersect8(valid, scenes.robot, &context, &packet);
  for (std::size_t lane = 0; lane < n; ++lane) {
    if (valid[lane] && packet.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID) {
      MapHit(packet, lane, /*direct_body=*/-1, bodies, &hits[lane]);
    }
  }
}

}  // namespace

void RayCaster::Cast(std::span<const Ray> rays, std::span<Hit> hits) const {
  assert(hits.size() == rays.size() && "one hit per ray");
  assert(impl_->committed && "Commit() after adding or moving bodies");
  const Impl& impl = *impl_;
  const auto packets = static_cast<std::ptrdiff_t>((rays.size() + kPacketRays - 1) / kPacketRays);
  const CastScenes scenes{.world = impl.world_direct ? impl.world_direct : impl.scene_world,
                          .direct_body = impl.world_direct ? impl.world_direct_body : -1,
                          .robot = impl.has_robot ? impl.scene_robot : nullptr};
  const auto cast_packet = [&](std::ptrdiff_t p) {
    const std::size_t first = static_cast<std::size_t>(p) * kPacketRays;
    CastPacket(scenes, impl.bodies, rays.data() + first, hits.data() + first, std::min(kPacketRays, rays.size() - first));
  };

  // every ray is independent, so the result does not depend on the thread count
  // (a batch is split on packet boundaries: the same packets either way)
  const std::size_t grain_packets = std::max<std::size_t>(1, kParallelBatchRays / kPacketRays);
  const auto cast_packets = [&](std::size_t begin, std::size_t end) {
    DenormalModeGuard denormal_mode;
    for (std::size_t p = begin; p < end; ++p) cast_packet(static_cast<std::ptrdiff_t>(p));
  };
  if (rays.size() >= kParallelBatchRays && impl.runner->threads() > 1) {
    impl.runner->For(static_cast<std::size_t>(packets), grain_packets, cast_packets);
  } else {
    cast_packets(0, static_cast<std::size_t>(packets));
  }
  impl_->ThrowIfDeviceError("Cast");
}

void RayCaster::set_threads(int threads) {
  assert(threads >= 1);
  if (threads != impl_->runner->threads()) impl_->runner = std::make_unique<ParallelRunner>(threads);
}

double RayCaster::DistanceToWorld(const Vec3& p_W, std::span<const std::int32_t> exclude_object_ids,
                                  double below_m) const {
  // no distance is below a cap <= 0 (and a point query needs a positive radius)
  if (!(below_m > 0)) return below_m;
  // the cap is the first best: nothing at or beyond it is measured
  double best_m = below_m;
  for (const auto& body_ptr : impl_->bodies) {
    const Body& body = *body_ptr;
    if (body.kind != BodyKind::kWorld) continue;
    const Vec3 p_B = body.X_WB.inverse() * p_W;

    // boxes and analytic shapes: exact closed forms in the shape frame
    for (const GeomRecord* geom_ptr : body.closed_form_geoms) {
      const GeomRecord& geom = *geom_ptr;
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
      best_m = std::min(best_m, distance_m);
    }

    // meshes: Embree's point query walks the body's BVH within a search radius.
    // An unbounded query (a world of meshes only) would visit a large part of
    // the BVH before the radius shrinks, so the radius grows from 5 cm by ×2
    // until a triangle lies within it: the nearest one is then found exactly.
    // The growth stops at the best so far (the cap at first): a point far from
    // every mesh then costs a few small empty queries, not one that wades
    // through the triangles between it and the nearest.
    if (!body.has_mesh) continue;
    RTCScene query_scene = impl_->MeshQueryScene(const_cast<Body&>(body), exclude_object_ids);
    if (!query_scene) continue;  // every mesh of the body is excluded
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
    best_m = std::min(best_m, state.best_distance_m);
  }
  return best_m;
}

std::size_t RayCaster::triangle_count() const { return impl_->triangle_count; }

}  // namespace proxsim
