// What a robot is made of, for a person placing sensors on it (`proxsim
// inspect`, docs/robots.md "Your own robot"): its links in tree order with
// their geometry and bounding boxes, its joints with their axes and limits,
// all at the reference pose — every joint at 0, the root link's frame at the
// world origin — and where a line through a link leaves its geometry (the
// front surface of a shank).
//
// Frames: W world (the root link's frame at the reference pose), L a link, O a
// shape in its link.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "robot/robot_model.h"

namespace proxsim {

/// An axis-aligned box, metres.
struct BoundingBox {
  Vec3 min_m = Vec3::Zero();
  Vec3 max_m = Vec3::Zero();
};

/// One link at the reference pose.
struct LinkSummary {
  int link = -1;                   ///< index in the model
  int depth = 0;                   ///< joints between it and the root
  std::string parent_joint;        ///< empty for the root
  std::vector<std::string> shapes; ///< "box", "sphere", "cylinder", "mesh FILE"; empty: no geometry
  std::optional<BoundingBox> box_L;  ///< its geometry in its own frame; none without geometry
  std::optional<BoundingBox> box_W;  ///< the same in the world at the reference pose
  double mass_kg = 0;
};

/// A robot at its reference pose.
struct RobotSummary {
  std::vector<LinkSummary> links;  ///< depth-first from the root, children in URDF order
  std::vector<int> joints;         ///< joint indices in the same tree order
  std::vector<Pose> X_WL;          ///< every link's pose, by link index
  std::vector<Pose> X_WJ;          ///< every joint's frame, by joint index
};

/// The robot at the reference pose (every joint 0, root at the origin).
RobotSummary SummarizeRobot(const RobotModel& model);

/// Bounding box of a link's geometry seen from frame F (X_FL: the link in F);
/// nullopt for a link without geometry. Curved shapes are bounded by their
/// outline points (scene/shape_points.h), within 0.05 % of a radius.
std::optional<BoundingBox> LinkBox(const RobotLink& link, const Pose& X_FL);

/// The farthest point along d_L (unit) where the line p_L + t·d_L leaves the
/// link's geometry: t in metres (either sign), nullopt when the line misses it.
std::optional<double> FarthestAlongLink_m(const RobotLink& link, const Vec3& p_L, const Vec3& d_L);

/// "revolute", "continuous", "prismatic" or "fixed".
const char* JointTypeName(JointType type);

}  // namespace proxsim
