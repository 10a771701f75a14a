// The legs of a biped seen by the gait: each leg as a planar hip–knee–ankle
// chain in the pelvis's sagittal plane, its foot as a sole rectangle, read from
// a RobotModel that follows the biped convention of robot/robot_model.h
// (joints <side>_{hip,knee,ankle}_pitch about ±y, tibia and foot hanging along
// −z at q = 0, a box on each foot link). Planar forward and inverse kinematics
// in the pelvis frame P: a point is (x forward, z up); angles as in
// gait/gait_curves.h (hip flexion, knee flexion, foot pitch toe-up).
#pragma once

#include <array>
#include <string>

#include "core/geometry.h"
#include "gait/gait_curves.h"
#include "robot/robot_model.h"

namespace proxsim {

enum class Side { kLeft = 0, kRight = 1 };

/// A point in the pelvis sagittal plane: x forward, z up, metres.
using Vec2xz = Eigen::Vector2d;

struct LegGeometry {
  int hip_joint = -1, knee_joint = -1, ankle_joint = -1;
  int foot_link = -1;
  double hip_sign = 1, knee_sign = 1, ankle_sign = 1;  ///< q = sign × clinical angle
  Vec3 p_PH = Vec3::Zero();  ///< hip joint in the pelvis frame
  double thigh_m = 0.45;     ///< hip → knee
  double shank_m = 0.45;     ///< knee → ankle
  double heel_x_m = -0.06;   ///< sole rectangle in the foot frame (x), heel end
  double toe_x_m = 0.20;     ///< toe end
  double sole_z_m = -0.08;   ///< sole plane below the ankle
  double half_width_m = 0.05;
};

/// Where a foot touches: heel edge, sole point under the ankle, toe edge.
enum class FootPoint { kHeel, kMid, kToe };

/// Both legs of a biped model.
class BipedLegs {
 public:
  /// Throws InputError naming the model's source when it lacks the biped convention.
  explicit BipedLegs(const RobotModel& model);

  const LegGeometry& leg(Side s) const { return legs_[static_cast<int>(s)]; }

  /// Ankle in P for the hip/knee angles.
  Vec2xz Ankle(Side s, const LegAnglesRad& a) const;
  /// A foot point in P (its y is the hip's).
  Vec2xz Point(Side s, const LegAnglesRad& a, FootPoint which) const;
  /// Lowest z over the sole rectangle's corners, in P.
  double LowestSoleZ(Side s, const LegAnglesRad& a) const;
  /// Hip and knee (knee ≥ 0) putting the ankle at p_PA with the given foot
  /// pitch; out of reach, the leg points at the target as far as it goes.
  LegAnglesRad SolveAnkle(Side s, const Vec2xz& p_PA, double pitch) const;
  /// Foot-frame offset (x, z) of a foot point.
  Vec2xz FootOffset(Side s, FootPoint which) const;

  /// Writes the three pitch joints of a leg into q (by joint index).
  void WriteJoints(Side s, const LegAnglesRad& a, std::span<double> q) const;
  /// Reads them back.
  LegAnglesRad ReadJoints(Side s, std::span<const double> q) const;

 private:
  std::array<LegGeometry, 2> legs_;
};

/// Rotates a sagittal vector by a segment angle (positive: lower end forward / toe up).
inline Vec2xz RotateSagittal(double angle_rad, const Vec2xz& v) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return {v.x() * c - v.y() * s, v.x() * s + v.y() * c};
}

}  // namespace proxsim
