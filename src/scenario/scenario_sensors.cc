// The `sensors` section (its keys: sensors/sensor_keys.cc): each sensor starts from the preset of its `type`
// (the paper's values, or a named part's, sensors/sensor_spec.h), any of
// range_m, max_incidence_deg, noise and the beyond-the-paper keys (beam,
// echo_model, echo_threshold, specular_exponent, use_material, lookup_table)
// override it, and SensorSpec::Validate() has the last word; its problems are
// reported under the sensor's key path, at the line of the offending key. The
// timing keys (rate_hz, latency_s, flight_time, wave_speed_m_s) belong to the
// SensorConfig.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>

#include "core/nearest_key.h"
#include "core/text_fields.h"
#include "sensors/distance_modes.h"
#include "sensors/multizone.h"
#include "sensors/sensor_keys.h"
#include "scenario/scenario_sections.h"

namespace proxsim {

namespace {

// A sensor's latency: milliseconds for real parts; 10 s is far beyond any of them.
constexpr double kMaxLatency_s = 10;

// the physics types and the named parts
const std::vector<std::string>& AllTypeNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = SensorTypeNames();
    all.insert(all.end(), SensorSpec::PartNames().begin(), SensorSpec::PartNames().end());
    return all;
  }();
  return names;
}

std::string JoinSensorNames(const std::vector<std::string>& names) {
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

// beam: {aperture_deg, rays, pattern: uniform | {gaussian: {width_deg}} | {table: [[angle_deg, gain], ...]}}
void ReadBeam(YamlReader& reader, const Field& field, SensorSpec& spec) {
  if (!field) return;
  const auto map = reader.Map(field, SensorKeyNames("beam"));
  if (!map) return;
  BeamSpec beam = spec.beam.value_or(BeamSpec{});
  if (reader.Require((*map)["aperture_deg"], "aperture_deg, the full cone angle in degrees")) {
    beam.aperture_deg = reader.Number((*map)["aperture_deg"]).value_or(beam.aperture_deg);
  }
  if (const auto rays = reader.Count((*map)["rays"])) beam.rays = static_cast<int>(std::min<std::uint64_t>(*rays, 1000000));
  const Field pattern = (*map)["pattern"];
  if (pattern && pattern.node.IsScalar()) {
    const auto name = reader.String(pattern);
    if (name && *name == "uniform") {
      beam.pattern = BeamPattern::kUniform;
    } else if (name) {
      reader.Fail(pattern, "expected uniform, {gaussian: {width_deg}} or {table: [[angle_deg, gain], ...]}, got '" + *name + "'");
    }
  } else if (pattern) {
    const auto kinds = reader.Map(pattern, {"gaussian", "table"},
                                  "uniform, {gaussian: {width_deg}} or {table: [[angle_deg, gain], ...]}");
    if (kinds && kinds->Has("gaussian") == kinds->Has("table")) {
      reader.Fail(pattern, "expected exactly one of gaussian, table, got " + DescribeNode(pattern.node));
    } else if (kinds && kinds->Has("gaussian")) {
      beam.pattern = BeamPattern::kGaussian;
      if (const auto gaussian = reader.Map((*kinds)["gaussian"], {"width_deg"})) {
        if (reader.Require((*gaussian)["width_deg"], "width_deg, the gaussian's standard deviation in degrees")) {
          beam.width_deg = reader.Number((*gaussian)["width_deg"]).value_or(beam.width_deg);
        }
      }
    } else if (kinds) {
      beam.pattern = BeamPattern::kTable;
      beam.table.clear();
      if (const auto rows = reader.List((*kinds)["table"], "a list of [angle_deg, gain] rows")) {
        for (const Field& row : *rows) {
          if (const auto values = reader.Numbers(row, 2, AnyNumber(), "[angle_deg, gain]")) {
            beam.table.push_back({(*values)[0], (*values)[1]});
          }
        }
      }
    }
  }
  // reach: [[d_m, half_angle_deg], ...] (checked by SensorSpec::Validate)
  if (const auto rows = reader.List((*map)["reach"], "a list of [d_m, half_angle_deg] rows")) {
    if (map->Has("reach")) beam.reach.clear();
    for (const Field& row : *rows) {
      if (const auto values = reader.Numbers(row, 2, AnyNumber(), "[d_m, half_angle_deg]")) {
        beam.reach.push_back({(*values)[0], (*values)[1]});
      }
    }
  }
  spec.beam = beam;
}

// lookup_table: [[distance_m, output, noise_fraction], ...]
void ReadLookupTable(YamlReader& reader, const Field& field, SensorSpec& spec) {
  if (!field) return;
  const auto rows = reader.List(field, "a list of [distance_m, output, noise_fraction] rows");
  if (!rows) return;
  spec.lookup_table.clear();
  for (const Field& row : *rows) {
    if (const auto values = reader.Numbers(row, 3, AnyNumber(), "[distance_m, output, noise_fraction]")) {
      spec.lookup_table.push_back({(*values)[0], (*values)[1], (*values)[2]});
    }
  }
}

// a [[reflectance, ambient_klux, value], ...] table (range_table, noise.sigma_table): a given list replaces the part's ([] turns it off)
void ReadAmbientTable(YamlReader& reader, const Field& field, const std::string& row_text,
                      std::vector<std::array<double, 3>>& table) {
  const auto rows = reader.List(field, "a list of " + row_text + " rows");
  if (!rows) return;
  if (field) table.clear();
  for (const Field& row : *rows) {
    if (const auto values = reader.Numbers(row, 3, AnyNumber(), row_text)) table.push_back({(*values)[0], (*values)[1], (*values)[2]});
  }
}

// zones: [nx, ny], fov_deg: [h, v], zone_rays, targets, target_separation_m, target_order, distance (multizone.h)
void ReadZones(YamlReader& reader, const MapView& map, SensorSpec& spec) {
  const bool given = map.Has("zones") || map.Has("fov_deg") || map.Has("zone_rays") || map.Has("targets") ||
                     map.Has("target_separation_m") || map.Has("target_order") || map.Has("distance");
  if (!given) return;
  ZoneSpec zones = spec.zones.value_or(ZoneSpec{});
  if (const auto grid = reader.Numbers(map["zones"], 2, PositiveNumber(""), "[nx, ny], whole numbers of zones")) {
    zones.nx = static_cast<int>(std::min((*grid)[0], 1e6));
    zones.ny = static_cast<int>(std::min((*grid)[1], 1e6));
    if (zones.nx != (*grid)[0] || zones.ny != (*grid)[1]) {
      reader.Fail(map["zones"], "expected whole numbers of zones [nx, ny], got " + DescribeNode(map["zones"].node));
    }
  }
  if (const auto fov = reader.Numbers(map["fov_deg"], 2, AnyNumber(), "[h, v] in degrees")) {
    zones.fov_h_deg = (*fov)[0];
    zones.fov_v_deg = (*fov)[1];
  }
  if (const auto rays = reader.Count(map["zone_rays"])) zones.rays_per_zone = static_cast<int>(std::min<std::uint64_t>(*rays, 1000));
  if (const auto targets = reader.Count(map["targets"])) zones.targets = static_cast<int>(std::min<std::uint64_t>(*targets, 1000));
  zones.target_separation_m = reader.Number(map["target_separation_m"]).value_or(zones.target_separation_m);
  if (const auto order = reader.String(map["target_order"])) {
    if (*order == "closest" || *order == "strongest")
      zones.strongest_first = *order == "strongest";
    else
      reader.Fail(map["target_order"], "expected closest or strongest (ST's target orders), got '" + *order + "'");
  }
  if (const auto distance = reader.String(map["distance"])) {
    if (*distance == "perpendicular" || *distance == "radial")
      zones.perpendicular = *distance == "perpendicular";
    else
      reader.Fail(map["distance"], "expected perpendicular (projected on the sensor's axis, as ST's parts report) or "
                                   "radial (along the zone's rays), got '" + *distance + "'");
  }
  spec.zones = zones;
}

// roi: [w, h] SPADs and timing_budget_ms (the VL53L1X's; checked by SensorSpec::Validate)
void ReadRoiAndBudget(YamlReader& reader, const MapView& map, SensorSpec& spec) {
  if (const auto roi = reader.Numbers(map["roi"], 2, AnyNumber(), "[w, h], SPADs of the receiver's array")) {
    for (int axis = 0; axis < 2; ++axis) {
      const double spads = (*roi)[static_cast<std::size_t>(axis)];
      if (spads != std::floor(spads) || !(std::abs(spads) < 1e6)) {
        reader.Fail(map["roi"], "expected whole numbers of SPADs [w, h], got " + DescribeNode(map["roi"].node));
        return;
      }
      spec.roi_spads[static_cast<std::size_t>(axis)] = static_cast<int>(spads);
    }
  }
  spec.timing_budget_ms = reader.Number(map["timing_budget_ms"]).value_or(spec.timing_budget_ms);
}

// what a rate above the part's limit breaks, naming the limit and its source
std::string RateLimitProblem(const SensorSpec& spec, const RateLimit& limit, double rate_hz) {
  if (rate_hz <= limit.max_hz) return "";
  char message[400];
  if (spec.zones) {
    std::snprintf(message, sizeof message,
                  "expected a ranging frequency of at most %g Hz for a %s at %dx%d zones (%s), got %g", limit.max_hz,
                  spec.part.c_str(), spec.zones->nx, spec.zones->ny, limit.source.c_str(), rate_hz);
  } else {
    std::snprintf(message, sizeof message, "expected at most %.4g Hz for a %s (%s), got %g", limit.max_hz,
                  spec.part.c_str(), limit.source.c_str(), rate_hz);
  }
  return message;
}

// fire: simultaneous | round_robin | an offset in seconds (round_robin's
// slots are given once every sensor is read: ResolveRoundRobin); crosstalk: bool
void ReadFiring(YamlReader& reader, const MapView& map, SensorConfig& sensor) {
  const Field crosstalk = map["crosstalk"];
  sensor.crosstalk = reader.Bool(crosstalk).value_or(sensor.crosstalk);
  if (crosstalk && sensor.spec.type != SensorType::kUltrasonic) {
    reader.Fail(crosstalk, std::string("expected no crosstalk key for a ") + SensorTypeName(sensor.spec.type) +
                               " sensor (ultrasonic sensors hear each other's pings), got one");
  }
  const Field fire = map["fire"];
  if (!fire) return;
  const auto text = reader.String(fire);
  if (!text) return;
  if (*text == "simultaneous" || *text == "round_robin") {
    sensor.fire = *text;
  } else if (char* end = nullptr; std::strtod(text->c_str(), &end), end != text->c_str() && *end == '\0') {
    const auto offset_s = reader.Number(fire, NonNegativeNumber("s"));
    if (!offset_s) return;  // reported by Number
    sensor.fire = *text;
    sensor.fire_offset_s = *offset_s;
  } else {
    reader.Fail(fire, "expected simultaneous, round_robin or an offset in seconds, got '" + *text + "'");
    return;
  }
  const bool has_rate = map.Has("rate_hz") || PartRateLimit(sensor.spec).max_hz > 0;
  if (sensor.fire != "simultaneous" && !has_rate) {
    reader.Fail(fire, "expected a rate_hz beside fire: " + sensor.fire +
                          " (the offset is within the sensor's period), got none");
  }
}

// round_robin sensors share their period out evenly, in file order; an
// offset must lie within the sensor's period
void ResolveFiring(YamlReader& reader, const std::vector<Field>& items, std::vector<SensorConfig>& sensors) {
  std::size_t round_robin_count = 0, slot = 0;
  for (const SensorConfig& sensor : sensors) round_robin_count += sensor.fire == "round_robin" ? 1 : 0;
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    SensorConfig& sensor = sensors[i];
    if (!(sensor.rate_hz > 0)) continue;  // reported by ReadFiring
    const double period_s = 1.0 / sensor.rate_hz;
    if (sensor.fire == "round_robin") {
      sensor.fire_offset_s = period_s * static_cast<double>(slot++) / static_cast<double>(round_robin_count);
    } else if (sensor.fire_offset_s >= period_s) {
      char message[200];
      std::snprintf(message, sizeof message, "expected an offset in [0, %g) s, within the sensor's period at %g Hz, got %g",
                    period_s, sensor.rate_hz, sensor.fire_offset_s);
      reader.Fail(Field{NodeAtKeyPath(items[i].node, "fire"), JoinPath(items[i].path, "fire"), true}, message);
    }
  }
}

// the sensor's own sampling and the echo's flight
void ReadTiming(YamlReader& reader, const MapView& map, SensorConfig& sensor) {
  sensor.rate_hz = reader.Number(map["rate_hz"], PositiveNumber("Hz")).value_or(sensor.rate_hz);
  // bounded: the readings in flight (latency × rate of them) are held in memory (1e5 s once took 2.75 GB)
  const NumberRule latency{.min = 0, .max = kMaxLatency_s, .expected = "a latency in [0, 10] s (the readings in flight "
                                                                        "are held in memory; docs/trust.md)"};
  sensor.latency_s = reader.Number(map["latency_s"], latency).value_or(sensor.latency_s);
  sensor.wave_speed_m_s = reader.Number(map["wave_speed_m_s"], PositiveNumber("m/s")).value_or(sensor.wave_speed_m_s);
  const Field flight = map["flight_time"];
  sensor.flight_time = reader.Bool(flight).value_or(sensor.flight_time);
  if (sensor.flight_time && !IsTimeOfFlight(sensor.spec.type)) {
    reader.Fail(flight, std::string("expected false for a ") + SensorTypeName(sensor.spec.type) +
                            " sensor (flight_time applies to the time-of-flight types), got true");
  }
  sensor.spec.echo_timeout_s =
      reader.Number(map["echo_timeout_s"], NonNegativeNumber("s")).value_or(sensor.spec.echo_timeout_s);
  ReadFiring(reader, map, sensor);
  // a part samples no faster than its datasheet allows, by default at that limit
  if (const RateLimit limit = PartRateLimit(sensor.spec); limit.max_hz > 0) {
    if (!map.Has("rate_hz")) sensor.rate_hz = limit.max_hz;
    if (const std::string problem = RateLimitProblem(sensor.spec, limit, sensor.rate_hz); !problem.empty()) {
      reader.Fail(map["rate_hz"], problem);
    }
  }
}

// One sensor: preset, overrides, validation.
SensorConfig ReadSensor(YamlReader& reader, const MapView& map, bool has_robot) {
  SensorConfig sensor;
  const std::string& path = map.field().path;

  // type picks the preset
  const Field type = map["type"];
  if (reader.Require(type, "type, one of " + JoinSensorNames(AllTypeNames()))) {
    if (const auto name = reader.String(type)) {
      if (const auto sensor_type = SensorTypeFromName(*name)) {
        sensor.spec = SensorSpec::Preset(*sensor_type);
      } else if (const auto part = SensorSpec::PartPreset(*name)) {
        sensor.spec = *part;
      } else {
        const auto nearest = NearestKey(*name, AllTypeNames());
        reader.Fail(type, "unknown sensor type '" + *name + "' (" +
                              (nearest ? "did you mean '" + *nearest + "'? " : "") + "expected one of " +
                              JoinSensorNames(AllTypeNames()) + ")");
      }
    }
  }

  // a part's distance mode presets its range and its tables (distance_modes.h),
  // scaled by its region of interest and timing budget (vl53l1x_settings.h)
  ReadRoiAndBudget(reader, map, sensor.spec);
  const DistanceMode* mode_found = FindDistanceMode(sensor.spec.part, sensor.spec.distance_mode);
  if (const Field mode = map["distance_mode"]; mode) {
    if (const auto name = reader.String(mode)) {
      const std::string part = sensor.spec.part.empty() ? SensorTypeName(sensor.spec.type) : sensor.spec.part;
      if (const DistanceMode* found = FindDistanceMode(sensor.spec.part, *name)) {
        mode_found = found;
      } else if (DistanceModeNames(sensor.spec.part).empty()) {
        reader.Fail(mode, "expected no distance_mode for a " + part + " (only the vl53l1x has distance modes: " +
                              DistanceModeNames("vl53l1x") + ", " + kDistanceModeSource + "), got '" + *name + "'");
      } else {
        reader.Fail(mode, "expected one of " + DistanceModeNames(sensor.spec.part) + " for a " + part + " (" +
                              kDistanceModeSource + "), got '" + *name + "'");
      }
    }
  }
  if (mode_found != nullptr) ApplyDistanceMode(*mode_found, sensor.spec);
  // a multi-zone part's grid, and its datasheet's tables at that resolution
  ReadZones(reader, map, sensor.spec);
  if (map.Has("zones")) ApplyMultizonePartTables(sensor.spec);

  // overrides of the preset
  const bool range_valid = ReadRange(reader, map["range_m"], sensor.spec);
  sensor.spec.max_incidence_deg = reader.Number(map["max_incidence_deg"]).value_or(sensor.spec.max_incidence_deg);
  if (const auto noise = reader.Map(map["noise"], SensorKeyNames("noise"))) {
    sensor.spec.noise.sigma = reader.Number((*noise)["sigma"]).value_or(sensor.spec.noise.sigma);
    sensor.spec.noise.mean = reader.Number((*noise)["mean"]).value_or(sensor.spec.noise.mean);
    sensor.spec.noise.resolution_m = reader.Number((*noise)["resolution_m"]).value_or(sensor.spec.noise.resolution_m);
    sensor.spec.noise.dropout = reader.Number((*noise)["dropout"]).value_or(sensor.spec.noise.dropout);
    // a σ of the scenario's own replaces a part's table by target and light, unless it gives a table too
    if (noise->Has("sigma") && !noise->Has("sigma_table")) sensor.spec.sigma_table.clear();
    ReadAmbientTable(reader, (*noise)["sigma_table"], "[reflectance, ambient_klux, sigma]", sensor.spec.sigma_table);
    if (const auto model = reader.String((*noise)["model"])) {
      if (const auto parsed = NoiseModelFromName(*model)) {
        sensor.spec.noise.model = *parsed;
      } else {
        reader.Fail((*noise)["model"], "expected multiplicative, additive or distance_scaled, got '" + *model + "'");
      }
    }
  }

  // beyond the paper: beam, materials, echo model, lookup table
  ReadBeam(reader, map["beam"], sensor.spec);
  sensor.spec.echo_threshold = reader.Number(map["echo_threshold"]).value_or(sensor.spec.echo_threshold);
  sensor.spec.specular_exponent = reader.Number(map["specular_exponent"]).value_or(sensor.spec.specular_exponent);
  sensor.spec.use_material = reader.Bool(map["use_material"]).value_or(sensor.spec.use_material);
  if (const auto model = reader.String(map["echo_model"])) {
    if (*model == "window" || *model == "physical") {
      sensor.spec.echo_model = *model == "window" ? EchoModel::kWindow : EchoModel::kPhysical;
    } else {
      reader.Fail(map["echo_model"], "expected window or physical, got '" + *model + "'");
    }
  }
  ReadLookupTable(reader, map["lookup_table"], sensor.spec);
  // range_table, corner_range_table: [[reflectance, ambient_klux, max_range_m], ...] ([] turns a part's off)
  ReadAmbientTable(reader, map["range_table"], "[reflectance, ambient_klux, max_range_m]", sensor.spec.range_table);
  ReadAmbientTable(reader, map["corner_range_table"], "[reflectance, ambient_klux, max_range_m]",
                   sensor.spec.corner_range_table);
  // echoes: first | strongest | all, and how far apart two echoes must be
  if (const auto echoes = reader.String(map["echoes"])) {
    if (const auto selection = EchoSelectionFromName(*echoes)) {
      sensor.spec.echoes = *selection;
    } else {
      reader.Fail(map["echoes"], "expected first, strongest or all, got '" + *echoes + "'");
    }
  }
  sensor.spec.echo_separation_m = reader.Number(map["echo_separation_m"]).value_or(sensor.spec.echo_separation_m);
  // a lookup sensor's range is its table's unless range_m says otherwise
  if (sensor.spec.type == SensorType::kLookup && map.Has("lookup_table") && !map.Has("range_m") &&
      sensor.spec.lookup_table.size() >= 2) {
    sensor.spec.min_range_m = sensor.spec.lookup_table.front().distance_m;
    sensor.spec.max_range_m = sensor.spec.lookup_table.back().distance_m;
  }
  ReadTiming(reader, map, sensor);

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
  if (link) sensor.link_line = link.node.Mark().line + 1;  // the link is checked against the robot later
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
  std::map<std::string, std::string> folder_origin;  // zones/ and echoes/ folder -> the name that has it
  std::vector<Field> sensor_items;                 // each read sensor's item, for ResolveFiring's messages
  for (const Field& item : *items) {
    const auto map = reader.Map(item, SensorKeyNames());
    if (!map) continue;
    SensorConfig sensor = ReadSensor(reader, *map, has_robot);
    const Field name = (*map)["name"];
    if (reader.Require(name, "name, unique among the sensors")) {
      if (const auto text = reader.String(name)) {
        sensor.name = *text;
        // printable UTF-8 only: the JSON outputs stay valid (commas are quoted in CSV)
        if (const std::string problem = NamingProblem(*text); !problem.empty())
          reader.Fail(name, "expected a name of printable UTF-8 text, got " + problem);
        const auto [previous, inserted] = name_origin.emplace(*text, item.path);
        if (!inserted) reader.Fail(name, "duplicate sensor name '" + *text + "' (already used by " + previous->second + ")");
        // one folder per sensor under zones/ and echoes/, or one sensor's arrays overwrite the other's
        const std::string folder = SensorFolderName(*text, sensors.size());
        const auto [other, fresh] = folder_origin.emplace(folder, *text);
        if (inserted && !fresh) {
          reader.Fail(name, "sensor '" + *text + "' and sensor '" + other->second + "' would write the same folder '" +
                                folder + "' under zones/ and echoes/ (a name that is not a plain file name is written "
                                "as sensor_INDEX); rename one of them");
        }
      }
    }
    sensors.push_back(std::move(sensor));
    sensor_items.push_back(item);
  }
  ResolveFiring(reader, sensor_items, sensors);
  return sensors;
}

}  // namespace proxsim
