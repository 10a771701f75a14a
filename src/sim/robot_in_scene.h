// The robot as part of the simulated world: its motion source (the gait or a
// replayed trajectory), its links as moving bodies in the ray caster (so a
// sensor on one tibia can see the other leg), the link poses at each sample,
// what the robot knows of itself (for strategies), and its true minimum
// clearance to the scene (for the summary, never for strategies).
//
// Frames: W world, P pelvis (the root link), L a link.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "gait/locomotion.h"
#include "io/scene_json.h"
#include "io/scenario.h"
#include "raycast/ray_caster.h"
#include "sim/stop_before_obstacle.h"

namespace proxsim {

class RobotInScene {
 public:
  /// Loads the robot and its motion; adds one body per link to `caster`, with
  /// object ids first_object_id + link index. Throws InputError on a bad robot.
  RobotInScene(const RobotConfig& config, RayCaster& caster, std::int32_t first_object_id);
  ~RobotInScene();

  /// Moves the robot to time t_s (non-decreasing) and its bodies with it; the
  /// caller commits the ray caster.
  void MoveTo(double t_s);

  const RobotState& state() const { return state_; }
  const Pose& X_WL(int link) const { return X_WL_[link]; }
  const std::vector<Pose>& X_WL() const { return X_WL_; }
  const RobotModel& model() const { return locomotion_->model(); }
  Locomotion& locomotion() { return *locomotion_; }

  /// Where the robot heads, its leading toe and its stance ground height, from its own kinematics.
  RobotSelfKnowledge SelfKnowledge() const;

  /// Least distance between the robot's surface (sampled every 2 cm) and any
  /// world object of its ray caster other than the excluded ones (the floor it
  /// walks on), when it is below `below_m`; otherwise some value >= below_m.
  /// Links and samples that cannot come closer are skipped, which keeps a
  /// running minimum cheap: each remembers a lower bound of its clearance from
  /// when it was last measured, valid while the world bodies stay as they are
  /// (the bounds start afresh when the exclude list differs from the last call's).
  double ClearanceTo(std::span<const std::int32_t> exclude_object_ids,
                     double below_m = std::numeric_limits<double>::infinity());

  /// Link shapes for scene.json.
  std::vector<LinkGeometryJson> LinkGeometry() const;

 private:
  struct LinkSamples {
    std::vector<Vec3> points_L;  // surface samples in the link frame
    Vec3 center_L = Vec3::Zero();
    double radius_m = 0;         // bounding sphere of the samples
  };
  // ClearanceTo's memory of a link: lower bounds of its samples' clearance,
  // each with the pose (or point) at which it holds
  struct ClearanceBounds {
    double link_lower_m = -std::numeric_limits<double>::infinity();  // no sample nearer, with the link at X_WL_ref
    Pose X_WL_ref = Pose::Identity();
    std::vector<double> point_lower_m;  // sample i no nearer than this when it was at p_W_ref[i]
    std::vector<Vec3> p_W_ref;
  };

  std::unique_ptr<Locomotion> locomotion_;
  RayCaster& caster_;
  std::vector<int> link_body_;  // body index of each link in the caster (-1: no shapes)
  std::vector<LinkSamples> link_samples_;
  // ClearanceTo's memory: bounds per link, and the exclude list they hold for
  std::vector<ClearanceBounds> clearance_bounds_;
  std::vector<std::int32_t> bounds_exclude_ids_;
  std::vector<int> foot_links_;
  RobotState state_;
  std::vector<Pose> X_WL_;
};

}  // namespace proxsim
