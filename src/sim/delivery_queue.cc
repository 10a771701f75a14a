#include "sim/delivery_queue.h"

#include <cmath>

namespace proxsim {

DeliveryQueue::DeliveryQueue(std::span<const SensorConfig> sensors, double rate_hz) {
  // a ring per sensor long enough for every reading still in flight
  pending_.resize(sensors.size());
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    const double latency_s = sensors[i].latency_s;
    if (latency_s > 0) active_ = true;
    pending_[i].ring.resize(static_cast<std::size_t>(std::ceil(latency_s * rate_hz)) + 2);
  }
}

void DeliveryQueue::Clear() {
  for (Pending& pending : pending_) {
    pending.head = 0;
    pending.count = 0;
  }
}

void DeliveryQueue::Deliver(const SampleFrame& taken, SampleFrame& delivered) {
  delivered.sample = taken.sample;
  delivered.t_s = taken.t_s;
  delivered.robot = taken.robot;
  delivered.sensors.resize(taken.sensors.size());
  for (std::size_t i = 0; i < taken.sensors.size(); ++i) {
    Pending& pending = pending_[i];
    const SensorSample& reading = taken.sensors[i];
    if (reading.reading.status != ReadingStatus::kNotSampled) {
      // the ring holds every reading still in flight (sized for the latency)
      pending.ring[(pending.head + pending.count) % pending.ring.size()] = reading;
      ++pending.count;
    }
    SensorSample& out = delivered.sensors[i];
    const SensorSample& oldest = pending.ring[pending.head];
    if (pending.count > 0 && oldest.t_reported_s <= taken.t_s + 1e-9) {
      out = oldest;
      pending.head = (pending.head + 1) % pending.ring.size();
      --pending.count;
    } else {
      out = SensorSample{};
      out.reading.status = ReadingStatus::kNotSampled;
      out.ray = -1;
    }
  }
}

}  // namespace proxsim
