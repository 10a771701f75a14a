#include "output/statistics_sink.h"

namespace proxsim {

StatisticsSink::StatisticsSink(const Scenario& scenario, std::vector<std::string> object_names)
    : object_names_(std::move(object_names)), statistics_(scenario.sensors.size()) {
  for (const SensorConfig& sensor : scenario.sensors) sensor_names_.push_back(sensor.name);
}

void StatisticsSink::Add(const SampleFrame& frame) {
  statistics_.Add(frame);
  for (const SensorSample& sample : frame.sensors) profile_points_ += sample.reading.detected() ? 1 : 0;
}

void StatisticsSink::AddToSummary(nlohmann::json& summary) const {
  summary["sensors"] = statistics_.ToJson(sensor_names_, object_names_);
  summary["profile_points"] = profile_points_;
}

}  // namespace proxsim
