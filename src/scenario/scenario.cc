// Loading a scenario (docs/scenario.md): YAML text → yaml-cpp
// document → Scenario, with every problem collected before anything runs.
// This file reads the top level (schema version, seed, duration, rate), hands
// each section to its reader (scenario_scene.cc, scenario_robot.cc,
// scenario_sensors.cc, scenario_map.cc) and checks the run as a whole; any problem anywhere
// ends in one InputError listing them all, each as
// "FILE:LINE: KEY.PATH: expected …, got …".
//
// Relative paths in the file (robot model, meshes, trajectory) start from the
// scenario file's folder; built-in scenarios ("builtin:NAME") resolve them
// from the current directory. Robot model and trajectory paths are stored
// resolved; a mesh keeps the path as written (Mesh::file) with its triangles
// loaded.
#include "scenario/scenario.h"
#include "scenario/scenario_generate.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <system_error>

#include "core/embedded_files.h"
#include "core/input_error.h"
#include "gait/gait_walker.h"
#include "scenario/scenario_sections.h"
#include "sensors/multizone.h"
#include "sensors/sensor_spec.h"

namespace proxsim {

namespace {

constexpr int kSchemaVersion = 1;

// A run whose outputs would pass this many bytes is refused as a likely typo.
constexpr double kMaxOutputBytes = 50e9;
// Bytes written per sensor sample (a readings.csv row with a hit, measured on
// the paper run: 239 B; plus a profile.ply point when it detects, about 50 B)
// and per sample of a robot (poses.csv: about 90 B for each of ~10 links).
constexpr double kBytesPerSensorSample = 300;
constexpr double kBytesPerRobotSample = 900;
// The zones/ and echoes/ arrays a run holds in memory until its end: a
// bound on the run's memory, far below the output guard.
constexpr double kMaxHeldBytes = 2e9;

struct BuiltinScenario {
  const char* name;
  const char* embedded_path;
};
constexpr BuiltinScenario kBuiltinScenarios[] = {
    {"paper", "data/scenarios/paper_dining_room.yaml"},
    {"world_demo", "data/scenarios/world_sensors_demo.yaml"},
};

std::string FormatCount(double value) {
  std::ostringstream text;
  text.precision(3);
  text << value;
  return text.str();
}

// The folder that relative paths in `source` start from.
std::filesystem::path BaseDirOf(const std::string& source) {
  if (source.starts_with("builtin:")) return {};
  return std::filesystem::path(source).parent_path();
}

// Bytes per sample of what a run holds in memory to its end, the zones/ and
// echoes/ arrays (written whole at the end): per zone and target d_m (8 B),
// p_W (24 B) and status (1 B), per zone its target count (1 B); per echo
// sensor four distances, four signals (8 B each) and a count (1 B); and each
// sensor's t_s (8 B).
double HeldBytesPerSample(const Scenario& scenario) {
  double bytes = 0;
  for (const SensorConfig& sensor : scenario.sensors) {
    if (const auto& zones = sensor.spec.zones)
      bytes += 8.0 + ZoneCount(*zones) * (33.0 * static_cast<double>(zones->targets) + 1.0);
    if (sensor.spec.echoes != EchoSelection::kFirst) bytes += 8.0 + 4 * 8.0 + 4 * 8.0 + 1.0;
  }
  return bytes;
}

// The whole run's outputs must fit on a disk: refuse one whose estimated size
// is beyond kMaxOutputBytes, giving the estimate; and what it holds in memory
// to its end (zones, echoes) within kMaxHeldBytes.
void CheckRunSize(YamlReader& reader, const MapView& top, const Scenario& scenario) {
  const double samples = scenario.duration_s * scenario.rate_hz;
  // blame the key the file gives (both default values fit)
  const Field blame = top.Has("duration_s") ? top["duration_s"] : top["rate_hz"];
  if (scenario.SampleCount() == 0) {
    reader.Fail(top.Has("rate_hz") ? top["rate_hz"] : blame,
                "the run takes no sample: " + FormatCount(scenario.duration_s) + " s × " + FormatCount(scenario.rate_hz) +
                    " Hz = " + FormatCount(samples) + " samples; expected at least one (raise rate_hz or duration_s)");
    return;
  }
  const double sensors = static_cast<double>(std::max<std::size_t>(1, scenario.sensors.size()));
  const double held_bytes = samples * HeldBytesPerSample(scenario);
  const double bytes =
      samples * (sensors * kBytesPerSensorSample + (scenario.robot ? kBytesPerRobotSample : 0.0)) + held_bytes;
  if (bytes <= kMaxOutputBytes) {
    if (held_bytes > kMaxHeldBytes) {
      reader.Fail(blame, "the run is too large: " + FormatCount(scenario.duration_s) + " s × " +
                             FormatCount(scenario.rate_hz) + " Hz of the multi-zone and echo sensors' arrays "
                             "(zones/, echoes/), held in memory to the run's end, would take about " +
                             FormatCount(held_bytes / 1e9) + " GB; expected at most " + FormatCount(kMaxHeldBytes / 1e9) +
                             " GB (shorten duration_s, lower rate_hz, or use fewer zones or echo sensors)");
    }
    return;
  }
  reader.Fail(blame, "the run is too large: " + FormatCount(scenario.duration_s) + " s × " +
                            FormatCount(scenario.rate_hz) + " Hz = " + FormatCount(samples) + " samples of " +
                            FormatCount(sensors) + " sensor(s) would write about " + FormatCount(bytes / 1e9) +
                            " GB; expected at most 50 GB (shorten duration_s, lower rate_hz or use fewer sensors)");
}

// Everything after the YAML parse: the top-level keys and the sections.
Scenario ReadScenario(YamlReader& reader, const YAML::Node& document, const std::string& source) {
  Scenario scenario;
  scenario.source = source;
  const auto top = reader.Map(reader.Root(document),
                              {"proxsim", "seed", "duration_s", "rate_hz", "scene", "robot", "sensors", "map", "outputs"},
                              "a map of scenario keys (proxsim, seed, duration_s, rate_hz, scene, robot, sensors, map, "
                              "outputs)");
  if (!top) return scenario;

  // proxsim: the schema version, required
  const Field version = (*top)["proxsim"];
  if (reader.Require(version, "proxsim: 1 (the schema version)")) {
    const auto number = reader.Count(version);
    if (number && *number != kSchemaVersion) {
      reader.Fail(version, "expected schema version 1, got " + std::to_string(*number) +
                               " (this proxsim reads version 1 only)");
    }
  }

  // the run's clock and random seed
  scenario.seed = reader.Count((*top)["seed"]).value_or(scenario.seed);
  const auto duration_s = reader.Number((*top)["duration_s"], PositiveNumber("s"));
  const auto rate_hz = reader.Number((*top)["rate_hz"], PositiveNumber("Hz"));
  scenario.duration_s = duration_s.value_or(scenario.duration_s);
  scenario.rate_hz = rate_hz.value_or(scenario.rate_hz);

  // the sections
  const std::filesystem::path base_dir = BaseDirOf(source);
  ReadScene(reader, (*top)["scene"], base_dir, scenario);
  if (top->Has("robot"))
    scenario.robot = ReadRobot(reader, (*top)["robot"], base_dir, scenario.scene, scenario.scene_from_model);
  scenario.sensors = ReadSensors(reader, (*top)["sensors"], scenario.robot.has_value());
  // the light the optical parts' range tables read
  for (SensorConfig& sensor : scenario.sensors) sensor.spec.ambient_klux = scenario.scene.ambient_klux;
  scenario.map = ReadTerrainMap(reader, (*top)["map"], scenario.sensors, scenario.robot.has_value());
  // footholds planned on the map need the map
  if (scenario.robot && scenario.robot->footholds == Footholds::kMap && !scenario.map.enabled) {
    reader.FailAtLine(scenario.robot->footholds_line, "robot.gait.footholds",
                      "map plans the footsteps on the robot's terrain map, but the map is off (map: {enabled: "
                      "false}); turn it on or plan on the truth");
  }
  // outputs: {range_convention: proxsim | rep117}
  if (const auto outputs = reader.Map((*top)["outputs"], {"range_convention"})) {
    if (const auto name = reader.String((*outputs)["range_convention"])) {
      if (*name == "rep117" || *name == "proxsim") {
        scenario.range_convention = *name == "rep117" ? RangeConvention::kRep117 : RangeConvention::kProxsim;
      } else {
        reader.Fail((*outputs)["range_convention"], "expected proxsim or rep117, got '" + *name + "'");
      }
    }
  }

  // the run as a whole (only with a valid clock, else the estimate means nothing)
  if (duration_s.has_value() == top->Has("duration_s") && rate_hz.has_value() == top->Has("rate_hz")) {
    CheckRunSize(reader, *top, scenario);
  }
  return scenario;
}

}  // namespace

std::int64_t Scenario::SampleCount() const {
  // samples at t_k = k / rate_hz strictly before duration_s; a product within
  // rounding of a whole number counts as that number (0.3 s at 10 Hz is 3)
  const double exact = duration_s * rate_hz;
  if (!std::isfinite(exact) || exact <= 0) return 0;
  if (exact >= static_cast<double>(std::numeric_limits<std::int64_t>::max() / 2)) {
    return std::numeric_limits<std::int64_t>::max() / 2;
  }
  const double nearest = std::round(exact);
  if (std::abs(exact - nearest) <= 1e-9 * std::max(1.0, exact)) return static_cast<std::int64_t>(nearest);
  return static_cast<std::int64_t>(std::ceil(exact));
}

std::filesystem::path ResolveScenarioPath(const std::filesystem::path& base_dir, const std::string& file) {
  const std::filesystem::path path(file);
  if (path.is_absolute() || base_dir.empty()) return path;
  return (base_dir / path).lexically_normal();
}

Pose ReadPose(YamlReader& reader, const Field& field) {
  const auto map = reader.Map(field, {"xyz_m", "rpy_deg"});
  if (!map) return Pose::Identity();
  const Vec3 xyz_m = reader.Vector3((*map)["xyz_m"], Coordinate(), "[x, y, z] in metres").value_or(Vec3::Zero());
  const Vec3 rpy_deg =
      reader.Vector3((*map)["rpy_deg"], AnyNumber(), "[roll, pitch, yaw] in degrees").value_or(Vec3::Zero());
  return PoseFromXyzRpy(xyz_m, rpy_deg * (kPi / 180.0));
}

namespace {

// The problems building the scenario's walking robot would report (the URDF,
// the leg map, the held joints); none when it has no walking robot or its
// model file is missing (already reported by the scenario's own checks).
std::vector<std::string> RobotProblems(const Scenario& scenario) {
  if (!scenario.robot || !scenario.robot->trajectory_file.empty()) return {};
  const RobotConfig& robot = *scenario.robot;
  const bool builtin = robot.model.starts_with("builtin:");
  std::error_code error;
  if (!builtin && !std::filesystem::is_regular_file(robot.model, error)) return {};
  try {
    const UrdfOptions options{
        .geometry = robot.geometry, .package_paths = robot.package_paths, .geom_group = robot.geom_group};
    // (an MJCF the scenario read already, to take its scene, is not read again)
    const bool read = robot.model_read != nullptr && robot.model_read_key == ModelReadKey(robot);
    GaitWalker(builtin ? RobotModel::Builtin(robot.model.substr(8), options)
               : read  ? *robot.model_read
                       : RobotModel::FromFile(robot.model, options),
               robot);
  } catch (const InputError& robot_error) {
    return robot_error.problems();
  } catch (const std::exception&) {
    // not an input problem: the run reports it when it builds the robot
  }
  return {};
}

// The document read, every problem at once.
Scenario ReadChecked(YamlReader& reader, const YAML::Node& document, const std::string& source) {
  Scenario scenario = ReadScenario(reader, document, source);
  if (reader.HasProblems()) {
    // every problem at once: the robot's (its leg map, its held joints) are
    // otherwise found only when the simulation is built, after these are fixed
    std::vector<std::string> problems = reader.Problems();
    for (const std::string& problem : RobotProblems(scenario))
      if (std::find(problems.begin(), problems.end(), problem) == problems.end()) problems.push_back(problem);
    throw InputError(problems);
  }
  return scenario;
}

}  // namespace

Scenario LoadScenarioText(const std::string& yaml_text, const std::string& source) {
  YamlReader reader(source);

  // the text must be YAML, and not empty
  YAML::Node document = reader.Parse(yaml_text);
  if (!document.IsDefined() || document.IsNull()) {
    reader.FailFile("the file is empty; expected a scenario map starting with 'proxsim: 1'");
    throw InputError(reader.Problems());
  }

  // a generated world: read as the plain scenario `proxsim generate` writes
  if (HasGenerate(document)) document = YAML::Load(GeneratedScenarioText(yaml_text, source));
  return ReadChecked(reader, document, source);
}

Scenario LoadScenarioNode(YAML::Node document, const std::string& source) {
  YamlReader reader(source);
  if (!document.IsDefined() || document.IsNull()) {
    reader.FailFile("the document is empty; expected a scenario map starting with 'proxsim: 1'");
    throw InputError(reader.Problems());
  }
  if (HasGenerate(document)) document = GeneratedScenarioNode(document, source);
  return ReadChecked(reader, document, source);
}

Scenario LoadScenarioFile(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    // a loop of links is no missing file: stat()'s own reason
    struct stat info {};
    const bool there = ::stat(path.c_str(), &info) == 0;
    const int why = errno;
    throw InputError(path + ": cannot read the scenario file: " +
                     (there          ? std::string("not a regular file")
                      : why == ELOOP ? "a loop of symbolic links (" + std::string(std::strerror(why)) + ")"
                      : why == ENOENT ? std::string("no such file")
                                      : std::string(std::strerror(why))));
  }
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  if (!file) throw InputError(path + ": cannot read the scenario file");
  return LoadScenarioText(text.str(), path);
}

std::vector<std::string> BuiltinScenarioNames() {
  std::vector<std::string> names;
  for (const auto& builtin : kBuiltinScenarios) names.emplace_back(builtin.name);
  return names;
}

Scenario LoadBuiltinScenario(const std::string& name) {
  for (const auto& builtin : kBuiltinScenarios) {
    if (name != builtin.name) continue;
    const auto& files = EmbeddedFiles();
    const auto file = files.find(builtin.embedded_path);
    if (file == files.end()) throw InputError("builtin:" + name + ": the scenario is missing from this build");
    return LoadScenarioText(std::string(file->second), "builtin:" + name);
  }
  std::string valid;
  for (const auto& known : BuiltinScenarioNames()) valid += (valid.empty() ? "" : ", ") + known;
  throw InputError("builtin:" + name + ": unknown built-in scenario (expected one of " + valid + ")");
}

}  // namespace proxsim
