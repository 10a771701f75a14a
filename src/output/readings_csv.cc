#include "output/readings_csv.h"

#include "core/number_format.h"

namespace proxsim {

const char* const kReadingsCsvHeader =
    "t_s,sensor,type,status,detected,d_m,d_true_m,incidence_deg,signal,"
    "hit_x_m,hit_y_m,hit_z_m,origin_x_m,origin_y_m,origin_z_m,dir_x,dir_y,dir_z,object,"
    "gait_phase,support_leg,ray,output,t_reported_s";

ReadingsCsvWriter::ReadingsCsvWriter(const std::string& path, const Scenario& scenario,
                                     std::vector<std::string> object_names)
    : file_(path), scenario_(scenario), object_names_(std::move(object_names)) {
  file_.Write(kReadingsCsvHeader);
  file_.Write('\n');
  line_.reserve(512);
}

void ReadingsCsvWriter::Append(const SampleFrame& frame) {
  for (std::size_t i = 0; i < frame.sensors.size(); ++i) {
    const SensorSample& s = frame.sensors[i];
    const SensorConfig& sensor = scenario_.sensors[i];
    if (s.reading.status == ReadingStatus::kNotSampled) continue;  // no row between a sensor's own samples
    const bool hit = s.object_id >= 0;
    line_.clear();
    AppendNumber(line_, frame.t_s);
    line_ += ',';
    line_ += sensor.name;
    line_ += ',';
    line_ += SensorTypeName(sensor.spec.type);
    line_ += ',';
    line_ += ReadingStatusName(s.reading.status);
    line_ += s.reading.detected() ? ",1," : ",0,";
    AppendNumber(line_, s.reading.d_m);
    line_ += ',';
    if (hit) AppendNumber(line_, s.echo.distance_m);
    line_ += ',';
    if (hit) AppendNumber(line_, s.echo.incidence_deg);
    line_ += ',';
    AppendNumber(line_, s.reading.signal);
    for (const Vec3* v : {&s.p_WH, &s.p_WS, &s.dir_W}) {
      for (int k = 0; k < 3; ++k) {
        line_ += ',';
        AppendNumber(line_, (*v)[k]);
      }
    }
    line_ += ',';
    if (hit) line_ += object_names_[s.object_id];
    line_ += ',';
    if (frame.robot.present) {
      AppendNumber(line_, frame.robot.gait_phase);
      line_ += ',';
      line_ += SupportLegName(frame.robot.support);
    } else {
      line_ += ',';
    }
    // beyond the paper: the beam's ray, a lookup sensor's output, the report time
    line_ += ',';
    line_ += std::to_string(s.ray);
    line_ += ',';
    AppendNumber(line_, s.reading.output);
    line_ += ',';
    AppendNumber(line_, s.t_reported_s);
    line_ += '\n';
    file_.Write(line_);
  }
}

}  // namespace proxsim
