#include "sim/make_locomotion.h"

#include "gait/external_drive.h"
#include "gait/gait_walker.h"
#include "gait/trajectory_player.h"

namespace proxsim {

namespace {

constexpr const char* kBuiltinPrefix = "builtin:";

}  // namespace

RobotModel LoadRobotModel(const RobotConfig& config) {
  const UrdfOptions options{
      .geometry = config.geometry, .package_paths = config.package_paths, .geom_group = config.geom_group};
  if (config.model.starts_with(kBuiltinPrefix))
    return RobotModel::Builtin(config.model.substr(std::string(kBuiltinPrefix).size()), options);
  return RobotModel::FromFile(config.model, options);
}

std::unique_ptr<Locomotion> MakeLocomotion(const RobotConfig& config, double rate_hz) {
  RobotModel model = LoadRobotModel(config);
  if (config.locomotion == LocomotionSource::kExternal) {
    return std::make_unique<ExternalDrive>(std::move(model), config, rate_hz);
  }
  if (!config.trajectory_file.empty()) {
    return std::make_unique<TrajectoryPlayer>(std::move(model), config.trajectory_file);
  }
  return std::make_unique<GaitWalker>(std::move(model), config);
}

}  // namespace proxsim
