// libFuzzer target: the URDF loader (RobotModel::FromUrdfText, urdfdom inside),
// and through it the mesh URIs (relative paths resolve from fuzz/corpus/urdf/, so
// the tests' tetrahedron.stl is found and read; package:// and file:// are looked up).
// Any input must either load or throw InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.h"
#include "robot/robot_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    proxsim::RobotModel::FromUrdfText(text, PROXSIM_SOURCE_DIR "/fuzz/corpus/urdf/fuzz.urdf");
  } catch (const proxsim::InputError&) {
  }
  return 0;
}
