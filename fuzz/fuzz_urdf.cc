// libFuzzer target: the URDF loader (RobotModel::FromUrdfText, urdfdom inside).
// Any input must either load or throw InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.h"
#include "robot/robot_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    proxsim::RobotModel::FromUrdfText(text, "fuzz.urdf");
  } catch (const proxsim::InputError&) {
  }
  return 0;
}
