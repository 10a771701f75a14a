#include "sim/robot_knowledge.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace proxsim {

void KnowRobot(const RobotState& state, const RobotInScene& body, std::span<const FootFrame> feet,
               double half_width_m, RobotKnowledge& out) {
  out.X_WP = state.X_WP;
  out.q = state.q;
  out.gait_phase = state.gait_phase;
  out.support = state.support;
  out.stopped = state.stopped;
  out.distance_walked_m = state.distance_walked_m;
  out.half_width_m = half_width_m;
  // heading: the pelvis's +x, made horizontal
  Vec3 heading = state.X_WP.linear().col(0);
  heading.z() = 0;
  out.heading_W = heading.norm() > 1e-9 ? heading.normalized() : Vec3::UnitX();
  out.yaw_rad = std::atan2(out.heading_W.y(), out.heading_W.x());

  double front = -std::numeric_limits<double>::infinity();
  double lowest = std::numeric_limits<double>::infinity();
  const auto consider = [&](const Vec3& p_W, bool can_lead) {
    if (can_lead && p_W.dot(out.heading_W) > front) {
      front = p_W.dot(out.heading_W);
      out.p_W_front = p_W;
    }
    lowest = std::min(lowest, p_W.z());
  };
  out.has_feet = feet.size() == 2;
  if (out.has_feet) {
    // the feet's contact points: the ground is the lowest of soles and toes
    // (the stance foot's), the leading point the foremost toe
    for (std::size_t side = 0; side < 2; ++side) {
      const Pose& X_WL = body.X_WL(feet[side].link);
      FootKnowledge& foot = out.feet[side];
      foot.p_W_sole = X_WL * feet[side].p_L_sole;
      foot.p_W_toe = X_WL * feet[side].p_L_toe;
      foot.p_W_heel = X_WL * feet[side].p_L_heel;
      consider(foot.p_W_sole, false);
      consider(foot.p_W_toe, true);
    }
  } else {
    // no feet named: the whole robot's surface points stand in for them
    for (int link = 0; link < body.model().link_count(); ++link) {
      for (const Vec3& p_L : body.surface_points_L(link)) consider(body.X_WL(link) * p_L, true);
    }
  }
  out.ground_z_m = std::isfinite(lowest) ? lowest : 0.0;
  if (!std::isfinite(front)) out.p_W_front = state.X_WP.translation();
}

double ReferenceHalfWidth_m(const RobotInScene& body) {
  const RobotModel& model = body.model();
  const std::vector<double> q(model.joint_count(), 0.0);
  const std::vector<Pose> X_PL = model.ForwardKinematics(Pose::Identity(), q);
  double half_width_m = 0;
  for (int link = 0; link < model.link_count(); ++link) {
    for (const Vec3& p_L : body.surface_points_L(link)) half_width_m = std::max(half_width_m, std::abs((X_PL[link] * p_L).y()));
  }
  return half_width_m;
}

}  // namespace proxsim
