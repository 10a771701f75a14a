// Internal to io/: the readers of the scenario file's sections, one file each
// (scenario_scene.cc, scenario_robot.cc, scenario_sensors.cc), sharing the
// reader that collects problems. Each reads what it can, reports every
// problem it finds, and leaves defaults where a value was bad or absent; the
// caller throws if any problem was reported.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scenario/scenario.h"
#include "scenario/yaml_reader.h"

namespace proxsim {

/// `file` as written in the scenario, resolved against the scenario's folder
/// `base_dir` (empty: the current directory) unless it is absolute.
std::filesystem::path ResolveScenarioPath(const std::filesystem::path& base_dir, const std::string& file);

/// A `pose: {xyz_m, rpy_deg}` map (both optional, zeros by default); angles in
/// the file are degrees.
Pose ReadPose(YamlReader& reader, const Field& field);

/// An object's `motion: {waypoints_m, speed_m_s, mode, start_s | velocity_m_s |
/// trajectory}`; nullopt when absent or unreadable (after reporting).
std::optional<Motion> ReadMotion(YamlReader& reader, const Field& field, const std::filesystem::path& base_dir);

/// `person: {height_m}` (default 1.75 m).
double ReadPersonHeight(YamlReader& reader, const Field& field);

/// `scene: {builtin, objects}`: the built-in scene's objects, then the file's,
/// meshes loaded; object names unique across both.
void ReadScene(YamlReader& reader, const Field& field, const std::filesystem::path& base_dir, Scenario& scenario);

/// `robot: {model, start, gait, path, strategy, stop_distance_m, trajectory, ...}`; file paths resolved;
/// an MJCF model's world geoms added to `scene` (unless `model_scene: ignore`,
/// said in `from_model`); `start.on` must name an object of `scene`.
RobotConfig ReadRobot(YamlReader& reader, const Field& field, const std::filesystem::path& base_dir, Scene& scene,
                      SceneFromModel& from_model);

/// `strategy: {name: stop | circumvent, ...}`: the keys allowed depend on the
/// name; nullopt after reporting when the field is not one (an outcome study
/// reads its strategies with it).
std::optional<StrategyConfig> ReadStrategy(YamlReader& reader, const Field& field);

/// `sensors: [...]`: presets from `type`, overrides, SensorSpec::Validate();
/// without a robot, every link must be "world".
std::vector<SensorConfig> ReadSensors(YamlReader& reader, const Field& field, bool has_robot);

/// `map: {enabled, resolution_m, max_height_m, obstacle_min_m, drop_min_m,
/// step_max_m, step_min_size_m, sensors}`: the terrain map's parameters;
/// sensor names checked against `sensors`; a map needs a robot.
TerrainMapConfig ReadTerrainMap(YamlReader& reader, const Field& field, const std::vector<SensorConfig>& sensors,
                                bool has_robot);

}  // namespace proxsim
