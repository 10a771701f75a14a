#include "gait/joint_limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace proxsim {

std::string LimitExcess::Describe() const {
  char text[240];
  if (speed) {
    std::snprintf(text, sizeof text, "joint '%s' needs %.2f rad/s, beyond its velocity limit %.2f rad/s",
                  joint.c_str(), needed, limit);
  } else {
    std::snprintf(text, sizeof text, "joint '%s' needs %.1f deg, beyond its limit %.1f deg", joint.c_str(),
                  RadToDeg(needed), RadToDeg(limit));
  }
  return text;
}

LegLimits::LegLimits(const BipedLegs& legs) : legs_(legs) {
  const RobotModel& model = legs.model();
  for (const Side side : {Side::kLeft, Side::kRight}) {
    const LegGeometry& g = legs.leg(side);
    const int joints[3] = {g.hip_joint, g.knee_joint, g.ankle_joint};
    for (int k = 0; k < 3; ++k) {
      const RobotJoint& joint = model.joint(joints[k]);
      JointLimit& limit = limits_[static_cast<int>(side)][k];
      limit.joint = joints[k];
      limit.name = joint.name;
      limit.has_range = joint.type == JointType::kRevolute && joint.lower < joint.upper;
      limit.lower_rad = joint.lower;
      limit.upper_rad = joint.upper;
      limit.velocity_rad_s = std::max(0.0, joint.velocity);  // (a negative URDF velocity: no limit)
    }
  }
}

std::array<double, 3> LegLimits::JointValues(Side s, const LegAnglesRad& a) const {
  // the same mapping that writes the robot's joints (BipedLegs::WriteJoints)
  return legs_.JointValues(s, a);
}

std::optional<LimitExcess> LegLimits::AngleExcess(Side s, const LegAnglesRad& a) const {
  const std::array<double, 3> q = JointValues(s, a);
  std::optional<LimitExcess> worst;
  double worst_by = kLimitTolerance_rad;
  for (int k = 0; k < 3; ++k) {
    const JointLimit& limit = of(s)[k];
    if (!limit.has_range) continue;
    const double below = limit.lower_rad - q[k], above = q[k] - limit.upper_rad;
    if (below > worst_by) {
      worst_by = below;
      worst = LimitExcess{limit.name, false, q[k], limit.lower_rad};
    }
    if (above > worst_by) {
      worst_by = above;
      worst = LimitExcess{limit.name, false, q[k], limit.upper_rad};
    }
  }
  return worst;
}

double LegLimits::SpeedRatio(Side s, const LegAnglesRad& from, const LegAnglesRad& to, double dt_s) const {
  const std::array<double, 3> q0 = JointValues(s, from), q1 = JointValues(s, to);
  double ratio = 0;
  for (int k = 0; k < 3; ++k) {
    const JointLimit& limit = of(s)[k];
    if (limit.velocity_rad_s > 0) ratio = std::max(ratio, std::abs(q1[k] - q0[k]) / dt_s / limit.velocity_rad_s);
  }
  return ratio;
}

std::optional<LimitExcess> LegLimits::SpeedExcess(Side s, const LegAnglesRad& from, const LegAnglesRad& to,
                                                  double dt_s) const {
  const std::array<double, 3> q0 = JointValues(s, from), q1 = JointValues(s, to);
  std::optional<LimitExcess> worst;
  double worst_ratio = 1;
  for (int k = 0; k < 3; ++k) {
    const JointLimit& limit = of(s)[k];
    if (!(limit.velocity_rad_s > 0)) continue;
    const double speed = std::abs(q1[k] - q0[k]) / dt_s;
    if (speed / limit.velocity_rad_s > worst_ratio) {
      worst_ratio = speed / limit.velocity_rad_s;
      worst = LimitExcess{limit.name, true, speed, limit.velocity_rad_s};
    }
  }
  return worst;
}

}  // namespace proxsim
