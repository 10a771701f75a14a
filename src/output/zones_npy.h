// The zones of multi-zone sensors (sensors/multizone.h) as NumPy arrays:
// OUT/zones/SENSOR/ holds, over the sensor's own samples (none between them),
//   t_s.npy           float64 (samples,)                      the sample times
//   d_m.npy           float64 (samples, zones, targets)       distances, 0 without a target
//   status.npy        uint8   (samples, zones, targets)       ST's target status codes
//   target_count.npy  uint8   (samples, zones)                valid targets per zone
// and OUT/zones/columns.json describes each sensor's folder, shapes, the zone
// order and the status codes' names. Zone z is row z / nx, column z % nx, row
// 0 at the top and column 0 on the left as seen along the sensor's axis.
// numpy.load(OUT/zones/SENSOR/d_m.npy)[k, z, j] is target j of zone z at sample k.
#pragma once

#include <string>
#include <vector>

#include "output/npy_files.h"
#include "output/run_sink.h"
#include "scenario/scenario.h"

namespace proxsim {

class ZonesNpyWriter : public RunSink {
 public:
  /// Writes `out_dir`/zones/ for the scenario's multizone sensors (nothing without one).
  ZonesNpyWriter(const std::string& out_dir, const Scenario& scenario);

  /// Whether the scenario has a multizone sensor.
  static bool Needed(const Scenario& scenario);

  void Add(const SampleFrame& frame) override;
  void Commit() override;
  void AddToSummary(nlohmann::json& summary) const override;

 private:
  struct Sensor {
    std::size_t index;      // in the scenario
    std::string folder;     // under zones/
    int zones, targets;
    std::vector<double> t_s, d_m;
    std::vector<double> p_W;  // each target's measured point, x y z (NaN without a target)
    std::vector<std::uint8_t> status, target_count;
  };
  std::string dir_;
  const Scenario& scenario_;
  std::vector<Sensor> sensors_;
};

}  // namespace proxsim
