// The files of `proxsim fidelity` (docs/fidelity.md#outputs), each written
// whole under a temporary name and renamed when complete:
//   fidelity.json        the inputs echoed and every table of statistics
//   fidelity_stats.csv   the same tables, one row per group
//   fidelity_pairs.csv   each recorded reading beside the model's
// The figure (fidelity.png) is drawn from these by report/fidelity_report.py.
#pragma once

#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fidelity/fidelity_config.h"
#include "fidelity/fidelity_replay.h"
#include "fidelity/fidelity_stats.h"
#include "fidelity/recording_csv.h"

namespace proxsim {

/// The JSON of the comparison: inputs and tables (NaN written as null).
nlohmann::json FidelityJson(const FidelityConfig& config, const Recording& recording, std::span<const FidelityRow> rows);

/// Writes the three files into the folder `dir` (which must exist).
void WriteFidelityOutputs(const std::string& dir, const FidelityConfig& config, const Recording& recording,
                          const ReplayedReadings& replayed, std::span<const ComparedReading> compared,
                          std::span<const FidelityRow> rows);

}  // namespace proxsim
