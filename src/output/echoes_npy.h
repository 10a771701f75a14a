// The several echoes of beams with `echoes: strongest | all`
// (sensors/beam_echoes.h) as NumPy arrays: OUT/echoes/SENSOR/ holds, over the
// sensor's own samples (none between them),
//   t_s.npy     float64 (samples,)     the sample times
//   d_m.npy     float64 (samples, 4)   the echoes' reported distances, nearest first; NaN past the last echo
//   signal.npy  float64 (samples, 4)   each echo's signal (Σ weight × returned energy of its rays); NaN past it
//   count.npy   uint8   (samples,)     the echoes heard (at most 4)
// and OUT/echoes/columns.json describes each sensor's folder and the columns.
// readings.csv's row is the first echo (`first`, `all`) or the strongest.
#pragma once

#include <string>
#include <vector>

#include "output/run_sink.h"
#include "scenario/scenario.h"

namespace proxsim {

class EchoesNpyWriter : public RunSink {
 public:
  /// Writes `out_dir`/echoes/ for the scenario's sensors with several echoes.
  EchoesNpyWriter(const std::string& out_dir, const Scenario& scenario);

  /// Whether a sensor of the scenario reports several echoes.
  static bool Needed(const Scenario& scenario);

  void Add(const SampleFrame& frame) override;
  void Commit() override;
  void AddToSummary(nlohmann::json& summary) const override;

 private:
  struct Sensor {
    std::size_t index;   // in the scenario
    std::string folder;  // under echoes/
    std::vector<double> t_s, d_m, signal;
    std::vector<std::uint8_t> count;
  };
  std::string dir_;
  const Scenario& scenario_;
  std::vector<Sensor> sensors_;
};

}  // namespace proxsim
