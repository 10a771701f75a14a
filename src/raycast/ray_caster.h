// The ray caster: the one place that talks to Embree (no file outside
// src/raycast/ includes it; ray_caster_internal.h lists its files). It holds
// rigid bodies made of shapes: the static world, and the robot's links that
// move every sample. Rays come in a batch, hits go out in a
// caller-owned buffer of the same length; nothing is allocated per ray.
//
// Frames: W world, B a body, O a shape on a body.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "core/ray_hit.h"
#include "scene/shape.h"

namespace proxsim {

/// One ray. The first hit in [0, max_range_m] is reported.
struct Ray {
  Vec3f origin_W = Vec3f::Zero();
  Vec3f direction_W = Vec3f::UnitX();  ///< unit length
  float max_range_m = 1.0f;            ///< > 0
  bool see_robot = true;               ///< false: the robot's links are transparent
  bool see_moving = true;              ///< false: the scene's moving objects are transparent
};

/// A shape fixed on a body.
struct BodyShape {
  Shape shape;
  Pose X_BO = Pose::Identity();  ///< pose of the shape in its body frame
  std::int32_t object_id = 0;    ///< reported in Hit::object_id; >= 0
};

/// kWorld: the static scene (built once, never moved in practice); kMoving:
/// a scene object that moves every sample (an instance whose transform
/// changes); kRobot: a robot link. Rays see all three; DistanceToWorld and
/// NearestToWorld measure the kWorld bodies only (a caller who wants the
/// distance to moving things keeps them as kWorld bodies of a caster of
/// their own, moved with SetBodyPose).
enum class BodyKind { kWorld, kRobot, kMoving };

class RayCaster {
 public:
  RayCaster();
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  /// Adds a rigid body at pose X_WB; returns its index for SetBodyPose.
  int AddBody(std::vector<BodyShape> shapes, BodyKind kind, const Pose& X_WB = Pose::Identity());

  /// Moves a body: at once for DistanceToWorld and NearestToWorld, for rays at the next Commit().
  void SetBodyPose(int body, const Pose& X_WB);

  /// Builds or refits the acceleration structures; call after adding or moving bodies.
  void Commit();

  /// Casts every ray; hits[i] answers rays[i]. Requires hits.size() == rays.size().
  /// Large batches are spread over the threads set by set_threads.
  void Cast(std::span<const Ray> rays, std::span<Hit> hits) const;

  /// Threads used by Cast for large batches (>= 1).
  void set_threads(int threads);

  /// Distance from p_W to the nearest surface of any world body shape whose
  /// object_id is not in exclude_object_ids (+inf when there is none), capped:
  /// min(distance, below_m), exact below the cap and cheaper the lower the cap.
  double DistanceToWorld(const Vec3& p_W, std::span<const std::int32_t> exclude_object_ids,
                         double below_m = std::numeric_limits<double>::infinity()) const;

  /// The world surface nearest p_W, as DistanceToWorld measures it, and which
  /// object it belongs to: object_id -1 when nothing is nearer than below_m.
  /// depth_m: how deep p_W lies inside that object when it is a box, sphere
  /// or cylinder (scene/shape_inside.h), else 0.
  struct NearestSurface {
    double distance_m = std::numeric_limits<double>::infinity();
    std::int32_t object_id = -1;
    double depth_m = 0;
  };
  NearestSurface NearestToWorld(const Vec3& p_W, std::span<const std::int32_t> exclude_object_ids,
                                double below_m = std::numeric_limits<double>::infinity()) const;

  /// The world's bodies and closed-form shapes that a distance query from
  /// within a ball may have to measure: those whose bounding sphere comes
  /// within reach_m of it. Many queries from the same ball (a robot link's
  /// surface samples) then walk these lists instead of every shape of the
  /// world; their answers are the same (what is left out is what each query
  /// would skip by its own bounding-sphere tests). Valid until a world body moves.
  struct Nearby {
    Vec3 center_W = Vec3::Zero();
    double radius_m = 0;
    double reach_m = 0;
    std::vector<int> bodies;                ///< world slots, ascending
    std::vector<std::uint32_t> geom_begin;  ///< per listed body, its first entry in `geoms` (and one past the last)
    std::vector<std::uint32_t> geoms;       ///< closed-form shapes' indices within their body, ascending
  };
  /// `within`: a Nearby whose ball holds this one's and whose reach is no
  /// less: only its lists are looked through (otherwise every shape).
  void FindNearby(const Vec3& center_W, double radius_m, double reach_m, Nearby* nearby,
                  const Nearby* within = nullptr) const;
  /// NearestToWorld and DistanceToWorld from a point in `nearby`'s ball, capped
  /// at most at its reach (otherwise `nearby` is not used: every shape is looked at).
  NearestSurface NearestToWorld(const Vec3& p_W, std::span<const std::int32_t> exclude_object_ids, double below_m,
                                const Nearby* nearby) const;
  double DistanceToWorld(const Vec3& p_W, std::span<const std::int32_t> exclude_object_ids, double below_m,
                         const Nearby* nearby) const;

  /// Whether any body is a kMoving one.
  bool has_moving() const;

  /// Whether a world body holds a mesh: without one, every distance is a
  /// closed form, whose cost does not grow with the distance asked for.
  bool world_has_mesh() const;

  /// Number of triangles held (meshes and boxes), for reports.
  std::size_t triangle_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace proxsim
