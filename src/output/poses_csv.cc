#include "output/poses_csv.h"

#include "core/number_format.h"

namespace proxsim {

PosesCsvWriter::PosesCsvWriter(const std::string& path, const RobotModel& model) : file_(path), model_(model) {
  file_.Write("t_s,link,x,y,z,qw,qx,qy,qz\n");
}

void PosesCsvWriter::Append(double t_s, const std::vector<Pose>& X_WL) {
  for (int link = 0; link < model_.link_count(); ++link) {
    const Pose& X = X_WL[link];
    const Eigen::Quaterniond q(X.linear());
    line_.clear();
    AppendNumber(line_, t_s);
    line_ += ',';
    line_ += model_.link_name(link);
    for (double value : {X.translation().x(), X.translation().y(), X.translation().z(), q.w(), q.x(), q.y(), q.z()}) {
      line_ += ',';
      AppendNumber(line_, value);
    }
    line_ += '\n';
    file_.Write(line_);
  }
}

}  // namespace proxsim
