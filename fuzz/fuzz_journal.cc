// libFuzzer target: the study journal's line reader (ParseJournalLine), as
// --resume reads OUT/journal.jsonl: each line parsed as JSON, then checked
// against a study of 3 candidates, 2 hazards and 6 jobs. Any input must give
// metrics of exactly that shape or throw InputError (issue 23: a line with
// the wrong number of metrics once read out of bounds).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "study/study_journal.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const proxsim::JournalShape shape{6, 3, 2};
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) {
    const nlohmann::json json = nlohmann::json::parse(line, nullptr, false);
    if (json.is_discarded()) continue;
    try {
      const proxsim::JournalEntry entry = proxsim::ParseJournalLine(json, shape);
      if (entry.job >= shape.jobs || entry.metrics.size() != shape.candidates) __builtin_trap();
      for (const auto& m : entry.metrics)
        if (m.hazards.size() != shape.hazards) __builtin_trap();
    } catch (const proxsim::InputError&) {
    }
  }
  return 0;
}
