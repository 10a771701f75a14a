#include "robot/robot_inspect.h"

#include <functional>
#include <limits>

#include "scene/shape_inside.h"
#include "scene/shape_points.h"

namespace proxsim {

const char* JointTypeName(JointType type) {
  switch (type) {
    case JointType::kRevolute: return "revolute";
    case JointType::kContinuous: return "continuous";
    case JointType::kPrismatic: return "prismatic";
    case JointType::kFixed: return "fixed";
  }
  return "fixed";
}

std::optional<BoundingBox> LinkBox(const RobotLink& link, const Pose& X_FL) {
  BoundingBox box{Vec3::Constant(std::numeric_limits<double>::infinity()),
                  Vec3::Constant(-std::numeric_limits<double>::infinity())};
  bool any = false;
  for (const LinkShape& shape : link.shapes) {
    const Pose X_FO = X_FL * shape.X_LO;
    for (const Vec3& p_O : ShapeOutlinePoints_O(shape.shape)) {
      const Vec3 p_F = X_FO * p_O;
      box.min_m = box.min_m.cwiseMin(p_F);
      box.max_m = box.max_m.cwiseMax(p_F);
      any = true;
    }
  }
  if (!any) return std::nullopt;
  return box;
}

std::optional<double> FarthestAlongLink_m(const RobotLink& link, const Vec3& p_L, const Vec3& d_L) {
  std::optional<double> farthest;
  for (const LinkShape& shape : link.shapes) {
    const Pose X_OL = shape.X_LO.inverse();
    const auto t = FarthestAlongLine_m(shape.shape, X_OL * p_L, X_OL.linear() * d_L);
    if (t && (!farthest || *t > *farthest)) farthest = t;
  }
  return farthest;
}

RobotSummary SummarizeRobot(const RobotModel& model) {
  RobotSummary summary;
  const std::vector<double> q_zero(model.joint_count(), 0.0);
  summary.X_WL = model.ForwardKinematics(Pose::Identity(), q_zero);
  summary.X_WJ.resize(model.joint_count());
  for (int j = 0; j < model.joint_count(); ++j) {
    summary.X_WJ[j] = summary.X_WL[model.joint(j).parent_link] * model.joint(j).X_PJ;
  }
  // depth first from the root, children in the URDF's order
  const std::function<void(int, int)> visit = [&](int link, int depth) {
    const RobotLink& l = model.link(link);
    LinkSummary s;
    s.link = link;
    s.depth = depth;
    s.parent_joint = l.parent_joint >= 0 ? model.joint_name(l.parent_joint) : "";
    for (const LinkShape& shape : l.shapes) {
      const auto* mesh = std::get_if<Mesh>(&shape.shape);
      s.shapes.push_back(mesh ? "mesh " + mesh->file : ShapeKindName(shape.shape));
    }
    s.box_L = LinkBox(l, Pose::Identity());
    s.box_W = LinkBox(l, summary.X_WL[link]);
    s.mass_kg = l.mass_kg;
    summary.links.push_back(std::move(s));
    for (const int j : l.child_joints) {
      summary.joints.push_back(j);
      visit(model.joint(j).child_link, depth + 1);
    }
  };
  visit(model.root_link(), 0);
  return summary;
}

}  // namespace proxsim
