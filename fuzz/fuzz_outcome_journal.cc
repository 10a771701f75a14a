// libFuzzer target: an outcome study's journal lines (ParseOutcomeJob), as
// --resume reads OUT/journal.jsonl of a study with `mode: outcomes`: each
// line parsed as JSON, its "metrics" checked against a study of 2 runs per
// job. Any input gives exactly 2 runs whose numbers are in range (or NaN),
// or throws InputError (issue 40: a line saying reached_goal at t = -1e308
// was taken as a result).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "study/outcome_runner.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) {
    const nlohmann::json json = nlohmann::json::parse(line, nullptr, false);
    if (json.is_discarded() || !json.is_object() || !json.contains("metrics")) continue;
    try {
      const proxsim::OutcomeJob job = proxsim::ParseOutcomeJob(json["metrics"], 2, "job");
      if (job.runs.size() != 2 || !(job.hazard_m >= 0 && job.hazard_m <= 1e9)) __builtin_trap();
      for (const proxsim::OutcomeRun& run : job.runs)
        if (run.outcome_t_s < 0 || run.walked_m < 0 || run.straight_m < 0) __builtin_trap();
    } catch (const proxsim::InputError&) {
    }
  }
  return 0;
}
