#include "robot_state.h"

#include <pybind11/numpy.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace proxsim {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string Repr(const py::handle& value) { return py::repr(value).cast<std::string>(); }

// a float argument or None
std::optional<double> OptionalNumber(const py::object& value, const char* name) {
  if (value.is_none()) return std::nullopt;
  try {
    return value.cast<double>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string("step: ") + name + ": expected a number or None, got " + Repr(value));
  }
}

}  // namespace

ExternalState ExternalStateFromPython(const ExternalDrive& drive, const py::object& q, const py::object& X_WP,
                                      const py::object& gait_phase, const py::object& support_leg) {
  ExternalState state;
  if (q.is_none() || X_WP.is_none()) {
    throw py::value_error("step: robot.locomotion is external: give the robot's state, step(q=..., X_WP=(xyz, quat_wxyz))");
  }
  // q: by name, or an array in the robot's joint order (sim.joint_names)
  if (py::isinstance<py::dict>(q)) {
    std::vector<std::pair<std::string, double>> named;
    for (const auto& [key, value] : q.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key)) throw py::type_error("step: q: expected joint names as keys, got " + Repr(key));
      try {
        named.emplace_back(key.cast<std::string>(), value.cast<double>());
      } catch (const py::cast_error&) {
        throw py::type_error("step: q['" + key.cast<std::string>() + "']: expected a number, got " + Repr(value));
      }
    }
    state.q = drive.JointVector(named);
  } else {
    const Array array(q);
    if (array.ndim() != 1) throw py::value_error("step: q: expected a dict {joint: value} or a 1-D array in sim.joint_names order");
    state.q.assign(array.data(), array.data() + array.size());
  }
  // X_WP: (xyz, quat_wxyz) or (xyz, R)
  if (!py::isinstance<py::sequence>(X_WP) || py::len(X_WP) != 2) {
    throw py::value_error("step: X_WP: expected (xyz, quat_wxyz) or (xyz, 3x3 rotation matrix), got " + Repr(X_WP));
  }
  const py::sequence pose = X_WP.cast<py::sequence>();
  const Array xyz(pose[0]), rotation(pose[1]);
  if (xyz.ndim() != 1 || xyz.size() != 3) throw py::value_error("step: X_WP: the position must be [x, y, z] in metres");
  state.p_WP = Vec3(xyz.at(0), xyz.at(1), xyz.at(2));
  if (rotation.ndim() == 1 && rotation.size() == 4) {
    state.quat_wxyz = Eigen::Vector4d(rotation.at(0), rotation.at(1), rotation.at(2), rotation.at(3));
  } else if (rotation.ndim() == 2 && rotation.shape(0) == 3 && rotation.shape(1) == 3) {
    Rotation R;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R(i, j) = rotation.at(i, j);
    state.R_WP = R;
  } else {
    throw py::value_error("step: X_WP: the orientation must be a quaternion [w, x, y, z] or a 3x3 rotation matrix");
  }
  state.gait_phase = OptionalNumber(gait_phase, "gait_phase");
  if (!support_leg.is_none()) {
    const std::string name = py::str(support_leg);
    const auto& names = SupportLegNames();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) throw py::value_error("step: support_leg: expected 'left', 'right', 'double' or None, got " + Repr(support_leg));
    state.support = static_cast<SupportLeg>(it - names.begin());
  }
  return state;
}

py::dict RobotStateDict(const RobotModel& model, const RobotState& state) {
  const std::vector<int> moving = model.MovingJoints();
  // a state never filled (before any sample) has no joints: refused, never read out of bounds
  for (const int j : moving) {
    if (j < 0 || static_cast<std::size_t>(j) >= state.q.size())
      throw std::runtime_error("robot_state: the robot has no state yet (no sample taken)");
  }
  py::array_t<double> xyz(3), quat(4), R({3, 3}), q(static_cast<py::ssize_t>(moving.size()));
  Eigen::Quaterniond rotation(state.X_WP.linear());
  if (rotation.w() < 0) rotation.coeffs() = -rotation.coeffs();  // one of the two: w >= 0
  const double wxyz[4] = {rotation.w(), rotation.x(), rotation.y(), rotation.z()};
  for (int k = 0; k < 3; ++k) xyz.mutable_at(k) = state.X_WP.translation()[k];
  for (int k = 0; k < 4; ++k) quat.mutable_at(k) = wxyz[k];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R.mutable_at(i, j) = state.X_WP.linear()(i, j);
  for (std::size_t i = 0; i < moving.size(); ++i) q.mutable_at(static_cast<py::ssize_t>(i)) = state.q[moving[i]];
  py::dict d;
  d["t_s"] = state.t_s;
  d["xyz"] = xyz;
  d["quat_wxyz"] = quat;
  d["R"] = R;
  d["q"] = q;
  d["gait_phase"] = state.gait_phase;
  d["support_leg"] = SupportLegName(state.support);
  d["stopped"] = state.stopped;
  d["distance_walked_m"] = state.distance_walked_m;
  return d;
}

}  // namespace proxsim
