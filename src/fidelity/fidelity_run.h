// `proxsim fidelity FILE`: a part's model against a user's recording of it
// (docs/fidelity.md). The inputs are read and checked first (every problem
// at once, nothing written); the comparison then replays the recording
// through the model (fidelity_replay.h) and summarises the differences
// (fidelity_stats.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fidelity/fidelity_config.h"
#include "fidelity/fidelity_replay.h"
#include "fidelity/fidelity_stats.h"
#include "fidelity/recording_csv.h"

namespace proxsim {

struct FidelityInputs {
  FidelityConfig config;  ///< its sensor prepared for the replay (PrepareFidelitySensor)
  Recording recording;
};

/// Reads the fidelity file and its recording; `simulate_noise`, when given,
/// overrides the file's. Throws InputError listing every problem.
FidelityInputs LoadFidelityInputs(const std::string& path, std::optional<bool> simulate_noise);

struct FidelityComparison {
  ReplayedReadings replayed;
  std::vector<ComparedReading> compared;  ///< [sample · zone_count + zone]
  std::vector<FidelityRow> rows;          ///< FidelityTables(compared)
};

/// Each recorded reading beside the model's, with its zone's ring and its range band.
std::vector<ComparedReading> CompareReadings(const Recording& recording, const ReplayedReadings& replayed,
                                             const SensorSpec& spec, const std::vector<double>& band_edges_m);

/// Replays the recording on `threads` threads and summarises it.
FidelityComparison CompareFidelity(const FidelityInputs& inputs, int threads);

/// The summary printed at the end: the counts, then the rows of the tables
/// "all", "ring" and "band", one line each (with the confusion counts); the
/// zones' and the ring × band rows are in the files.
std::string FidelitySummary(const FidelityInputs& inputs, const FidelityComparison& comparison);

}  // namespace proxsim
