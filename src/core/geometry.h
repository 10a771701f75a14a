// Geometry vocabulary shared by every module.
//
// Frames follow Drake's monogram notation: X_AB is the pose of frame B in frame
// A, p_AQ the position of point Q in A, R_AB a rotation. World W is x forward,
// y left, z up (REP-103). Orientations are roll-pitch-yaw as in URDF:
// R = Rz(yaw)·Ry(pitch)·Rx(roll).
#pragma once

#include <numbers>

#include <Eigen/Geometry>

namespace proxsim {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec3f = Eigen::Vector3f;
using Rotation = Eigen::Matrix3d;
using Pose = Eigen::Isometry3d;

constexpr double kPi = std::numbers::pi;
constexpr double DegToRad(double deg) { return deg * kPi / 180.0; }
constexpr double RadToDeg(double rad) { return rad * 180.0 / kPi; }

/// Rotation from URDF roll-pitch-yaw angles in radians: Rz(yaw)·Ry(pitch)·Rx(roll).
Rotation RotationFromRpy(const Vec3& rpy_rad);

/// Pose from a translation in metres and URDF roll-pitch-yaw in radians.
Pose PoseFromXyzRpy(const Vec3& xyz_m, const Vec3& rpy_rad);

/// Roll-pitch-yaw in radians of a rotation (the inverse of RotationFromRpy).
Vec3 RpyFromRotation(const Rotation& R);

}  // namespace proxsim
