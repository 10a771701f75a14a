#include "gait/external_drive.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/input_error.h"
#include "core/input_limits.h"
#include "core/message_format.h"
#include "gait/held_joints.h"
#include "gait/leg_kinematics.h"

namespace proxsim {

namespace {

// The gait's feet on this model, or none when the built-in legs map does not fit it.
std::vector<FootFrame> FeetOf(const RobotModel& model, const WalkConfig& config) {
  try {
    const auto names = config.legs.value_or(BuiltinBipedLegs());
    const std::vector<double> q_held = HeldJointAngles(model, config.joints_rad, names);
    const BipedLegs legs(model, config.legs, q_held);
    std::vector<FootFrame> feet;
    for (const Side side : {Side::kLeft, Side::kRight}) {
      const LegGeometry& leg = legs.leg(side);
      feet.push_back({.link = leg.foot_link, .p_L_sole = leg.p_L_sole, .p_L_toe = leg.p_L_toe, .p_L_heel = leg.p_L_heel,
                     .up_L = leg.up_L});
    }
    return feet;
  } catch (const InputError&) {
    // a map the scenario gave must fit; the built-in one is only a guess
    if (config.legs) throw;
    return {};
  }
}

std::string Where(double t_s) { return FormatNumbers("robot state at t = %.4g s: ", t_s); }

}  // namespace

ExternalDrive::ExternalDrive(RobotModel model, const WalkConfig& config, double rate_hz)
    : model_(std::move(model)), dt_s_(1.0 / rate_hz) {
  joint_index_ = model_.MovingJoints();
  for (const int j : joint_index_) joint_names_.push_back(model_.joint_name(j));
  feet_ = FeetOf(model_, config);
}

std::vector<double> ExternalDrive::JointVector(const std::vector<std::pair<std::string, double>>& q_by_name) const {
  std::vector<std::string> problems;
  std::vector<double> q(joint_names_.size(), 0.0);
  std::vector<bool> given(joint_names_.size(), false);
  for (const auto& [name, value] : q_by_name) {
    const auto it = std::find(joint_names_.begin(), joint_names_.end(), name);
    if (it == joint_names_.end()) {
      problems.push_back("robot state: q: '" + name + "' is not a moving joint of robot '" + model_.name() + "'");
      continue;
    }
    const auto i = static_cast<std::size_t>(it - joint_names_.begin());
    q[i] = value;
    given[i] = true;
  }
  for (std::size_t i = 0; i < joint_names_.size(); ++i) {
    if (!given[i]) problems.push_back("robot state: q: joint '" + joint_names_[i] + "' is missing (every moving joint needs a value)");
  }
  if (!problems.empty()) throw InputError(problems);
  return q;
}

std::vector<std::string> ExternalDrive::Problems(const ExternalState& state, const Rotation& R_WP, double t_s) const {
  std::vector<std::string> problems;
  const std::string where = Where(t_s);
  if (!state.p_WP.allFinite()) {
    problems.push_back(where + "X_WP: the position is not finite");
  } else if (state.p_WP.cwiseAbs().maxCoeff() > kMaxCoordinate_m) {
    // as a scenario's coordinates: rays are cast in single precision, and the map's grid and
    // files span the robot's track (at 5e7 m the first step allocated 8.5 GB)
    problems.push_back(where + FormatNumbers("X_WP: the position (%.6g, %.6g, %.6g) m is beyond the coordinate limit of ",
                                             state.p_WP.x(), state.p_WP.y(), state.p_WP.z()) +
                       FormatNumbers("±%g m (rays are cast in single precision; docs/trust.md)", kMaxCoordinate_m));
  }
  if (state.quat_wxyz.has_value() == state.R_WP.has_value()) {
    problems.push_back(where + "X_WP: give the orientation once, as a quaternion (w, x, y, z) or a rotation matrix");
    return problems;
  }
  bool rotation_ok = true;
  if (state.quat_wxyz) {
    const double norm = state.quat_wxyz->norm();
    if (!std::isfinite(norm) || std::abs(norm - 1) > kUnitQuaternionTolerance) {
      rotation_ok = false;
      const Eigen::Vector4d& w = *state.quat_wxyz;
      problems.push_back(where + FormatNumbers("X_WP: the quaternion (w, x, y, z) = (%.6g, %.6g, %.6g, %.6g)", w[0], w[1], w[2], w[3]) +
                         FormatNumbers(" has norm %.9g; expected a unit quaternion (within %g)", norm, kUnitQuaternionTolerance));
    }
  } else {
    const double off = (R_WP.transpose() * R_WP - Rotation::Identity()).cwiseAbs().maxCoeff();
    const double det = R_WP.determinant();
    if (!R_WP.allFinite() || !(off <= kUnitQuaternionTolerance) || !(std::abs(det - 1) <= kUnitQuaternionTolerance)) {
      rotation_ok = false;
      problems.push_back(where + FormatNumbers("X_WP: the matrix is not a rotation (|R^T R - I| = %.3g, det R = %.9g); "
                                               "expected an orthonormal matrix with det 1 (within %g)",
                                               off, det, kUnitQuaternionTolerance));
    }
  }
  if (state.q.size() != joint_names_.size()) {
    problems.push_back(where + "q: " + std::to_string(state.q.size()) + " values, expected " +
                       std::to_string(joint_names_.size()) + " (one per moving joint, in the robot's joint order)");
    return problems;
  }
  if (state.gait_phase && !(*state.gait_phase >= 0 && *state.gait_phase < 1))
    problems.push_back(where + FormatNumbers("gait_phase %.6g is outside [0, 1)", *state.gait_phase));

  for (std::size_t i = 0; i < joint_names_.size(); ++i) {
    const RobotJoint& joint = model_.joint(joint_index_[i]);
    const double q = state.q[i];
    const char* unit = joint.type == JointType::kPrismatic ? "m" : "rad";
    if (!std::isfinite(q)) {
      problems.push_back(where + "joint '" + joint.name + "' is not a finite number");
      continue;
    }
    const bool limited = joint.type != JointType::kContinuous && joint.has_limits;
    if (limited && (q < joint.lower - kJointLimitSlack || q > joint.upper + kJointLimitSlack)) {
      problems.push_back(where + "joint '" + joint.name + "' = " + FormatNumbers("%.6g ", q) + unit +
                         " is outside its URDF limits " + FormatNumbers("[%.6g, %.6g] ", joint.lower, joint.upper) + unit);
    }
    if (last_ && std::abs(q - last_->q[joint_index_[i]]) > kMaxJointSpeed_rad_s * dt_s_) {
      problems.push_back(where + "joint '" + joint.name + "' jumped " +
                         FormatNumbers("%.6g ", std::abs(q - last_->q[joint_index_[i]])) + unit +
                         FormatNumbers(" since the last sample (%.4g s): more than the plausible %g ", dt_s_,
                                       kMaxJointSpeed_rad_s) +
                         unit + "/s allows");
    }
  }
  // the root's jump, from a valid pose only
  if (last_ && rotation_ok && state.p_WP.allFinite()) {
    const double moved_m = (state.p_WP - last_->X_WP.translation()).norm();
    if (moved_m > kMaxRootSpeed_m_s * dt_s_) {
      problems.push_back(where + FormatNumbers("X_WP: the root link jumped %.4g m since the last sample (%.4g s): more than "
                                               "the plausible %g m/s allows (%.4g m)",
                                               moved_m, dt_s_, kMaxRootSpeed_m_s, kMaxRootSpeed_m_s * dt_s_));
    }
    const double turned_rad = Eigen::AngleAxisd(last_->X_WP.linear().transpose() * R_WP).angle();
    if (turned_rad > kMaxRootTurnRate_rad_s * dt_s_) {
      problems.push_back(where + FormatNumbers("X_WP: the root link turned %.4g deg since the last sample (%.4g s): more "
                                               "than the plausible %g deg/s allows",
                                               RadToDeg(turned_rad), dt_s_, RadToDeg(kMaxRootTurnRate_rad_s)));
    }
  }
  return problems;
}

void ExternalDrive::Set(const ExternalState& state, double t_s) {
  Rotation R_WP = Rotation::Identity();
  if (state.R_WP) R_WP = *state.R_WP;
  if (state.quat_wxyz) {
    const Eigen::Vector4d& w = *state.quat_wxyz;
    const double norm = w.norm();
    if (norm > 0) R_WP = Eigen::Quaterniond(w[0] / norm, w[1] / norm, w[2] / norm, w[3] / norm).toRotationMatrix();
  }
  const std::vector<std::string> problems = Problems(state, R_WP, t_s);
  if (!problems.empty()) throw InputError(problems);
  RobotState s;
  s.t_s = t_s;
  s.X_WP = Pose::Identity();
  s.X_WP.linear() = R_WP;
  s.X_WP.translation() = state.p_WP;
  s.q.assign(model_.joint_count(), 0.0);
  for (std::size_t i = 0; i < joint_index_.size(); ++i) s.q[joint_index_[i]] = state.q[i];
  s.gait_phase = state.gait_phase.value_or(0.0);
  s.support = state.support.value_or(SupportLeg::kDouble);
  pending_ = std::move(s);
}

RobotState ExternalDrive::Advance(double t_s) {
  if (!pending_) throw std::logic_error("ExternalDrive::Advance: no robot state was set for this sample");
  RobotState s = std::move(*pending_);
  pending_.reset();
  s.t_s = t_s;
  // standing still: the very state of the last sample
  s.stopped = last_ && s.X_WP.matrix() == last_->X_WP.matrix() && s.q == last_->q;
  if (last_) distance_m_ += (s.X_WP.translation() - last_->X_WP.translation()).head<2>().norm();
  s.distance_walked_m = distance_m_;
  last_ = s;
  return s;
}

void ExternalDrive::Reset() {
  pending_.reset();
  last_.reset();
  stop_requested_ = false;
  distance_m_ = 0;
}

}  // namespace proxsim
