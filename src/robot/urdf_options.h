// How a URDF is turned into a robot: which of a link's geometries stands for
// its surface, and where `package://` mesh URIs are looked for.
#pragma once

#include <string>
#include <vector>

namespace proxsim {

/// Which URDF geometry a link's surface is made of (`robot.geometry`).
enum class LinkGeometryKind {
  kVisual,     ///< <visual>: the surface a proximity sensor really sees (the default)
  kCollision,  ///< <collision>: the simplified shapes a physics engine uses
};

/// "visual" or "collision".
const char* LinkGeometryKindName(LinkGeometryKind kind);

/// Options of RobotModel::FromUrdfFile / FromUrdfText / FromMjcfFile / FromFile.
struct UrdfOptions {
  /// The geometry used; a link without any of that kind uses the other.
  LinkGeometryKind geometry = LinkGeometryKind::kVisual;
  /// Folders searched first for `package://NAME/...` (each is the package
  /// NAME itself or holds it as a direct subfolder), before ROS_PACKAGE_PATH
  /// and the URDF's own ancestor folders.
  std::vector<std::string> package_paths;
  /// MJCF only (`robot.geom_group`): the geom group (0–5) whose geoms are the
  /// links' surfaces; −1, every geom. MuJoCo Menagerie's models put their
  /// visual meshes in group 2 and their collision shapes in group 3.
  int geom_group = -1;
};

}  // namespace proxsim
