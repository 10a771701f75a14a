// libFuzzer target: an outcome study file (LoadOutcomeStudyFile, the parser
// of `proxsim study` with `mode: outcomes`), written beside a base scenario
// and a ranking (fuzz/outcome_study_input.h). Any input loads or throws
// InputError; never a crash, a hang or a world of unbounded size.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/input_error.h"
#include "outcome_study_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    proxsim::LoadFuzzedOutcomeStudy(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const proxsim::InputError&) {
  }
  return 0;
}
