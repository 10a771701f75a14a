#include "sim/run_statistics.h"

namespace proxsim {

RunStatistics::RunStatistics(std::size_t sensor_count) : sensors_(sensor_count) {}

void RunStatistics::Add(const SampleFrame& frame) {
  for (std::size_t i = 0; i < frame.sensors.size(); ++i) {
    const SensorSample& s = frame.sensors[i];
    if (s.reading.status == ReadingStatus::kNotSampled) continue;  // not one of the sensor's samples
    PerSensor& stats = sensors_[i];
    ++stats.samples;
    ++stats.by_status[static_cast<std::size_t>(s.reading.status)];
    // an object is credited with its own echoes only: a crosstalk reading is
    // another sensor's ping, and its truth columns (object, hit) are those of
    // the listener's own rays, which may have met nothing (object −1)
    if (s.reading.status == ReadingStatus::kOk && s.object_id >= 0) {
      ++stats.detections_by_object[s.object_id];
      stats.first_detection_t_s.try_emplace(s.object_id, frame.t_s);
    }
  }
}

std::int64_t RunStatistics::detections(std::size_t sensor) const {
  return sensors_.at(sensor).by_status[static_cast<std::size_t>(ReadingStatus::kOk)];
}

nlohmann::json RunStatistics::ToJson(const std::vector<std::string>& sensor_names,
                                     const std::vector<std::string>& object_names) const {
  nlohmann::json all = nlohmann::json::object();
  for (std::size_t i = 0; i < sensors_.size(); ++i) {
    const PerSensor& stats = sensors_[i];
    nlohmann::json by_status = nlohmann::json::object();
    for (std::size_t k = 0; k < kStatusCount; ++k) {
      if (static_cast<ReadingStatus>(k) == ReadingStatus::kNotSampled) continue;  // not a sample
      by_status[ReadingStatusName(static_cast<ReadingStatus>(k))] = stats.by_status[k];
    }
    nlohmann::json by_object = nlohmann::json::object();
    for (const auto& [id, count] : stats.detections_by_object) by_object[object_names.at(id)] = count;
    nlohmann::json first = nlohmann::json::object();
    for (const auto& [id, t_s] : stats.first_detection_t_s) first[object_names.at(id)] = t_s;
    all[sensor_names.at(i)] = {{"samples", stats.samples},
                               {"detections", stats.by_status[0]},
                               {"by_status", by_status},
                               {"detections_by_object", by_object},
                               {"first_detection_t_s", first}};
  }
  return all;
}

}  // namespace proxsim
