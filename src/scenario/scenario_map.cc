// The `map` section: the terrain map's parameters (knowledge/terrain_config.h),
// `map: {enabled, resolution_m, max_height_m, obstacle_min_m, drop_min_m,
// step_max_m, step_min_size_m, window_m, sensors: [names]}`, every key optional. The map
// is built by a walking robot: a `map` section without a `robot` is a
// problem. Sensor names must be the scenario's (the nearest one suggested).
#include <algorithm>

#include "core/nearest_key.h"
#include "scenario/scenario_sections.h"

namespace proxsim {

TerrainMapConfig ReadTerrainMap(YamlReader& reader, const Field& field, const std::vector<SensorConfig>& sensors,
                                bool has_robot) {
  TerrainMapConfig config;
  if (!field) return config;
  const auto map = reader.Map(field, {"enabled", "resolution_m", "max_height_m", "obstacle_min_m", "drop_min_m",
                                      "step_max_m", "step_min_size_m", "window_m", "truth_within_m", "sensors"});
  if (!map) return config;
  if (!has_robot) {
    reader.Fail(field, "the terrain map is built by a walking robot; expected a robot section with it");
  }
  config.enabled = reader.Bool((*map)["enabled"]).value_or(config.enabled);
  // the numbers as written; TerrainMapConfig::Validate() judges them, at their keys
  for (auto [key, value] : {std::pair{"resolution_m", &config.resolution_m}, std::pair{"max_height_m", &config.max_height_m},
                            std::pair{"obstacle_min_m", &config.obstacle_min_m}, std::pair{"drop_min_m", &config.drop_min_m},
                            std::pair{"step_max_m", &config.step_max_m}, std::pair{"step_min_size_m", &config.step_min_size_m},
                            std::pair{"window_m", &config.window_m}, std::pair{"truth_within_m", &config.truth_within_m}}) {
    *value = reader.Number((*map)[key], AnyNumber()).value_or(*value);
  }
  for (const std::string& problem : config.Validate()) {
    const std::string key = problem.substr(0, problem.find(": "));
    const Field at = map->Has(key) ? (*map)[key] : field;
    reader.Fail(at, problem.substr(key.size() + 2));
  }

  // sensors: names of the scenario's sensors, each once
  const Field names_field = (*map)["sensors"];
  if (!names_field) return config;
  const auto items = reader.List(names_field, "a list of sensor names");
  if (!items) return config;
  config.sensors_given = true;
  std::vector<std::string> known;
  for (const SensorConfig& sensor : sensors) known.push_back(sensor.name);
  for (const Field& item : *items) {
    const auto name = reader.String(item);
    if (!name) continue;
    if (std::find(known.begin(), known.end(), *name) == known.end()) {
      const auto nearest = NearestKey(*name, known);
      std::string all;
      for (const std::string& k : known) all += (all.empty() ? "" : ", ") + k;
      reader.Fail(item, "unknown sensor '" + *name + "'" + (nearest ? " (did you mean '" + *nearest + "'?)" : "") +
                            "; expected one of " + (all.empty() ? "none: the scenario has no sensors" : all));
      continue;
    }
    if (std::find(config.sensors.begin(), config.sensors.end(), *name) != config.sensors.end()) {
      reader.Fail(item, "sensor '" + *name + "' is listed twice");
      continue;
    }
    config.sensors.push_back(*name);
  }
  return config;
}

}  // namespace proxsim
