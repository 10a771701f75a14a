// libFuzzer target: a co-simulated robot's state (robot.locomotion:
// external), as Simulation::Step(state) takes it from a script or from
// MuJoCo. The input's bytes are the state (fuzz/cosim_state_input.h); the
// simulation is the built-in paper scenario driven from outside, built once,
// reset when its samples run out. Any state is taken or refused with
// InputError, never a crash or an unbounded allocation.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>

#include "core/input_error.h"
#include "cosim_state_input.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::unique_ptr<proxsim::Simulation> sim = [] {
    proxsim::Scenario scenario = proxsim::LoadBuiltinScenario("paper");
    scenario.robot->locomotion = proxsim::LocomotionSource::kExternal;
    return std::make_unique<proxsim::Simulation>(std::move(scenario), 1);
  }();
  if (sim->done()) sim->Reset(0);
  try {
    sim->Step(proxsim::FuzzedExternalState(std::string_view(reinterpret_cast<const char*>(data), size)));
  } catch (const proxsim::InputError&) {
  }
  return 0;
}
