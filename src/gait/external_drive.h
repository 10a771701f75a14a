// Co-simulation (`robot.locomotion: external`, docs/cosimulation.md): the
// robot's state comes from another simulator each sample — MuJoCo's qpos,
// Isaac's root pose and joint positions — and proxsim only places the robot
// there and measures. The caller sets the state of the next sample (Set),
// then the simulation takes it (Advance); a sample without a state is our
// caller's bug (std::logic_error), a bad state is bad input (InputError).
//
// A state is checked before anything moves, every fault named at once: a
// joint missing or unknown, a value that is not finite, a joint outside its
// URDF limits (by more than kJointLimitSlack: MuJoCo's and Isaac's limits are
// soft constraints that a loaded joint passes a little), a quaternion that is
// not unit (within kUnitQuaternionTolerance) or a rotation matrix that is not
// one, and a jump from the last sample's state farther than a plausible motion
// in one sample period dt = 1 / rate_hz: the root link by more than
// kMaxRootSpeed_m_s · dt or turned by more than kMaxRootTurnRate_rad_s · dt, a
// joint by more than kMaxJointSpeed_rad_s · dt (m/s for a prismatic joint).
// The first sample of an episode has no last state: it may be anywhere.
//
// What a co-simulated robot reports of itself: support and gait phase as the
// caller gives them (double and 0 otherwise, as a replayed trajectory), standing
// still when its state did not change from the last sample, and the path
// length of its root on the floor. Commands (stop, stride, path) cannot move
// it: a stop is recorded (stop_requested()) for the caller to read, the rest
// is ignored. The feet are the gait's (robot.legs) when that map fits the
// model, so contacts with the ground are judged as for the gait; without
// them the ground is not checked, as for a replayed trajectory.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gait/locomotion.h"
#include "gait/gait_config.h"

namespace proxsim {

/// Plausible motion of a legged robot, per second; a state farther from the
/// last sample's than these allow in one sample period is refused.
constexpr double kMaxRootSpeed_m_s = 10.0;           ///< a sprint is ~10 m/s; a walk 1–2
constexpr double kMaxRootTurnRate_rad_s = 4 * kPi;   ///< two turns a second
constexpr double kMaxJointSpeed_rad_s = 40.0;        ///< rad/s, or m/s for a prismatic joint (motors: 10–25)
/// How far past its URDF limits a joint may be, rad (or m): soft limits.
constexpr double kJointLimitSlack = 0.01;
/// |‖q‖ − 1| allowed for a quaternion; the matrix test for a rotation: ‖RᵀR − I‖∞ and |det R − 1|.
constexpr double kUnitQuaternionTolerance = 1e-6;

/// The robot's state at one sample, as another simulator gives it.
struct ExternalState {
  Vec3 p_WP = Vec3::Zero();  ///< the root link's (pelvis') origin in the world, m
  /// Its orientation, exactly one of: a unit quaternion (w, x, y, z) — MuJoCo's
  /// free-joint qpos[3:7], Isaac's root_quat_w — or a rotation matrix (MuJoCo's xmat).
  std::optional<Eigen::Vector4d> quat_wxyz;
  std::optional<Rotation> R_WP;
  std::vector<double> q;                  ///< the moving joints in joint_names() order: rad, m for prismatic
  std::optional<double> gait_phase;       ///< the left leg's phase in [0, 1), when the caller has one
  std::optional<SupportLeg> support;      ///< the support leg, when the caller knows it
};

class ExternalDrive : public Locomotion {
 public:
  /// For `model`, sampled at `rate_hz`; its feet from `config`'s legs map
  /// (throws InputError when a map given in the scenario does not fit).
  ExternalDrive(RobotModel model, const WalkConfig& config, double rate_hz);

  /// The moving joints (every joint but the fixed ones), in the model's joint
  /// order: the order of ExternalState::q.
  const std::vector<std::string>& joint_names() const { return joint_names_; }

  /// ExternalState::q from joint values by name. Throws InputError naming
  /// every moving joint missing and every name that is not a moving joint.
  std::vector<double> JointVector(const std::vector<std::pair<std::string, double>>& q_by_name) const;

  /// Checks `state` as the state at sample time t_s and keeps it for the next
  /// Advance(). Throws InputError naming every fault (nothing is kept then).
  void Set(const ExternalState& state, double t_s);

  /// The state Set() gave; throws std::logic_error when none was set since the last call.
  RobotState Advance(double t_s) override;
  void RequestStop() override { stop_requested_ = true; }
  void Resume() override { stop_requested_ = false; }
  void SetStride(double) override {}
  void SetPath(std::vector<Vec2>) override {}
  std::vector<FootFrame> Feet() const override { return feet_; }
  void Reset() override;
  const RobotModel& model() const override { return model_; }

  /// A stop commanded (by a strategy or a script) and not resumed since: the caller's to obey.
  bool stop_requested() const { return stop_requested_; }

 private:
  // every fault of `state` against the model and the last state, for time t_s
  std::vector<std::string> Problems(const ExternalState& state, const Rotation& R_WP, double t_s) const;

  RobotModel model_;
  double dt_s_ = 0;
  std::vector<std::string> joint_names_;
  std::vector<int> joint_index_;  // joint_names_[i]'s index in the model
  std::vector<FootFrame> feet_;
  // the episode
  std::optional<RobotState> pending_;  // set, not yet taken
  std::optional<RobotState> last_;     // the last state taken
  bool stop_requested_ = false;
  double distance_m_ = 0;
};

}  // namespace proxsim
