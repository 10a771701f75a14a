// The small interface between a robot's motion source (the kinematic gait or a
// replayed trajectory) and the simulation loop: step it in time, read the
// robot's state, command it (stop, resume, stride, path) and start it afresh
// for a new episode. Strategies command it through strategy/RobotCommands.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "gait/terrain_query.h"
#include "knowledge/support_leg.h"
#include "robot/robot_model.h"

namespace proxsim {

/// The robot at one sample time.
struct RobotState {
  double t_s = 0;                   ///< sample time
  Pose X_WP = Pose::Identity();     ///< root link (pelvis) pose in the world
  std::vector<double> q;            ///< joint positions by joint index, rad (m for prismatic)
  double gait_phase = 0;            ///< left leg's phase in [0, 1), 0 at left heel strike
  SupportLeg support = SupportLeg::kDouble;
  bool stopped = false;             ///< standing still (commanded stop or end of path)
  double distance_walked_m = 0;     ///< path length of the pelvis on the floor since t = 0
};

/// A foot's contact points in its link frame, for what the robot knows of itself.
struct FootFrame {
  int link = -1;                 ///< the foot link
  Vec3 p_L_sole = Vec3::Zero();  ///< the sole point under the ankle
  Vec3 p_L_toe = Vec3::Zero();   ///< the sole's front end on the foot's centre line
  Vec3 p_L_heel = Vec3::Zero();  ///< its back end
  /// The sole's upward normal in the foot link frame: the root's z at the
  /// reference pose, whatever way the foot link's own frame is turned
  Vec3 up_L = Vec3::UnitZ();
};

/// One gait cycle as walked.
struct GaitCycle {
  double stride_m = 0;    ///< heel strike to heel strike of one foot
  double period_s = 0;    ///< the cycle's duration
  double max_step_m = 0;  ///< highest step up or down it takes on uneven ground
  double crouch_knee_rad = 0;  ///< the stance knee bend added to the curves (0: straight-kneed)
  double pelvis_height_m = 0;  ///< root link above the floor at heel strike on level ground, walking so
  double amplitude = 0;        ///< the curves' amplitude k for the stride (1: the normative adult walk)
  /// each foot's pitch at joint zero the gait walks flat (left, right; toe up
  /// positive): `legs.*.ankle_zero_deg` as given, or found from the sole's geometry
  std::array<double, 2> ankle_zero_rad{0, 0};
};

/// Something the motion noticed or decided (a step it cannot take), for
/// summary.json `robot.events`.
struct LocomotionEvent {
  std::string event;   ///< snake_case name: cannot_step, fall (a foot landed where it cannot stand)
  std::string detail;  ///< one line for a person
  std::optional<Vec3> p_W;  ///< where it happened, when a place is known (a fall: the middle of the sole at the foothold it missed, as planned)
  /// cannot_step: the step refused passes over level ground only, so the
  /// legs' own limits refused it (no gentler step fits either): the robot
  /// stands, whatever gait.unsafe_steps says — a planner's limit is not a fall
  bool level_ground = false;
};

/// What moves the robot. Advance() is called with non-decreasing times.
class Locomotion {
 public:
  virtual ~Locomotion() = default;
  /// Back to the state before the first Advance(): a new episode.
  virtual void Reset() = 0;
  /// The state at t_s (≥ the previous call's).
  virtual RobotState Advance(double t_s) = 0;
  /// Stop at the next double support and stand still there, both feet down.
  virtual void RequestStop() = 0;
  /// Walk again after a stop.
  virtual void Resume() = 0;
  /// Stride (heel strike to heel strike of one foot) to walk from the next step on, metres.
  virtual void SetStride(double stride_m) = 0;
  /// Replaces the rest of the path (world x-y); a motion that has no path ignores it.
  virtual void SetPath(std::vector<Vec2> waypoints_m) = 0;
  /// The feet, left then right; empty when the motion does not know them.
  virtual std::vector<FootFrame> Feet() const = 0;
  /// The stride and period being walked (after defaults and limits); nullopt
  /// for a motion without a gait cycle (a replayed trajectory).
  virtual std::optional<GaitCycle> gait_cycle() const { return std::nullopt; }
  /// The scene's true surface the feet stand on (null: a flat floor at the
  /// start height) and the terrain the footsteps are planned on (null: that
  /// true surface; else what the robot knows, `gait.footholds: map`, each
  /// landing then felt on the true surface); both must outlive the motion.
  /// Starts the episode afresh. A motion that does not plan footsteps ignores it.
  virtual void SetTerrain(const TerrainQuery* ground, const TerrainQuery* footholds = nullptr) {
    (void)ground;
    (void)footholds;
  }
  /// What happened since the last call, oldest first.
  virtual std::vector<LocomotionEvent> TakeEvents() { return {}; }
  virtual const RobotModel& model() const = 0;
};

}  // namespace proxsim
