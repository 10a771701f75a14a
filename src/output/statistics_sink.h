// The run's counts as an output: per sensor, its samples by status, its
// detections by object and its first detection of each (summary.json
// `sensors`), and the profile's point count (`profile_points`). Written into
// the summary only; kept whether or not the run writes files.
#pragma once

#include <string>
#include <vector>

#include "output/run_sink.h"
#include "scenario/scenario.h"
#include "sim/run_statistics.h"

namespace proxsim {

class StatisticsSink : public RunSink {
 public:
  StatisticsSink(const Scenario& scenario, std::vector<std::string> object_names);

  void Add(const SampleFrame& frame) override;
  void AddToSummary(nlohmann::json& summary) const override;

 private:
  std::vector<std::string> sensor_names_, object_names_;
  RunStatistics statistics_;
  std::int64_t profile_points_ = 0;  // detections: the points profile.ply holds
};

}  // namespace proxsim
