#include "sim/make_locomotion.h"

#include <map>
#include <mutex>
#include <string>

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
  if (config.model.starts_with(kBuiltinPrefix)) {
    // a built-in model's text is part of the program: parsed once per
    // process and options (a study builds one per episode), then copied
    static std::mutex mutex;
    static std::map<std::string, RobotModel> parsed;
    std::string key = config.model + '\n' + std::to_string(static_cast<int>(options.geometry)) + '\n' +
                      std::to_string(options.geom_group);
    for (const std::string& path : options.package_paths) key += '\n' + path;
    {
      const std::lock_guard<std::mutex> lock(mutex);
      if (const auto found = parsed.find(key); found != parsed.end()) return found->second;
    }
    RobotModel model = RobotModel::Builtin(config.model.substr(std::string(kBuiltinPrefix).size()), options);
    const std::lock_guard<std::mutex> lock(mutex);
    parsed.emplace(key, model);
    return model;
  }
  // an MJCF the scenario read already, to take its scene: read with the same options, it is the same model
  if (config.model_read != nullptr && config.model_read_key == ModelReadKey(config)) return *config.model_read;
  return RobotModel::FromFile(config.model, options);
}

std::unique_ptr<Locomotion> MakeLocomotion(const RobotConfig& config, double rate_hz) {
  return MakeLocomotion(config, rate_hz, LoadRobotModel(config));
}

std::unique_ptr<Locomotion> MakeLocomotion(const RobotConfig& config, double rate_hz, RobotModel model) {
  if (config.locomotion == LocomotionSource::kExternal) {
    return std::make_unique<ExternalDrive>(std::move(model), config, rate_hz);
  }
  if (!config.trajectory_file.empty()) {
    return std::make_unique<TrajectoryPlayer>(std::move(model), config.trajectory_file);
  }
  return std::make_unique<GaitWalker>(std::move(model), config);
}

}  // namespace proxsim
