#include "study/run_metrics.h"

#include <cmath>

#include "strategy/stop_strategy.h"

namespace proxsim {

bool NamesAHazard(const World& world, const std::string& prefix) {
  for (std::int32_t id = 0; id < world.first_robot_object_id(); ++id)
    if (world.object_name(id).starts_with(prefix)) return true;
  return false;
}

RunMetricsRecorder::RunMetricsRecorder(const Simulation& sim, const std::vector<std::string>& hazards)
    : sim_(sim) {
  const World& world = sim.world();
  hazard_of_object_.assign(world.object_names().size(), -1);
  ground_object_.assign(world.object_names().size(), false);
  for (std::int32_t id : world.ground_ids()) ground_object_[id] = true;
  const std::size_t sensors = sim.scenario().sensors.size();
  metrics_.assign(sensors, RunMetrics{});
  for (RunMetrics& m : metrics_) m.hazards.assign(hazards.size(), HazardResult{});
  // a hazard is every scene object (not a robot link) whose name starts with its prefix
  for (std::int32_t id = 0; id < world.first_robot_object_id(); ++id) {
    for (std::size_t h = 0; h < hazards.size(); ++h) {
      if (!world.object_name(id).starts_with(hazards[h])) continue;
      hazard_of_object_[id] = static_cast<int>(h);
      for (RunMetrics& m : metrics_) m.hazards[h].applies = true;
      break;
    }
  }
  self_.assign(sensors, 0);
  grazing_.assign(sensors, 0);
  floor_bins_.assign(sensors, {});
}

void RunMetricsRecorder::Add() {
  const SampleFrame& frame = sim_.frame();
  const Observation& observation = sim_.observation();
  const RobotKnowledge* self = observation.robot;
  const std::int64_t bin = self ? static_cast<std::int64_t>(self->distance_walked_m / kCoverageBin_m) : 0;
  bins_walked_ = std::max(bins_walked_, bin + 1);
  const StopConfig stop_rule;
  for (std::size_t i = 0; i < frame.sensors.size(); ++i) {
    const SensorSample& sample = frame.sensors[i];
    if (sample.reading.status == ReadingStatus::kNotSampled) continue;
    RunMetrics& m = metrics_[i];
    ++m.samples;
    self_[i] += sample.reading.status == ReadingStatus::kSelf;
    grazing_[i] += sample.reading.status == ReadingStatus::kGrazing;
    // a hazard is seen, and the floor covered, by the sensor's own echoes (a
    // crosstalk reading is another sensor's ping; its object is its own ray's)
    if (sample.reading.status != ReadingStatus::kOk) continue;
    const std::int32_t object = sample.object_id;
    const int hazard = HazardOf(object);
    if (hazard >= 0 && !m.hazards[hazard].detected && self != nullptr) {
      HazardResult& h = m.hazards[hazard];
      h.detected = true;
      h.first_t_s = frame.t_s;
      h.lead_m = (sample.p_WH - self->p_W_front).dot(self->heading_W);
    }
    if (object >= 0 && object < static_cast<std::int32_t>(ground_object_.size()) && ground_object_[object]) {
      auto& bins = floor_bins_[i];
      if (static_cast<std::int64_t>(bins.size()) <= bin) bins.resize(bin + 1, false);
      bins[bin] = true;
    }
  }
  // what the stop rule would take for an obstacle where there is none: the
  // delivered readings (latency applied), as the rule sees them
  if (self == nullptr) return;
  const SampleFrame& delivered = sim_.delivered();
  for (std::size_t i = 0; i < delivered.sensors.size(); ++i) {
    if (!IsObstacleAhead(observation.sensors[i], sim_.sensor_info()[i], *self, stop_rule)) continue;
    if (HazardOf(delivered.sensors[i].object_id) < 0) ++metrics_[i].false_alarms;
  }
}

int RunMetricsRecorder::HazardOf(std::int32_t object_id) const {
  return object_id >= 0 && object_id < static_cast<std::int32_t>(hazard_of_object_.size())
             ? hazard_of_object_[object_id]
             : -1;
}

std::vector<RunMetrics> RunMetricsRecorder::Finish() const {
  std::vector<RunMetrics> out = metrics_;
  const Simulation::Outcome outcome = sim_.outcome();
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double samples = static_cast<double>(std::max<std::int64_t>(out[i].samples, 1));
    out[i].self_share = self_[i] / samples;
    out[i].grazing_share = grazing_[i] / samples;
    std::int64_t covered = 0;
    for (bool b : floor_bins_[i]) covered += b;
    out[i].floor_coverage = bins_walked_ > 0 ? static_cast<double>(covered) / bins_walked_ : 0.0;
    out[i].outcome = outcome.kind;
    out[i].outcome_t_s = outcome.t_s;
  }
  return out;
}

}  // namespace proxsim
