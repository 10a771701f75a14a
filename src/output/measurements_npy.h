// What parts report beside their reading (sensors/measurement.h: groups of
// ranked measurements) as NumPy arrays, one sink for both shapes, over each
// sensor's own samples (none between them):
//
// OUT/zones/SENSOR/ for multi-zone parts (sensors/multizone.h; a group is a
// zone, its ranks the part's targets):
//   t_s.npy           float64 (samples,)                      the sample times
//   d_m.npy           float64 (samples, zones, targets)       distances, 0 without a target
//   p_W.npy           float64 (samples, zones, targets, 3)    each target's measured point, NaN without one
//   status.npy        uint8   (samples, zones, targets)       ST's target status codes
//   target_count.npy  uint8   (samples, zones)                valid targets per zone
// Zone z is row z / nx, column z % nx, row 0 at the top and column 0 on the
// left as seen along the sensor's axis: numpy.load(.../d_m.npy)[k, z, j] is
// target j of zone z at sample k.
//
// OUT/echoes/SENSOR/ for beams with `echoes: strongest | all`
// (sensors/beam_echoes.h; one group, its ranks the echoes nearest first):
//   t_s.npy     float64 (samples,)     the sample times
//   d_m.npy     float64 (samples, 4)   the echoes' reported distances, nearest first; NaN past the last echo
//   signal.npy  float64 (samples, 4)   each echo's signal (Σ weight × returned energy of its rays); NaN past it
//   count.npy   uint8   (samples,)     the echoes heard (at most 4)
// readings.csv's row is the first echo (`first`, `all`) or the strongest.
//
// Each folder's columns.json describes its sensors' folders, the shapes and
// (zones) the zone order and the status codes' names.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "output/run_sink.h"
#include "scenario/scenario.h"

namespace proxsim {

class MeasurementsNpyWriter : public RunSink {
 public:
  /// Which parts, and which folder: zones/ or echoes/ (above).
  enum class Kind { kZones, kEchoes };

  /// Writes `out_dir`/zones/ or /echoes/ for the scenario's sensors of that kind.
  MeasurementsNpyWriter(const std::string& out_dir, const Scenario& scenario, Kind kind);

  /// Whether a sensor of the scenario reports measurements of that kind.
  static bool Needed(const Scenario& scenario, Kind kind);

  void Add(const SampleFrame& frame) override;
  void Commit() override;
  void AddToSummary(nlohmann::json& summary) const override;

 private:
  struct Sensor {
    std::size_t index;   // in the scenario
    std::string folder;  // under zones/ or echoes/
    int groups, ranks;   // a sample's slots: groups × ranks
    std::vector<double> t_s, d_m, signal, p_W;   // signal: echoes only; p_W (x y z per slot): zones only
    std::vector<std::uint8_t> code;              // the part's status code per slot: zones only
    std::vector<std::uint8_t> group_count;       // detections per group: zones only
    std::vector<std::uint8_t> count;             // measurements per sample: echoes only
  };
  Kind kind_;
  std::string dir_;
  const Scenario& scenario_;
  std::vector<Sensor> sensors_;
};

}  // namespace proxsim
