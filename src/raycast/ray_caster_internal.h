// The ray caster's insides, shared by its files; users include
// raycast/ray_caster.h. The files, one job each:
//   ray_caster.cc              the device, the bodies and their instances, Commit
//   ray_caster_user_shapes.cc  Embree user geometry: spheres, cylinders and planes
//   ray_caster_cast.cc         casting a batch of rays, packet by packet
//   ray_caster_distance.cc     the distance from a point to the world
// With embree_version.cc they are the only files of proxsim that include Embree
// (the bench's bare-Embree peer aside).
//
// Layout of the acceleration structures:
//   - every body B is a child RTCScene holding its shapes in the body frame:
//     boxes as 12 triangles, meshes as their triangles (both moved by X_BO),
//     spheres, cylinders and planes as user geometry intersected exactly
//     (analytic_shapes.h), never tessellated;
//   - two top-level scenes instance the bodies (one level of instancing):
//     `world` the kWorld bodies and `moving` the kMoving ones. A body's
//     instance ID is its index among its scene's bodies (Impl::world_bodies,
//     moving_bodies), so a hit maps back to (body, geometry) → object_id. A
//     ray is cast into the world first — straight into the world body's own
//     scene when there is one world body at the identity pose (the usual
//     case), so the big static BVH is walked without an instance level —
//     then, if it may meet one, into `moving`, then, if it sees the robot,
//     into each kRobot body it may meet (Impl::robot_bodies): the ray moved
//     into the body's frame and cast into the body's own scene, up to the
//     nearest hit so far. The robot has no top-level scene: it moves every
//     sample, and a commit of its instances cost more than the casts into it
//     (ray_caster_cast.cc, CastIntoRobotBody).
// Moving a body only rewrites its instance transforms; Commit() then rebuilds
// the world's top-level scene if it changed, whose only primitives are the
// instances. The moving objects' top-level scene is rebuilt only when a ray
// first may meet one of them after they moved (its segment up to the world
// hit passes within a moving body's bounding sphere, ray_caster_cast.cc): a
// commit of 50 instances costs ~40 µs, most samples' rays pass far from every
// moving object, and a ray that passes outside every sphere misses them all
// whether or not their scene is up to date. A robot body is cast into only
// when a ray's segment passes through its box (Body::box_lo_B, box_hi_B: a
// box fits a link far better than a sphere around it, and a shin sensor's
// rays start beside their own link).
// The child scenes, and so the static world's BVH, are built once in AddBody.
//
// Every scene is RTC_SCENE_FLAG_ROBUST: Embree then uses its watertight
// triangle test, so a ray through a shared edge or vertex cannot slip between
// triangles. Child scenes are built once with high (world) or medium (robot,
// moving) quality; the small top-level scenes are rebuilt at medium quality.
//
// Normals: Embree reports Ng in the instanced body's frame B and unnormalised;
// we normalise it and rotate it by R_WB. Triangle normals follow the right-hand
// rule of the vertex order (counter-clockwise seen from the front), which for
// boxes is outward.
//
// Errors: the device error callback records Embree's message; the public
// calls check it and throw std::runtime_error, so no error passes silently
// (and no exception is thrown through Embree's C frames).
#pragma once

#include <embree3/rtcore.h>
#include <oneapi/tbb/task_arena.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "core/parallel.h"
#include "raycast/ray_caster.h"

namespace proxsim {

namespace raycast_internal {

enum class GeomKind { kBox, kMesh, kSphere, kCylinder, kPlane };

// A robot body's box is grown by this much: Embree's float transforms and
// bounds err by microns, not this (a ray that passes outside the grown box
// cannot meet the body).
inline constexpr double kRobotBoxSlack_m = 1e-3;

/// An axis-aligned box in a body's frame B holding a shape (unbounded: every point is in it).
struct ShapeBox {
  Vec3 lo_B = Vec3::Constant(-std::numeric_limits<double>::infinity());
  Vec3 hi_B = Vec3::Constant(std::numeric_limits<double>::infinity());
  /// The squared distance from p_B to the box (0 inside).
  double SquaredDistance(const Vec3& p_B) const {
    return (lo_B - p_B).cwiseMax(p_B - hi_B).cwiseMax(0.0).squaredNorm();
  }
};

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
  RTCGeometry instance_world = nullptr;  ///< null for robot and moving bodies
  RTCGeometry instance_moving = nullptr; ///< null for world and robot bodies
  bool has_mesh = false;
  std::vector<const GeomRecord*> closed_form_geoms;  ///< every geom but meshes, for DistanceToWorld
  // each of those shapes' bounding sphere in B (centre x, y, z, radius;
  // infinite for a plane), side by side: a distance query skips, without
  // touching the geom's record or moving the point into O, every shape
  // farther than its best so far (most of a room's furniture from any point)
  std::vector<Eigen::Vector4d> closed_form_spheres_B;
  std::vector<ShapeBox> closed_form_boxes_B;  ///< and their boxes in B, tighter: tested after the spheres
  // a sphere holding every geom (from the body's bounds in B; infinite with a
  // plane), so that a distance query skips a body farther than its best so far
  Vec3 bound_center_B = Vec3::Zero();
  double bound_radius_m = std::numeric_limits<double>::infinity();
  Vec3 bound_center_W = Vec3::Zero();  ///< X_WB · bound_center_B, kept with X_WB
  Pose X_BW = Pose::Identity();  ///< X_WB.inverse(), kept with X_WB (distance queries, the robot's box test)
  // a kRobot body's box in B (Embree's bounds of its scene, grown by a
  // slack): a ray that misses the box misses the body (CastIntoRobotBody)
  Vec3 box_lo_B = Vec3::Constant(-std::numeric_limits<double>::infinity());
  Vec3 box_hi_B = Vec3::Constant(std::numeric_limits<double>::infinity());
  int world_slot = -1;  ///< a kWorld body's index in Impl::world_bodies and world_spheres_W
  int moving_slot = -1; ///< a kMoving body's index in Impl::moving_spheres_W
  int robot_slot = -1;  ///< a kRobot body's index in Impl::robot_bodies and robot_spheres_W
  bool instance_stale = false;  ///< moved since its instance's transform was last set (Impl::stale_*)
  // point-query scenes of this body's meshes without some objects (the
  // ground, say), keyed by the sorted excluded object ids; built on first use
  std::mutex query_scenes_mutex;
  std::map<std::vector<std::int32_t>, RTCScene> query_scenes;
  std::vector<std::int32_t> last_exclude{-1};  // the last list asked for (never a valid list: ids >= 0)
  RTCScene last_query_scene = nullptr;          // and its answer
};

}  // namespace raycast_internal

struct RayCaster::Impl {
  using Body = raycast_internal::Body;
  using GeomRecord = raycast_internal::GeomRecord;

  RTCDevice device = nullptr;
  RTCScene scene_world = nullptr;
  RTCScene scene_moving = nullptr;  ///< the kMoving bodies' instances
  std::vector<std::unique_ptr<Body>> bodies;
  // each top-level scene's bodies by instance ID: IDs are dense within a
  // scene (Embree's commit walks every ID up to the largest)
  std::vector<int> moving_bodies;
  std::vector<int> robot_bodies;  ///< the kRobot bodies (no scene of theirs: cast one by one)
  // the kWorld bodies' indices and bounding spheres in W (centre x, y, z,
  // radius), side by side and kept with their poses: a distance query culls
  // bodies without touching their records (50 moving boxes: 50 bodies a query)
  std::vector<int> world_bodies;  ///< also the world scene's bodies by instance ID
  std::vector<Eigen::Vector4d> world_spheres_W;
  // each kMoving body's bounding sphere in W (as world_spheres_W), kept with its pose
  std::vector<Eigen::Vector4d> moving_spheres_W;
  // the moving objects' scene has moved since its last commit (see the top of
  // the file); the first cast that may meet one of them commits it, once
  std::atomic<bool> moving_uncommitted{false};
  std::mutex moving_commit_mutex;
  // the bodies moved since their instances' transforms were set: set at the
  // commit of their scene (Commit, or CommitMovingIfMoved for kMoving bodies)
  std::vector<int> stale_fixed;
  std::vector<int> stale_moving;
  // each robot body's bounding sphere in W (as world_spheres_W, the radius
  // grown by kRobotBoxSlack_m), by robot_slot, kept with its pose: a batch
  // of rays from one point (a sensor's beam) is tested against them as a
  // cone, and only the bodies the cone may meet take the box test
  std::vector<Eigen::Vector4d> robot_spheres_W;
  // the world body cast without its instance (see the top of the file), or null
  RTCScene world_direct = nullptr;
  int world_direct_body = -1;
  bool has_robot = false;
  bool has_moving = false;
  bool world_has_mesh = false;  ///< a kWorld body holds a mesh
  std::size_t triangle_count = 0;
  std::unique_ptr<ParallelRunner> runner = std::make_unique<ParallelRunner>(1);  ///< for large batches
  bool committed = true;
  // which top-level scene has a change to commit (moving a robot body changes neither)
  bool world_dirty = true;
  bool moving_dirty = true;
  tbb::task_arena commit_arena{1};  ///< one slot: top-level commits run on the caller only

  // first error reported by Embree since the last check
  std::mutex error_mutex;
  std::string error_message;
  std::atomic<bool> has_error{false};

  /// Embree's error callback: keeps the first message for ThrowIfDeviceError.
  static void OnDeviceError(void* user_ptr, RTCError code, const char* message);

  /// Throws std::runtime_error if Embree reported an error since the last check.
  void ThrowIfDeviceError(const char* during);

  /// A new scene, robust, at the given build quality.
  RTCScene NewScene(RTCBuildQuality quality);

  /// Commits the moving objects' scene if they moved since its last commit
  /// (thread-safe: the casts of a batch may ask at once).
  void CommitMovingIfMoved();
  /// The above: the scene's transforms pushed and the scene committed,
  /// once, by the first cast that finds `uncommitted` set.
  void CommitIfMoved(std::atomic<bool>& uncommitted, std::mutex& mutex, std::vector<int>& stale, RTCScene scene);
  /// Sets the instances' transforms of the bodies in `stale` from their poses, and empties it.
  void PushTransforms(std::vector<int>& stale);

  // ray_caster.cc: a body's triangles (a box's or a mesh's) and its instance in a top-level scene
  void AttachTriangles(Body& body, std::unique_ptr<GeomRecord> record, const std::vector<Vec3>& vertices_B,
                       const std::vector<std::array<std::uint32_t, 3>>& triangles);
  RTCGeometry NewInstance(RTCScene top, const Body& body, unsigned int inst_id);
  // ray_caster_user_shapes.cc: a sphere, cylinder or plane of a body
  void AttachUserShape(Body& body, std::unique_ptr<GeomRecord> record);
  // ray_caster_distance.cc: the scene a point query of the body walks
  RTCScene MeshQueryScene(Body& body, std::span<const std::int32_t> exclude_object_ids);
};

}  // namespace proxsim
