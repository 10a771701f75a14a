#include "core/geometry.h"

#include <algorithm>
#include <cmath>

namespace proxsim {

Rotation RotationFromRpy(const Vec3& rpy_rad) {
  return (Eigen::AngleAxisd(rpy_rad.z(), Vec3::UnitZ()) *
          Eigen::AngleAxisd(rpy_rad.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(rpy_rad.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

Pose PoseFromXyzRpy(const Vec3& xyz_m, const Vec3& rpy_rad) {
  Pose X = Pose::Identity();
  X.linear() = RotationFromRpy(rpy_rad);
  X.translation() = xyz_m;
  return X;
}

Vec3 RpyFromRotation(const Rotation& R) {
  // R = Rz(y)Ry(p)Rx(r): R(2,0) = -sin p, R(2,1) = cos p sin r, R(2,2) = cos p cos r.
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  const double roll = std::atan2(R(2, 1), R(2, 2));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  return {roll, pitch, yaw};
}

}  // namespace proxsim
