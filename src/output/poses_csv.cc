#include "output/poses_csv.h"

#include <algorithm>

#include "core/number_format.h"
#include "core/text_fields.h"
#include "scene/motion.h"

namespace proxsim {

PosesCsvWriter::PosesCsvWriter(const std::string& path, const RobotInScene& robot) : file_(path), robot_(robot) {
  file_.Write("t_s,link,x,y,z,qw,qx,qy,qz\n");
}

void AppendPoseRow(std::string& line, double t_s, const std::string& name, const Pose& X) {
  const Eigen::Quaterniond q(X.linear());
  AppendNumber(line, t_s);
  line += ',';
  AppendCsvField(line, name);  // a URDF's link names may hold commas
  for (double value : {X.translation().x(), X.translation().y(), X.translation().z(), q.w(), q.x(), q.y(), q.z()}) {
    line += ',';
    AppendNumber(line, value);
  }
  line += '\n';
}

void PosesCsvWriter::Add(const SampleFrame& frame) {
  const RobotModel& model = robot_.model();
  const std::vector<Pose>& X_WL = robot_.X_WL();
  for (int link = 0; link < model.link_count(); ++link) {
    line_.clear();
    AppendPoseRow(line_, frame.t_s, model.link_name(link), X_WL[link]);
    file_.Write(line_);
  }
}

JointsCsvWriter::JointsCsvWriter(const std::string& path, const RobotModel& model, const RobotState& state)
    : file_(path), model_(model), state_(state), joints_(model.MovingJoints()) {
  file_.Write("t_s,joint,position\n");
}

void JointsCsvWriter::Add(const SampleFrame& frame) {
  line_.clear();
  for (const int joint : joints_) {
    AppendNumber(line_, frame.t_s);
    line_ += ',';
    AppendCsvField(line_, model_.joint_name(joint));
    line_ += ',';
    AppendNumber(line_, state_.q.at(joint));
    line_ += '\n';
  }
  file_.Write(line_);
}

bool ObjectPosesCsvWriter::Needed(const Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& o) { return o.motion.has_value(); });
}

ObjectPosesCsvWriter::ObjectPosesCsvWriter(const std::string& path, const Scene& scene) : file_(path), scene_(scene) {
  file_.Write("t_s,object,x,y,z,qw,qx,qy,qz\n");
}

void ObjectPosesCsvWriter::Add(const SampleFrame& frame) {
  line_.clear();
  for (const SceneObject& object : scene_.objects) {
    if (object.motion) AppendPoseRow(line_, frame.t_s, object.name, MotionPoseAt(*object.motion, frame.t_s));
  }
  file_.Write(line_);
}

}  // namespace proxsim
