// The robot's body in the simulated world: its links as moving bodies in the
// ray caster (so a sensor on one tibia can see the other leg), placed by
// forward kinematics from the robot's state at each sample, points sampled on
// their surfaces, and the robot's true minimum clearance to the scene (for
// the summary, never for strategies). What moves the robot (gait/Locomotion)
// lives outside.
//
// Frames: W world, P pelvis (the root link), L a link.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "gait/locomotion.h"
#include "raycast/ray_caster.h"
#include "robot/robot_model.h"

namespace proxsim {

/// One robot link's surfaces: its name and shapes in the link frame (scene.json draws them).
struct LinkShapes {
  std::string name;
  std::vector<BodyShape> shapes;
};

class RobotInScene {
 public:
  /// Adds one body per link of `model` (which must outlive this) to `caster`,
  /// with object ids first_object_id + link index.
  RobotInScene(const RobotModel& model, RayCaster& caster, std::int32_t first_object_id);
  ~RobotInScene();

  /// Places every link where forward kinematics puts it for `state`, and its
  /// body with it; the caller commits the ray caster.
  void Place(const RobotState& state);

  const Pose& X_WL(int link) const { return X_WL_[link]; }
  const std::vector<Pose>& X_WL() const { return X_WL_; }
  const RobotModel& model() const { return model_; }

  /// Points on a link's surface, every 2 cm, in the link frame (empty for a link without shapes).
  const std::vector<Vec3>& surface_points_L(int link) const { return link_samples_[link].points_L; }

  /// Forgets ClearanceTo's bounds (a new episode: the measure starts afresh).
  void ForgetClearanceBounds() { bounds_slots_.clear(); }
  /// The bodies of `against` moved, none of their points farther than
  /// `moved_m`: every bound remembered against it is lowered by that much
  /// (a distance to them shrank by moved_m at most), so it stays a bound.
  void LowerClearanceBounds(const RayCaster* against, double moved_m);

  /// Which of a link's surface samples a query counts: [link][sample], true
  /// to count it (a foot's sole points are left out against the ground).
  using SampleMask = std::vector<std::vector<bool>>;

  /// Least distance between the robot's surface (sampled every 2 cm; the
  /// samples `mask` counts, every one without a mask) and any world object of
  /// its ray caster other than the excluded ones (the floor it walks on), when
  /// it is below `below_m`; otherwise some value >= below_m. Links and samples
  /// that cannot come closer are skipped, which keeps a running minimum cheap:
  /// each remembers a lower bound of its clearance from when it was last
  /// measured, valid while the world bodies stay as they are. Bounds are kept
  /// for each (exclude list, mask) asked for, a few at a time.
  /// `against`: the world bodies of another ray caster than the robot's own
  /// (a caster of the ground alone, say), or null for its own.
  double ClearanceTo(std::span<const std::int32_t> exclude_object_ids,
                     double below_m = std::numeric_limits<double>::infinity(), const SampleMask* mask = nullptr,
                     const RayCaster* against = nullptr);

  /// One sample of the robot's surface nearer than `within_m` to a world
  /// object other than the excluded ones (and counted by `mask`).
  struct NearSample {
    int link = -1;
    Vec3 p_W = Vec3::Zero();
    RayCaster::NearestSurface nearest;
  };
  /// Every such sample at this pose (for contacts: call it once ClearanceTo
  /// has found something within reach, it measures every candidate sample).
  std::vector<NearSample> SamplesNear(std::span<const std::int32_t> exclude_object_ids, double within_m,
                                      const SampleMask* mask = nullptr, const RayCaster* against = nullptr) const;

  /// Link shapes for scene.json.
  std::vector<LinkShapes> LinkGeometry() const;

 private:
  // a run of consecutive samples of a link (neighbours on its surface, as
  // they are sampled) with the sphere that holds them
  struct Chunk {
    std::size_t begin = 0, end = 0;
    Vec3 center_L = Vec3::Zero();
    double radius_m = 0;
  };
  struct LinkSamples {
    std::vector<Vec3> points_L;  // surface samples in the link frame
    Vec3 center_L = Vec3::Zero();
    double radius_m = 0;         // bounding sphere of the samples
    std::vector<Chunk> chunks;   // the samples in runs, in order
  };
  // ClearanceTo's memory of a link: lower bounds of its samples' clearance,
  // each with the pose (or point) at which it holds
  struct ClearanceBounds {
    double link_lower_m = -std::numeric_limits<double>::infinity();  // no sample nearer, with the link at X_WL_ref
    Pose X_WL_ref = Pose::Identity();
    std::vector<double> point_lower_m;  // sample i no nearer than this when it was at p_W_ref[i]
    std::vector<Vec3> p_W_ref;
    // as link_lower_m, for each chunk: its samples no nearer, with the link at chunk_X_WL_ref
    std::vector<double> chunk_lower_m;
    std::vector<Pose> chunk_X_WL_ref;
  };

  // ClearanceTo's memory for one (exclude list, mask): bounds per link
  struct BoundsSlot {
    std::vector<std::int32_t> exclude_ids;
    const SampleMask* mask = nullptr;
    const RayCaster* against = nullptr;
    // how far the world has moved in all since the slot began
    // (LowerClearanceBounds): every bound is stored plus this sum as it was
    // then, so that lowering them all is one addition, not one per sample
    double lowered_m = 0;
    std::vector<ClearanceBounds> links;
  };
  BoundsSlot& SlotFor(std::span<const std::int32_t> exclude_object_ids, const SampleMask* mask,
                      const RayCaster* against);

  const RobotModel& model_;
  RayCaster& caster_;
  std::vector<int> link_body_;  // body index of each link in the caster (-1: no shapes)
  std::vector<LinkSamples> link_samples_;
  std::vector<BoundsSlot> bounds_slots_;  // the most recently used last
  std::vector<Pose> X_WL_;
  RayCaster::Nearby nearby_;  // ClearanceTo's scratch: the world's shapes near the link it measures
};

}  // namespace proxsim
