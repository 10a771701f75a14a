#include "gait/held_joints.h"

#include <cstdio>

#include "core/input_error.h"
#include "core/nearest_key.h"

namespace proxsim {

std::vector<double> HeldJointAngles(const RobotModel& model, std::span<const std::pair<std::string, double>> joints_rad,
                                    const std::array<LegNames, 2>& legs) {
  std::vector<double> q(model.joint_count(), 0.0);
  std::vector<std::string> problems, names;
  for (int j = 0; j < model.joint_count(); ++j) names.push_back(model.joint_name(j));
  for (const auto& [name, angle_rad] : joints_rad) {
    const std::string where = model.source() + ": robot.joints_deg." + name + ": ";
    const int j = model.JointIndex(name);
    if (j < 0) {
      const auto nearest = NearestKey(name, names);
      problems.push_back(where + "no joint '" + name + "' in the URDF" +
                         (nearest ? " (did you mean '" + *nearest + "'?)" : ""));
      continue;
    }
    const RobotJoint& joint = model.joint(j);
    if (joint.type != JointType::kRevolute && joint.type != JointType::kContinuous) {
      problems.push_back(where + "the joint is not revolute; only revolute and continuous joints hold an angle");
      continue;
    }
    bool driven = false;
    for (const LegNames& leg : legs) driven = driven || name == leg.hip || name == leg.knee || name == leg.ankle;
    if (driven) {
      problems.push_back(where + "the gait drives this joint (it is in robot.legs); hold only the others");
      continue;
    }
    if (joint.type == JointType::kRevolute && joint.lower < joint.upper &&
        (angle_rad < joint.lower - 1e-9 || angle_rad > joint.upper + 1e-9)) {
      char text[160];
      std::snprintf(text, sizeof text, "%.4g° is outside the joint's limits [%.4g°, %.4g°]", RadToDeg(angle_rad),
                    RadToDeg(joint.lower), RadToDeg(joint.upper));
      problems.push_back(where + text);
      continue;
    }
    q[j] = angle_rad;
  }
  if (!problems.empty()) throw InputError(problems);
  return q;
}

}  // namespace proxsim
