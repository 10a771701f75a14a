// Building the caster's scenes: the Embree device and its errors, a body's
// child scene of boxes and meshes (as triangles) and analytic shapes (user
// geometry, ray_caster_user_shapes.cc), its instance in a top-level scene,
// moving it, and Commit. The layout is described in ray_caster_internal.h.
#include "raycast/ray_caster_internal.h"
#include "raycast/embree_version.h"

#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

namespace proxsim {

namespace {

using raycast_internal::Body;
using raycast_internal::GeomKind;
using raycast_internal::GeomRecord;

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

}  // namespace

void RayCaster::Impl::OnDeviceError(void* user_ptr, RTCError code, const char* message) {
  auto& impl = *static_cast<Impl*>(user_ptr);
  std::lock_guard<std::mutex> lock(impl.error_mutex);
  if (impl.error_message.empty()) {
    impl.error_message = std::string("Embree error (") + ErrorCodeName(code) + "): " +
                         (message ? message : "(no message)");
  }
  impl.has_error.store(true);
}

void RayCaster::Impl::ThrowIfDeviceError(const char* during) {
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

RTCScene RayCaster::Impl::NewScene(RTCBuildQuality quality) {
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, quality);
  return scene;
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
  // the same configuration for every device of the process, so that a run can
  // be pinned to one of Embree's code paths (PROXSIM_EMBREE_CONFIG=isa=sse4.2)
  const std::string config = EmbreeDeviceConfig();
  impl_->device = rtcNewDevice(config.empty() ? nullptr : config.c_str());
  if (!impl_->device) {
    throw std::runtime_error(std::string("RayCaster: cannot create the Embree device") +
                             (config.empty() ? "" : std::string(" with ") + kEmbreeConfigVariable + "='" + config + "'") +
                             ": " + ErrorCodeName(rtcGetDeviceError(nullptr)));
  }
  rtcSetDeviceErrorFunction(impl_->device, &Impl::OnDeviceError, impl_.get());
  // rebuilt when their objects move: medium quality, not dynamic (for a few
  // instances Embree's low-quality two-level builder cost 3× more, ~60 µs
  // against ~20 µs a commit, when the robot's links were instances too)
  impl_->scene_world = impl_->NewScene(RTC_BUILD_QUALITY_MEDIUM);
  impl_->scene_moving = impl_->NewScene(RTC_BUILD_QUALITY_MEDIUM);
  Commit();  // an empty caster answers every ray with a miss
}

RayCaster::~RayCaster() {
  for (auto& body : impl_->bodies) {
    if (body->instance_world) rtcReleaseGeometry(body->instance_world);
    if (body->instance_moving) rtcReleaseGeometry(body->instance_moving);
    for (auto& [ids, scene] : body->query_scenes) rtcReleaseScene(scene);
    rtcReleaseScene(body->scene);
  }
  rtcReleaseScene(impl_->scene_world);
  rtcReleaseScene(impl_->scene_moving);
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
    if (geom->kind == GeomKind::kMesh) continue;
    body.closed_form_geoms.push_back(geom.get());
    // the shape's bounding sphere about its origin (O is its centre for each kind)
    double radius_m = std::numeric_limits<double>::infinity();
    if (const auto* box = std::get_if<Box>(&geom->shape)) radius_m = 0.5 * box->size_m.norm();
    if (const auto* sphere = std::get_if<Sphere>(&geom->shape)) radius_m = sphere->radius_m;
    if (const auto* cylinder = std::get_if<Cylinder>(&geom->shape))
      radius_m = std::hypot(cylinder->radius_m, 0.5 * cylinder->length_m);
    const Vec3 center_B = geom->X_BO.translation();
    body.closed_form_spheres_B.emplace_back(center_B.x(), center_B.y(), center_B.z(), radius_m);
    // and its box in B, the corners of its box in O moved to B (far tighter
    // than the sphere for a room's long walls; unbounded for a plane)
    raycast_internal::ShapeBox box_B;
    Vec3 half_O = Vec3::Constant(std::numeric_limits<double>::infinity());
    if (const auto* box = std::get_if<Box>(&geom->shape)) half_O = 0.5 * box->size_m;
    if (const auto* sphere = std::get_if<Sphere>(&geom->shape)) half_O = Vec3::Constant(sphere->radius_m);
    if (const auto* cylinder = std::get_if<Cylinder>(&geom->shape))
      half_O = Vec3(cylinder->radius_m, cylinder->radius_m, 0.5 * cylinder->length_m);
    if (half_O.allFinite()) {
      box_B.lo_B = Vec3::Constant(std::numeric_limits<double>::infinity());
      box_B.hi_B = -box_B.lo_B;
      for (int c = 0; c < 8; ++c) {
        const Vec3 sign((c & 1) ? 1 : -1, (c & 2) ? 1 : -1, (c & 4) ? 1 : -1);
        const Vec3 corner_B = geom->X_BO * half_O.cwiseProduct(sign);
        box_B.lo_B = box_B.lo_B.cwiseMin(corner_B);
        box_B.hi_B = box_B.hi_B.cwiseMax(corner_B);
      }
    }
    body.closed_form_boxes_B.push_back(box_B);
  }

  // the body's BVH, built once; then its instance in the top-level scenes
  rtcCommitScene(body.scene);
  RTCBounds bounds_B;
  rtcGetSceneBounds(body.scene, &bounds_B);
  const Vec3 lower_B(bounds_B.lower_x, bounds_B.lower_y, bounds_B.lower_z);
  const Vec3 upper_B(bounds_B.upper_x, bounds_B.upper_y, bounds_B.upper_z);
  // a plane's bounds are unbounded in practice: no sphere skips it
  if (lower_B.allFinite() && upper_B.allFinite() && (upper_B - lower_B).maxCoeff() < 1e6 &&
      (upper_B - lower_B).minCoeff() >= 0) {
    body.bound_center_B = 0.5 * (lower_B + upper_B);
    body.bound_radius_m = 0.5 * (upper_B - lower_B).norm();
  }
  body.bound_center_W = X_WB * body.bound_center_B;
  body.X_BW = X_WB.inverse();
  if (kind == BodyKind::kRobot && lower_B.allFinite() && upper_B.allFinite() && (upper_B - lower_B).minCoeff() >= 0) {
    body.box_lo_B = lower_B.array() - raycast_internal::kRobotBoxSlack_m;
    body.box_hi_B = upper_B.array() + raycast_internal::kRobotBoxSlack_m;
  }
  if (kind == BodyKind::kWorld) {
    body.world_slot = static_cast<int>(impl.world_bodies.size());
    impl.world_has_mesh = impl.world_has_mesh || body.has_mesh;
    impl.world_bodies.push_back(body_index);
    impl.world_spheres_W.emplace_back(body.bound_center_W.x(), body.bound_center_W.y(), body.bound_center_W.z(),
                                      body.bound_radius_m);
    body.instance_world = impl.NewInstance(impl.scene_world, body, static_cast<unsigned int>(body.world_slot));
    impl.world_dirty = true;
  } else if (kind == BodyKind::kMoving) {
    body.moving_slot = static_cast<int>(impl.moving_spheres_W.size());
    impl.moving_spheres_W.emplace_back(body.bound_center_W.x(), body.bound_center_W.y(), body.bound_center_W.z(),
                                       body.bound_radius_m);
    body.instance_moving = impl.NewInstance(impl.scene_moving, body, static_cast<unsigned int>(body.moving_slot));
    impl.moving_bodies.push_back(body_index);
    impl.moving_dirty = true;
    impl.has_moving = true;
  } else {
    body.robot_slot = static_cast<int>(impl.robot_bodies.size());
    impl.robot_bodies.push_back(body_index);
    impl.robot_spheres_W.emplace_back(body.bound_center_W.x(), body.bound_center_W.y(), body.bound_center_W.z(),
                                      body.bound_radius_m + raycast_internal::kRobotBoxSlack_m);
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
  body.bound_center_W = X_WB * body.bound_center_B;
  if (body.world_slot >= 0) impl_->world_spheres_W[body.world_slot].head<3>() = body.bound_center_W;
  if (body.moving_slot >= 0) impl_->moving_spheres_W[body.moving_slot].head<3>() = body.bound_center_W;
  if (body.robot_slot >= 0) impl_->robot_spheres_W[body.robot_slot].head<3>() = body.bound_center_W;
  body.X_BW = X_WB.inverse();
  impl_->committed = false;
  // a robot body has no instance: rays are moved into its frame as they are cast (ray_caster_cast.cc)
  if (body.kind == BodyKind::kRobot) return;
  // the instance's transform waits for the commit of its scene: a caster
  // asked only for distances (World's moving caster), or moving objects no
  // ray comes near, never pay for it
  if (!body.instance_stale) {
    body.instance_stale = true;
    (body.kind == BodyKind::kMoving ? impl_->stale_moving : impl_->stale_fixed).push_back(body_index);
  }
  (body.kind == BodyKind::kWorld ? impl_->world_dirty : impl_->moving_dirty) = true;
}

void RayCaster::Impl::PushTransforms(std::vector<int>& stale) {
  for (const int b : stale) {
    Body& body = *bodies[b];
    float xfm[12];
    ToColumnMajor3x4(body.X_WB, xfm);
    for (RTCGeometry instance : {body.instance_world, body.instance_moving}) {
      if (!instance) continue;
      rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
      rtcCommitGeometry(instance);
    }
    body.instance_stale = false;
  }
  stale.clear();
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
  impl.PushTransforms(impl.stale_fixed);
  if (impl.world_dirty) impl.commit_arena.execute([&impl] { rtcCommitScene(impl.scene_world); });
  // the moving objects' scene waits for a ray that may meet them (CommitMovingIfMoved)
  if (impl.moving_dirty) impl.moving_uncommitted.store(true, std::memory_order_release);
  impl.world_dirty = impl.moving_dirty = false;
  impl_->committed = true;
  impl_->ThrowIfDeviceError("Commit");
}

void RayCaster::Impl::CommitIfMoved(std::atomic<bool>& uncommitted, std::mutex& mutex, std::vector<int>& stale,
                                    RTCScene scene) {
  if (!uncommitted.load(std::memory_order_acquire)) return;
  std::lock_guard<std::mutex> lock(mutex);
  if (!uncommitted.load(std::memory_order_relaxed)) return;  // another cast committed it meanwhile
  PushTransforms(stale);
  commit_arena.execute([scene] { rtcCommitScene(scene); });
  uncommitted.store(false, std::memory_order_release);
}

void RayCaster::Impl::CommitMovingIfMoved() {
  CommitIfMoved(moving_uncommitted, moving_commit_mutex, stale_moving, scene_moving);
}

std::size_t RayCaster::triangle_count() const { return impl_->triangle_count; }

bool RayCaster::has_moving() const { return impl_->has_moving; }

bool RayCaster::world_has_mesh() const { return impl_->world_has_mesh; }

}  // namespace proxsim
