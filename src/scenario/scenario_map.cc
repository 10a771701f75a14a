// The `map` section: the terrain map's parameters, read by their declaration
// (TerrainMapSchema(), knowledge/terrain_config.h), every key optional. The map
// is built by a walking robot: a `map` section without a `robot` is a
// problem. Sensor names must be the scenario's (the nearest one suggested).
#include <algorithm>

#include "core/nearest_key.h"
#include "scenario/param_reader.h"
#include "scenario/scenario_sections.h"

namespace proxsim {

TerrainMapConfig ReadTerrainMap(YamlReader& reader, const Field& field, const std::vector<SensorConfig>& sensors,
                                bool has_robot) {
  TerrainMapConfig config;
  if (!field) return config;
  const auto map = OpenSection(reader, field, TerrainMapSchema());
  if (!map) return config;
  if (!has_robot) {
    reader.Fail(field, "the terrain map is built by a walking robot; expected a robot section with it");
  }
  ReadParams(reader, *map, TerrainMapSchema(), config);
  ReportAtKeys(reader, *map, config.Validate());

  // sensors: names of the scenario's sensors, each once
  const Field names_field = (*map)["sensors"];
  if (!names_field || !names_field.node.IsSequence()) return config;
  std::vector<std::string> known;
  for (const SensorConfig& sensor : sensors) known.push_back(sensor.name);
  std::vector<std::string> checked;
  for (std::size_t i = 0; i < names_field.node.size(); ++i) {
    const Field item{names_field.node[i], names_field.path + "[" + std::to_string(i) + "]", true};
    if (!item.node.IsScalar()) continue;  // reported as it was read
    const std::string name = item.node.Scalar();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      const auto nearest = NearestKey(name, known);
      std::string all;
      for (const std::string& k : known) all += (all.empty() ? "" : ", ") + k;
      reader.Fail(item, "unknown sensor '" + name + "'" + (nearest ? " (did you mean '" + *nearest + "'?)" : "") +
                            "; expected one of " + (all.empty() ? "none: the scenario has no sensors" : all));
      continue;
    }
    if (std::find(checked.begin(), checked.end(), name) != checked.end()) {
      reader.Fail(item, "sensor '" + name + "' is listed twice");
      continue;
    }
    checked.push_back(name);
  }
  config.sensors = checked;
  return config;
}

}  // namespace proxsim
