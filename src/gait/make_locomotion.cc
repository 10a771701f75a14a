#include "gait/make_locomotion.h"

#include "gait/gait_walker.h"
#include "gait/trajectory_player.h"

namespace proxsim {

namespace {

constexpr const char* kBuiltinPrefix = "builtin:";

RobotModel LoadModel(const std::string& model) {
  if (model.starts_with(kBuiltinPrefix)) return RobotModel::Builtin(model.substr(std::string(kBuiltinPrefix).size()));
  return RobotModel::FromUrdfFile(model);
}

}  // namespace

std::unique_ptr<Locomotion> MakeLocomotion(const RobotConfig& config) {
  RobotModel model = LoadModel(config.model);
  if (!config.trajectory_file.empty()) {
    return std::make_unique<TrajectoryPlayer>(std::move(model), config.trajectory_file);
  }
  return std::make_unique<GaitWalker>(std::move(model), config);
}

}  // namespace proxsim
