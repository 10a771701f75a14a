// Per-sensor tallies over a run, for summary.json: how many samples ended in
// each status, how many detections each object got, and when each object was
// first detected.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/sample_frame.h"

namespace proxsim {

class RunStatistics {
 public:
  explicit RunStatistics(std::size_t sensor_count);

  void Add(const SampleFrame& frame);

  /// {sensor name: {samples, by_status, detections_by_object, first_detection_t_s}}.
  nlohmann::json ToJson(const std::vector<std::string>& sensor_names,
                        const std::vector<std::string>& object_names) const;

  std::int64_t detections(std::size_t sensor) const;

 private:
  // one slot per status, the last one included (a status added to the enum
  // must get its slot: a reading's status indexes this array); not_sampled's
  // stays 0 and is not written out
  static constexpr std::size_t kStatusCount = static_cast<std::size_t>(ReadingStatus::kLast) + 1;
  struct PerSensor {
    std::int64_t samples = 0;
    std::array<std::int64_t, kStatusCount> by_status{};
    std::map<std::int32_t, std::int64_t> detections_by_object;
    std::map<std::int32_t, double> first_detection_t_s;
  };
  std::vector<PerSensor> sensors_;
};

}  // namespace proxsim
