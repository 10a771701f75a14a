// libFuzzer target: the scenario parser and validator (LoadScenarioText).
// Any input must either load or throw InputError; anything else (a crash, a
// sanitizer report, another exception, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.h"
#include "scenario/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // relative mesh and URDF paths resolve beside the test scenarios
    proxsim::LoadScenarioText(text, PROXSIM_SOURCE_DIR "/tests/data/scenarios/fuzz.yaml");
  } catch (const proxsim::InputError&) {
  }
  return 0;
}
