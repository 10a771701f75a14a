// The `sensors` section: each sensor starts from the preset of its `type`
// (the paper's values, sensors/sensor_spec.h), any of range_m,
// max_incidence_deg and noise override it, and SensorSpec::Validate() has the
// last word; its problems are reported under the sensor's key path, at the
// line of the offending key.
#include <algorithm>
#include <map>
#include <set>

#include "io/nearest_key.h"
#include "io/scenario_sections.h"

namespace proxsim {

namespace {

std::string JoinNames(const std::vector<std::string>& names) {
  std::string all;
  for (const auto& name : names) all += (all.empty() ? "" : ", ") + name;
  return all;
}

// The node a key path like "noise.sigma" or "range_m[0]" names inside `sensor`,
// or the deepest enclosing node that exists. (Nodes are rebound with reset():
// assigning one yaml-cpp node to another would overwrite the document.)
YAML::Node NodeAtKeyPath(const YAML::Node& sensor, const std::string& key_path) {
  YAML::Node node;
  node.reset(sensor);
  std::size_t start = 0;
  while (start < key_path.size()) {
    const std::size_t end = key_path.find_first_of(".[]", start);
    const std::string part = key_path.substr(start, end == std::string::npos ? std::string::npos : end - start);
    start = end == std::string::npos ? key_path.size() : end + 1;
    if (part.empty()) continue;
    const YAML::Node& current = node;
    const bool is_index = std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (is_index && current.IsSequence() && std::stoul(part) < current.size()) {
      node.reset(current[std::stoul(part)]);
    } else if (!is_index && current.IsMap() && current[part].IsDefined()) {
      node.reset(current[part]);
    } else {
      break;
    }
  }
  return node;
}

// range_m: [min, max] with 0 <= min < max; false when the file's value is bad
bool ReadRange(YamlReader& reader, const Field& field, SensorSpec& spec) {
  if (!field) return true;
  const auto range = reader.Numbers(field, 2, AnyNumber(), "[min, max] in metres");
  if (!range) return false;
  const double min_m = (*range)[0];
  const double max_m = (*range)[1];
  if (!(min_m >= 0 && min_m < max_m)) {
    reader.Fail(field, "expected [min, max] with 0 <= min < max, got " + DescribeNode(field.node));
    return false;
  }
  spec.min_range_m = min_m;
  spec.max_range_m = max_m;
  return true;
}

// One sensor: preset, overrides, validation.
SensorConfig ReadSensor(YamlReader& reader, const MapView& map, bool has_robot) {
  SensorConfig sensor;
  const std::string& path = map.field().path;

  // type picks the preset
  const Field type = map["type"];
  if (reader.Require(type, "type, one of " + JoinNames(SensorTypeNames()))) {
    if (const auto name = reader.String(type)) {
      if (const auto sensor_type = SensorTypeFromName(*name)) {
        sensor.spec = SensorSpec::Preset(*sensor_type);
      } else {
        const auto nearest = NearestKey(*name, SensorTypeNames());
        reader.Fail(type, "unknown sensor type '" + *name + "' (" +
                              (nearest ? "did you mean '" + *nearest + "'? " : "") + "expected one of " +
                              JoinNames(SensorTypeNames()) + ")");
      }
    }
  }

  // overrides of the preset
  const bool range_valid = ReadRange(reader, map["range_m"], sensor.spec);
  sensor.spec.max_incidence_deg = reader.Number(map["max_incidence_deg"]).value_or(sensor.spec.max_incidence_deg);
  if (const auto noise = reader.Map(map["noise"], {"sigma", "mean"})) {
    sensor.spec.noise.sigma = reader.Number((*noise)["sigma"]).value_or(sensor.spec.noise.sigma);
    sensor.spec.noise.mean = reader.Number((*noise)["mean"]).value_or(sensor.spec.noise.mean);
  }

  // the spec's own checks, placed at the key they name (a bad range is already reported)
  for (const std::string& problem : sensor.spec.Validate()) {
    const std::size_t colon = problem.find(": ");
    const std::string key = colon == std::string::npos ? std::string() : problem.substr(0, colon);
    const std::string message = colon == std::string::npos ? problem : problem.substr(colon + 2);
    if (!range_valid && key.starts_with("range_m")) continue;
    reader.Fail(Field{NodeAtKeyPath(map.field().node, key), JoinPath(path, key), true}, message);
  }

  // where it is mounted
  const Field link = map["link"];
  sensor.link = reader.String(link).value_or(sensor.link);
  if (!has_robot && sensor.link != "world") {
    reader.Fail(link, "expected 'world' (the scenario has no robot section), got '" + sensor.link + "'");
  }
  sensor.X_LS = ReadPose(reader, map["pose"]);
  sensor.see_robot = reader.Bool(map["see_robot"]).value_or(sensor.see_robot);
  return sensor;
}

}  // namespace

std::vector<SensorConfig> ReadSensors(YamlReader& reader, const Field& field, bool has_robot) {
  std::vector<SensorConfig> sensors;
  const auto items = reader.List(field, "a list of sensors");
  if (!items) return sensors;
  std::map<std::string, std::string> name_origin;  // name -> key path of its first use
  for (const Field& item : *items) {
    const auto map = reader.Map(
        item, {"name", "type", "link", "pose", "range_m", "max_incidence_deg", "noise", "see_robot"},
        "a map with keys name, type, link, pose, range_m, max_incidence_deg, noise, see_robot");
    if (!map) continue;
    SensorConfig sensor = ReadSensor(reader, *map, has_robot);
    const Field name = (*map)["name"];
    if (reader.Require(name, "name, unique among the sensors")) {
      if (const auto text = reader.String(name)) {
        sensor.name = *text;
        const auto [previous, inserted] = name_origin.emplace(*text, item.path);
        if (!inserted) reader.Fail(name, "duplicate sensor name '" + *text + "' (already used by " + previous->second + ")");
      }
    }
    sensors.push_back(std::move(sensor));
  }
  return sensors;
}

}  // namespace proxsim
