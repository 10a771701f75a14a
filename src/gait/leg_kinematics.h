// The legs of a biped seen by the gait, read from any URDF through a leg map
// (robot.legs: each leg's hip, knee and ankle pitch joints and its foot link).
// Nothing comes from names: at the reference pose (the gait's joints at 0,
// every other joint at its held angle) the model gives each pitch axis and
// its sign, the hip, knee and ankle points, the thigh and shank lengths in
// the sagittal plane and their angles from the vertical, and the sole: the
// lowest points of the foot link's geometry (and of the links hanging from
// it), whose front and back ends along x are the toe and the heel.
//
// Each leg is then a planar hip–knee–ankle chain in the pelvis's sagittal
// plane (x forward, z up) for the gait's planning and inverse kinematics, and
// its own chain of joints from the root for the exact 3D pose of the foot
// (which places the pelvis from a latched contact point, so that a planted
// foot stays planted even when a pitch axis is a few degrees off).
//
// Angles as in gait/gait_curves.h: thigh angle θT = hip flexion, shank angle
// θS = θT − knee, foot pitch ψ (toe up +), all 0 when standing straight. A
// pitch axis a = s·y_P (s = ±1, the sign) turns its segment by −s·q, so with
// θT0, θS0 the segments' angles at the reference pose:
//   q_hip = s_h·(θT0 − θT),  q_knee = s_k·(knee − (θT0 − θS0)),  q_ankle = s_a·(θS − θS0 − (ψ − ψ0)),
// ψ0 the foot's pitch at the reference pose (0 unless legs.*.ankle_zero_deg
// says the sole is pitched at joint zero: its geometry is then read turned
// flat about the ankle, and ψ = 0 is the sole flat).
//
// Frames: P pelvis (the root link; x forward, y left, z up), L the foot link.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "gait/gait_curves.h"
#include "gait/gait_config.h"
#include "robot/robot_model.h"

namespace proxsim {

enum class Side { kLeft = 0, kRight = 1 };

/// A point in the pelvis sagittal plane: x forward, z up, metres.
using Vec2xz = Eigen::Vector2d;

/// Largest angle between a pitch axis and the pelvis's y axis (the sagittal normal), degrees.
constexpr double kMaxPitchAxisTilt_deg = 5.0;

/// The built-in biped's leg map (the default of robot.legs).
std::array<LegNames, 2> BuiltinBipedLegs();

/// One leg at the reference pose, in the pelvis frame P.
struct LegGeometry {
  int hip_joint = -1, knee_joint = -1, ankle_joint = -1;
  int foot_link = -1;
  double hip_sign = 1, knee_sign = 1, ankle_sign = 1;  ///< s: each pitch axis is (about) s·y_P
  double thigh0_rad = 0;     ///< thigh angle θT0 from the downward vertical at the reference pose
  double shank0_rad = 0;     ///< shank angle θS0
  Vec3 p_PH = Vec3::Zero();  ///< hip pitch joint
  double thigh_m = 0;        ///< hip → knee, in the sagittal plane
  double shank_m = 0;        ///< knee → ankle
  double heel_x_m = 0;       ///< sole's back end, along x from the ankle joint
  double toe_x_m = 0;        ///< its front end
  double sole_z_m = 0;       ///< sole below the ankle joint (< 0)
  double sole_y_m = 0;       ///< y of the sole's centre line in P
  double half_width_m = 0;   ///< half the sole's width
  double foot0_rad = 0;      ///< ψ0: the foot's pitch at the reference pose (legs.*.ankle_zero_deg), toe up +
  double toe_top_m = 0;      ///< the foot's front face: its highest point at the toe's x, above the sole
  double heel_top_m = 0;     ///< its back face's, at the heel's x
  Vec3 p_L_heel = Vec3::Zero(), p_L_sole = Vec3::Zero(), p_L_toe = Vec3::Zero();  ///< in the foot link frame
  Vec3 up_L = Vec3::UnitZ();  ///< the sole's upward normal (P's z at the reference pose) in the foot link frame
  double leg_length_m = 0;   ///< hip joint above the sole, standing straight
  /// +1: the knee's URDF limits let it flex (knee > 0, the lower end moving
  /// back, as a human knee); −1: they let it bend the other way only
  double knee_bend = 1;
  /// The shank's links (from the knee joint down to the ankle joint) as one
  /// convex outline in the sagittal plane, counter-clockwise, in the shank's
  /// own frame: origin at the knee, the knee → ankle segment pointing down
  /// (gait/shank_clearance.h).
  std::vector<Vec2xz> shank_hull_S;
};

/// Where a foot touches: heel edge, sole point under the ankle, toe edge.
enum class FootPoint { kHeel, kMid, kToe };

/// Both legs of a biped model.
class BipedLegs {
 public:
  /// Reads the legs `names` (nullopt: the built-in biped's) from `model` at the
  /// reference pose `q_reference` (one value per joint: the held angles, 0 for
  /// the legs' pitch joints). Throws InputError naming the URDF, the map's key
  /// and why: a missing joint or link, a joint that is not revolute, joints not
  /// in hip → knee → ankle → foot order on one chain from the root, a pitch
  /// axis more than kMaxPitchAxisTilt_deg off the sagittal normal, a foot
  /// without geometry or whose sole does not reach behind and in front of the
  /// ankle, or legs that cannot reach the ground (zero-length segments, legs of
  /// unequal length, another link hanging below the soles). `model` must outlive this.
  BipedLegs(const RobotModel& model, const std::optional<std::array<LegNames, 2>>& names,
            std::span<const double> q_reference);
  /// The built-in map, every joint at 0.
  explicit BipedLegs(const RobotModel& model);

  const RobotModel& model() const { return model_; }
  const LegGeometry& leg(Side s) const { return legs_[static_cast<int>(s)]; }
  /// Mean of the legs' lengths (hip joint above the sole), m.
  double leg_length_m() const { return 0.5 * (legs_[0].leg_length_m + legs_[1].leg_length_m); }
  /// Pelvis above the floor when standing straight (the lower of the legs), m.
  double standing_height_m() const { return standing_height_m_; }

  /// Ankle in P for the hip/knee angles (sagittal plane).
  Vec2xz Ankle(Side s, const LegAnglesRad& a) const;
  /// A foot point in P (sagittal plane).
  Vec2xz Point(Side s, const LegAnglesRad& a, FootPoint which) const;
  /// The shank's outline (LegGeometry::shank_hull_S) in P (sagittal plane).
  std::vector<Vec2xz> ShankHull(Side s, const LegAnglesRad& a) const;
  /// Point(s, a, kHeel) and Point(s, a, kToe), the same values, the ankle
  /// and the pitch's rotation found once for both.
  std::array<Vec2xz, 2> HeelAndToe(Side s, const LegAnglesRad& a) const;
  /// Lowest z of the sole's heel and toe, in P.
  double LowestSoleZ(Side s, const LegAnglesRad& a) const;
  /// Hip and knee putting the ankle at p_PA with the given foot pitch, on the
  /// branch the knee's URDF limits allow (knee·knee_bend ≥ 0: a human knee
  /// flexes, never bends backward); out of reach, the leg points at the target
  /// as far as it goes. Whether the angles are within every limit is for
  /// gait/joint_limits.h to say: a target the branch cannot reach within them
  /// is reported there, never hidden by taking the other branch.
  LegAnglesRad SolveAnkle(Side s, const Vec2xz& p_PA, double pitch) const;
  /// `a` with its foot pitch moved, if it must be, to the nearest pitch at
  /// which the ankle joint is within its URDF limits (hip and knee unchanged:
  /// a swing foot in the air may tilt, the ankle's position does not depend on it).
  /// `margin_rad` > 0 keeps it that far inside them (never outside: narrower
  /// limits than the URDF's).
  LegAnglesRad PitchWithinAnkleLimits(Side s, const LegAnglesRad& a, double margin_rad = 0) const;
  /// Offset (x, z) of a foot point from the ankle at foot pitch 0.
  Vec2xz FootOffset(Side s, FootPoint which) const;

  /// The foot link's pose in P through the leg's own joint chain (exact, 3D).
  Pose FootPose_P(Side s, const LegAnglesRad& a) const;
  /// A foot point in P, exact (3D).
  Vec3 Point3(Side s, const LegAnglesRad& a, FootPoint which) const;
  /// A foot point in the foot link frame.
  const Vec3& FootPoint_L(Side s, FootPoint which) const;

  /// The leg's hip, knee and ankle joint values (rad) for gait angles `a`.
  std::array<double, 3> JointValues(Side s, const LegAnglesRad& a) const;
  /// Writes the three pitch joints of a leg into q (by joint index).
  void WriteJoints(Side s, const LegAnglesRad& a, std::span<double> q) const;
  /// Reads them back.
  LegAnglesRad ReadJoints(Side s, std::span<const double> q) const;

  /// The gait's crouch: a constant knee bend c (rad, ≥ 0) added to the curves
  /// while the foot's pitch is kept, the thigh leaning forward by c/2 and the
  /// shank back by c/2 (hip flexion +c/2, knee flexion +c, ankle dorsiflexion
  /// +c/2), so that a robot that stands and walks with bent knees (TALOS, the
  /// H1 under its own controllers) walks so here. 0: the curves as they are.
  void SetCrouch(double knee_rad) { crouch_knee_rad_ = knee_rad; }
  double crouch_knee_rad() const { return crouch_knee_rad_; }
  /// The normative curves at `phase` (gait/gait_curves.h, CurveLegAngles), with the crouch.
  LegAnglesRad Curve(double phase, double amplitude, double push_off_gain = 1.0) const {
    LegAnglesRad a = CurveLegAngles(phase, amplitude, push_off_gain);
    a.hip += 0.5 * crouch_knee_rad_;
    a.knee += crouch_knee_rad_;
    return a;
  }

  /// Every number the gait's planning reads from these legs, as bytes: both
  /// legs' geometry, the reference pose, and each chain joint's frame, axis,
  /// type and limits. Equal fingerprints plan equal steps (gait/gait_memo.h).
  std::string Fingerprint() const;

 private:
  const RobotModel& model_;
  std::array<LegGeometry, 2> legs_;
  std::array<std::vector<int>, 2> chain_;  // joints from the root to the foot link, parents first
  std::vector<double> q_reference_;
  double standing_height_m_ = 0;
  double crouch_knee_rad_ = 0;
};

/// Rotates a sagittal vector by an angle given by its cosine c and sine s
/// (for a caller that turns several vectors by one angle).
inline Vec2xz RotateSagittal(double c, double s, const Vec2xz& v) { return {v.x() * c - v.y() * s, v.x() * s + v.y() * c}; }
/// Rotates a sagittal vector by a segment angle (positive: lower end forward / toe up).
inline Vec2xz RotateSagittal(double angle_rad, const Vec2xz& v) {
  return RotateSagittal(std::cos(angle_rad), std::sin(angle_rad), v);
}

}  // namespace proxsim
