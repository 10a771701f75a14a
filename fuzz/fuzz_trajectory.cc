// libFuzzer target: the trajectory CSV reader (TrajectoryPlayer::FromCsvText)
// with the built-in biped, then a few samples of the playback.
// Any input must either load or throw InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.h"
#include "gait/trajectory_player.h"
#include "robot/robot_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const proxsim::RobotModel kBiped = proxsim::RobotModel::Builtin("biped");
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    auto player = proxsim::TrajectoryPlayer::FromCsvText(kBiped, text, "fuzz.csv");
    for (double t_s : {-1.0, 0.0, 0.01, 0.5, 1.0, 100.0}) player.Advance(t_s);
  } catch (const proxsim::InputError&) {
  }
  return 0;
}
