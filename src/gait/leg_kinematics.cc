#include "gait/leg_kinematics.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "core/input_error.h"

namespace proxsim {

namespace {

// A revolute joint about ±y with no rotation in its origin; returns the sign of its axis' y.
double PitchAxisSign(const RobotModel& m, int j, std::vector<std::string>* problems) {
  const RobotJoint& joint = m.joint(j);
  const bool ok = (joint.type == JointType::kRevolute || joint.type == JointType::kContinuous) &&
                  std::abs(std::abs(joint.axis_J.y()) - 1) < 1e-9 &&
                  joint.X_PJ.linear().isApprox(Rotation::Identity(), 1e-9);
  if (!ok) problems->push_back(m.source() + ": joint '" + joint.name + "' must be revolute about ±y with no origin rotation");
  return joint.axis_J.y() > 0 ? 1.0 : -1.0;
}

}  // namespace

BipedLegs::BipedLegs(const RobotModel& m) {
  std::vector<std::string> problems;
  for (const Side side : {Side::kLeft, Side::kRight}) {
    const std::string prefix = side == Side::kLeft ? "left_" : "right_";
    LegGeometry& g = legs_[static_cast<int>(side)];
    g.hip_joint = m.JointIndex(prefix + "hip_pitch");
    g.knee_joint = m.JointIndex(prefix + "knee_pitch");
    g.ankle_joint = m.JointIndex(prefix + "ankle_pitch");
    if (g.hip_joint < 0 || g.knee_joint < 0 || g.ankle_joint < 0) {
      problems.push_back(m.source() + ": the gait needs joints " + prefix + "hip_pitch, " + prefix +
                         "knee_pitch and " + prefix + "ankle_pitch");
      continue;
    }
    // hip and ankle flex about −y, the knee about +y (see robot_model.h)
    g.hip_sign = -PitchAxisSign(m, g.hip_joint, &problems);
    g.knee_sign = PitchAxisSign(m, g.knee_joint, &problems);
    g.ankle_sign = -PitchAxisSign(m, g.ankle_joint, &problems);
    if (m.joint(g.hip_joint).parent_link != m.root_link())
      problems.push_back(m.source() + ": " + prefix + "hip_pitch must hang from the root link");
    if (m.joint(g.knee_joint).parent_link != m.joint(g.hip_joint).child_link ||
        m.joint(g.ankle_joint).parent_link != m.joint(g.knee_joint).child_link)
      problems.push_back(m.source() + ": " + prefix + "hip, knee and ankle must form one chain");
    g.p_PH = m.joint(g.hip_joint).X_PJ.translation();
    const Vec3 knee = m.joint(g.knee_joint).X_PJ.translation();
    const Vec3 ankle = m.joint(g.ankle_joint).X_PJ.translation();
    if (knee.head<2>().norm() > 1e-9 || ankle.head<2>().norm() > 1e-9 || knee.z() >= 0 || ankle.z() >= 0)
      problems.push_back(m.source() + ": " + prefix + "knee and ankle origins must lie straight below (0 0 −L)");
    g.thigh_m = -knee.z();
    g.shank_m = -ankle.z();
    g.foot_link = m.joint(g.ankle_joint).child_link;
    // The sole: the lowest box on the foot link.
    bool found = false;
    for (const LinkShape& s : m.link(g.foot_link).shapes) {
      const Box* box = std::get_if<Box>(&s.shape);
      if (!box || !s.X_LO.linear().isApprox(Rotation::Identity(), 1e-9)) continue;
      const Vec3 o = s.X_LO.translation();
      const double sole = o.z() - box->size_m.z() / 2;
      if (found && sole >= g.sole_z_m) continue;
      found = true;
      g.sole_z_m = sole;
      g.heel_x_m = o.x() - box->size_m.x() / 2;
      g.toe_x_m = o.x() + box->size_m.x() / 2;
      g.half_width_m = box->size_m.y() / 2;
    }
    if (!found) problems.push_back(m.source() + ": link '" + m.link_name(g.foot_link) + "' needs an axis-aligned box as its sole");
    else if (g.heel_x_m >= 0 || g.toe_x_m <= 0 || g.sole_z_m >= 0)
      problems.push_back(m.source() + ": the sole box of '" + m.link_name(g.foot_link) + "' must reach behind and in front of the ankle, below it");
  }
  if (!problems.empty()) throw InputError(problems);
}

Vec2xz BipedLegs::Ankle(Side s, const LegAnglesRad& a) const {
  const LegGeometry& g = leg(s);
  const Vec2xz hip(g.p_PH.x(), g.p_PH.z());
  return hip + RotateSagittal(a.hip, {0, -g.thigh_m}) + RotateSagittal(a.hip - a.knee, {0, -g.shank_m});
}

Vec2xz BipedLegs::FootOffset(Side s, FootPoint which) const {
  const LegGeometry& g = leg(s);
  switch (which) {
    case FootPoint::kHeel: return {g.heel_x_m, g.sole_z_m};
    case FootPoint::kToe: return {g.toe_x_m, g.sole_z_m};
    case FootPoint::kMid: break;
  }
  return {0, g.sole_z_m};
}

Vec2xz BipedLegs::Point(Side s, const LegAnglesRad& a, FootPoint which) const {
  return Ankle(s, a) + RotateSagittal(a.pitch, FootOffset(s, which));
}

double BipedLegs::LowestSoleZ(Side s, const LegAnglesRad& a) const {
  return std::min(Point(s, a, FootPoint::kHeel).y(), Point(s, a, FootPoint::kToe).y());
}

LegAnglesRad BipedLegs::SolveAnkle(Side s, const Vec2xz& p_PA, double pitch) const {
  const LegGeometry& g = leg(s);
  const Vec2xz d = p_PA - Vec2xz(g.p_PH.x(), g.p_PH.z());
  const double lt = g.thigh_m, ls = g.shank_m;
  const double r = std::clamp(d.norm(), std::abs(lt - ls) + 1e-9, lt + ls);
  // law of cosines: r² = lt² + ls² + 2·lt·ls·cos(knee)
  const double cos_knee = std::clamp((r * r - lt * lt - ls * ls) / (2 * lt * ls), -1.0, 1.0);
  LegAnglesRad a;
  a.knee = std::acos(cos_knee);
  const double toward = std::atan2(d.x(), -d.y());  // hip→ankle line from the downward vertical
  a.hip = toward + std::atan2(ls * std::sin(a.knee), lt + ls * std::cos(a.knee));
  a.pitch = pitch;
  return a;
}

void BipedLegs::WriteJoints(Side s, const LegAnglesRad& a, std::span<double> q) const {
  const LegGeometry& g = leg(s);
  q[g.hip_joint] = g.hip_sign * a.hip;
  q[g.knee_joint] = g.knee_sign * a.knee;
  // ankle dorsiflexion = foot pitch − shank angle
  q[g.ankle_joint] = g.ankle_sign * (a.pitch - (a.hip - a.knee));
}

LegAnglesRad BipedLegs::ReadJoints(Side s, std::span<const double> q) const {
  const LegGeometry& g = leg(s);
  LegAnglesRad a;
  a.hip = q[g.hip_joint] / g.hip_sign;
  a.knee = q[g.knee_joint] / g.knee_sign;
  a.pitch = q[g.ankle_joint] / g.ankle_sign + (a.hip - a.knee);
  return a;
}

}  // namespace proxsim
