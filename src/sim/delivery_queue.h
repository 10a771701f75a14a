// Sensor latency: a reading taken at sample k is delivered to the robot at
// its t_reported_s (the first sample at or after it). One ring per sensor
// holds the readings still in flight; between deliveries a sensor shows
// not_sampled.
#pragma once

#include <span>
#include <vector>

#include "scenario/scenario.h"
#include "sim/sample_frame.h"

namespace proxsim {

class DeliveryQueue {
 public:
  DeliveryQueue(std::span<const SensorConfig> sensors, double rate_hz);

  /// True when some sensor has a latency (otherwise what is taken is delivered at once).
  bool active() const { return active_; }

  /// Queues the readings of `taken` and writes into `delivered` what is due at taken.t_s.
  void Deliver(const SampleFrame& taken, SampleFrame& delivered);

  /// Drops every reading in flight (a new episode).
  void Clear();

 private:
  struct Pending {
    std::vector<SensorSample> ring;
    std::size_t head = 0;
    std::size_t count = 0;
  };
  bool active_ = false;
  std::vector<Pending> pending_;
};

}  // namespace proxsim
