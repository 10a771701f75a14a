#include "output/poses_csv.h"

#include "core/number_format.h"
#include "core/text_fields.h"

namespace proxsim {

PosesCsvWriter::PosesCsvWriter(const std::string& path, const RobotInScene& robot) : file_(path), robot_(robot) {
  file_.Write("t_s,link,x,y,z,qw,qx,qy,qz\n");
}

void PosesCsvWriter::Add(const SampleFrame& frame) {
  const RobotModel& model = robot_.model();
  const std::vector<Pose>& X_WL = robot_.X_WL();
  for (int link = 0; link < model.link_count(); ++link) {
    const Pose& X = X_WL[link];
    const Eigen::Quaterniond q(X.linear());
    line_.clear();
    AppendNumber(line_, frame.t_s);
    line_ += ',';
    AppendCsvField(line_, model.link_name(link));  // a URDF's link names may hold commas
    for (double value : {X.translation().x(), X.translation().y(), X.translation().z(), q.w(), q.x(), q.y(), q.z()}) {
      line_ += ',';
      AppendNumber(line_, value);
    }
    line_ += '\n';
    file_.Write(line_);
  }
}

}  // namespace proxsim
