// The readings' sink for a format: readings.csv (the default) or the npy
// columns in readings/ — the one place the format is chosen.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "output/run_sink.h"
#include "scenario/scenario.h"

namespace proxsim {

/// How the readings are written: readings.csv, or one .npy per column in readings/.
enum class ReadingsFormat { kCsv, kNpy };

/// The sink writing a run's readings into `out_dir` in `format`.
std::unique_ptr<RunSink> MakeReadingsSink(ReadingsFormat format, const std::string& out_dir, const Scenario& scenario,
                                          std::vector<std::string> object_names);

}  // namespace proxsim
