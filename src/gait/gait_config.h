// What the gait needs to walk a robot: its pace, its legs, where it starts
// and where it goes. The scenario's robot section is this plus the model and
// the strategy (scenario/scenario.h); the gait reads nothing else.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry.h"

namespace proxsim {

struct GaitConfig {
  double stride_m = 0.6;  ///< distance between two heel strikes of the same foot, > 0
  double period_s = 1.2;  ///< duration of one gait cycle (a stride), > 0
  /// true: stride_m is not used; the gait scales the built-in biped's stride
  /// with the robot's leg length (the scenario gave no stride_m)
  bool derive_stride_from_legs = false;
  /// true: period_s is not used; the gait scales the built-in biped's period
  /// with the square root of the leg length (the scenario gave no period_s)
  bool derive_period_from_legs = false;
  /// highest step up or down the gait takes on uneven ground, m (> 0); 0:
  /// from the legs, the rise at which the landing knee bends 100 degrees
  double max_step_m = 0.0;
  /// `gait.touchdown_tolerance_m`: with footholds planned on what the robot
  /// knows, a foot landing lower than planned by more than this falls, m
  /// (gait/touchdown.h)
  double touchdown_tolerance_m = 0.02;
  /// `gait.keyframe`: a named pose of the model (an MJCF <key>, e.g. `home`):
  /// the gait walks with its knee bend (crouch) and holds every joint it does
  /// not drive at the key's angle (robot.joints_deg still overrides). Empty: none.
  std::string keyframe;
  /// `gait.crouch_knee_deg` in radians: the stance knee bend the gait walks
  /// with (gait/leg_kinematics.h, BipedLegs::SetCrouch), ≥ 0. Absent: the
  /// keyframe's, else 0 (the curves' straight-kneed human walk).
  std::optional<double> crouch_knee_rad;
};

/// One leg as the gait drives it (`robot.legs.left` / `.right`): the revolute
/// joints of its hip, knee and ankle pitch, and its foot link.
struct LegNames {
  std::string hip;
  std::string knee;
  std::string ankle;
  std::string foot;
  /// `legs.*.ankle_zero_deg` in radians: the foot's pitch at the reference
  /// pose (toe up +), for a foot whose sole is not flat at joint zero; the
  /// gait walks the sole flat (gait/leg_kinematics.h)
  double ankle_zero_rad = 0.0;
  /// ankle_zero_rad was given: without it, a foot whose sole is not flat at
  /// joint zero is read at the pitch its geometry lies flattest at
  bool ankle_zero_given = false;
};

/// A walk: the gait, the legs that take it, the start pose and the path.
struct WalkConfig {
  Vec3 start_xyz_m = Vec3::Zero();
  double start_yaw_rad = 0.0;
  GaitConfig gait;
  std::vector<Vec2> waypoints_m;  ///< path on the floor, world x-y; empty: straight ahead
  /// `robot.legs`: the gait's joints on this robot, left then right; absent:
  /// the built-in biped's (left_hip_pitch, left_knee_pitch, left_ankle_pitch, left_foot, ...)
  std::optional<std::array<LegNames, 2>> legs;
  /// `robot.joints_deg` in radians: joints the gait does not drive, held at
  /// these angles (every other one at 0), in the file's order
  std::vector<std::pair<std::string, double>> joints_rad;
};

}  // namespace proxsim
