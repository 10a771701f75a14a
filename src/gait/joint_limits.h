// The URDF limits of the joints the gait drives (each leg's hip, knee and
// ankle pitch): the angle range <limit lower upper> and the top speed
// <limit velocity>, and what a leg pose or a motion between two poses needs
// beyond them. A continuous joint, or a revolute one whose lower is not below
// its upper, has no angle range; a velocity of 0 (not given) no speed limit.
//
// The gait asks these at load (gait/level_gait_check.h: a stride or period
// the legs cannot walk on level ground is an input error) and before every
// step (gait/step_safety.h: a step that would need more is not taken).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "gait/leg_kinematics.h"
#include "robot/robot_model.h"

namespace proxsim {

/// Angles this far beyond a limit still count as within it (the IK's rounding), rad.
constexpr double kLimitTolerance_rad = 1e-9;

/// One joint's limits, in its own URDF units (rad, rad/s).
struct JointLimit {
  int joint = -1;
  std::string name;
  bool has_range = false;
  double lower_rad = 0, upper_rad = 0;
  double velocity_rad_s = 0;  ///< 0: no speed limit
};

/// What a pose or a motion needs of a joint beyond its limit.
struct LimitExcess {
  std::string joint;
  bool speed = false;   ///< true: the top speed; false: the angle range
  double needed = 0;    ///< the angle (rad) or the speed (rad/s) needed
  double limit = 0;     ///< the limit it passes (lower or upper, or the top speed)
  /// One line for a person, degrees for angles: "joint 'left_knee_pitch' needs
  /// 152.3 deg, beyond its limit 137.5 deg" / "... needs 12.40 rad/s, beyond its
  /// velocity limit 8.00 rad/s".
  std::string Describe() const;
};

/// The limits of both legs' pitch joints.
class LegLimits {
 public:
  /// `legs` must outlive this.
  explicit LegLimits(const BipedLegs& legs);

  /// The hip, knee and ankle limits of a leg.
  const std::array<JointLimit, 3>& of(Side s) const { return limits_[static_cast<int>(s)]; }
  /// The leg's hip, knee and ankle joint values for gait angles `a` (rad).
  std::array<double, 3> JointValues(Side s, const LegAnglesRad& a) const;
  /// The joint of the leg furthest outside its angle range, if any.
  std::optional<LimitExcess> AngleExcess(Side s, const LegAnglesRad& a) const;
  /// The joint of the leg moving fastest beyond its top speed from `from` to
  /// `to` in dt_s (> 0), if any.
  std::optional<LimitExcess> SpeedExcess(Side s, const LegAnglesRad& from, const LegAnglesRad& to, double dt_s) const;
  /// The largest ratio of a joint's speed to its top speed from `from` to `to`
  /// in dt_s (0 when no joint has a speed limit).
  double SpeedRatio(Side s, const LegAnglesRad& from, const LegAnglesRad& to, double dt_s) const;

 private:
  const BipedLegs& legs_;
  std::array<std::array<JointLimit, 3>, 2> limits_;
};

}  // namespace proxsim
