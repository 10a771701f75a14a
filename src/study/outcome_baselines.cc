#include "study/outcome_baselines.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <stdexcept>

namespace proxsim {

namespace {

// where the fan's rays meet a floor 1 m below their origin: dense near the
// feet, where a stop must be decided, sparser far ahead, where the walk sweeps them
constexpr double kOracleGroundReach_m[] = {0.3, 0.45, 0.6, 0.8, 1.0, 1.3, 1.7, 2.2, 3.0};

std::string OracleSensorsYaml(std::vector<std::string>& names) {
  std::string yaml = "[";
  char entry[400];
  const int azimuths = static_cast<int>(std::lround(2 * kOracleHalfFan_deg / kOracleAzimuthStep_deg)) + 1;
  for (int a = 0; a < azimuths; ++a) {
    const double yaw_deg = -kOracleHalfFan_deg + a * kOracleAzimuthStep_deg;
    for (std::size_t r = 0; r < std::size(kOracleGroundReach_m); ++r) {
      const double pitch_deg = std::atan2(1.0, kOracleGroundReach_m[r]) * 180.0 / M_PI;
      std::snprintf(entry, sizeof entry, "oracle_%02d_%zu", a, r);
      names.emplace_back(entry);
      std::snprintf(entry, sizeof entry,
                    "%s{name: %s, type: ideal, link: root, see_robot: false, range_m: [0, %g], max_incidence_deg: 90, "
                    "rate_hz: %g, pose: {xyz_m: [0.1, 0, 0], rpy_deg: [0, %.3f, %.1f]}}",
                    yaml.size() > 1 ? ", " : "", names.back().c_str(), kOracleRange_m, kOracleRate_hz, pitch_deg,
                    yaw_deg);
      yaml += entry;
    }
  }
  return yaml + "]";
}

// whether the run's robot.SECTION.KEY is `map` (gait.footholds: the legs
// plan on the robot's map; strategy.perception: the strategy reads it)
bool RobotKeyIsMap(const YAML::Node& run, const char* section, const char* key) {
  const YAML::Node robot = run["robot"];
  if (!robot || !robot.IsMap()) return false;
  const YAML::Node part = robot[section];
  if (!part || !part.IsMap()) return false;
  const YAML::Node value = part[key];
  return value && value.IsScalar() && value.Scalar() == "map";
}

}  // namespace

void GiveOraclePerception(YAML::Node& run) {
  const bool legs_on_map = RobotKeyIsMap(run, "gait", "footholds");
  if (legs_on_map) {
    run["robot"]["gait"]["footholds"] = "truth";
    run["robot"]["gait"]["unsafe_steps"] = "refuse";
  }
  // the true map only for a strategy that reads the map (nothing else reads it in a study)
  if (!RobotKeyIsMap(run, "strategy", "perception")) return;
  YAML::Node map = run["map"];
  if (!map || !map.IsMap()) map = YAML::Node(YAML::NodeType::Map);
  map["truth_within_m"] = kOracleReach_m;
  const YAML::Node ceiling = map["max_height_m"];
  double given_m = 0.6;  // TerrainMapConfig's default
  if (ceiling && ceiling.IsScalar()) given_m = ceiling.as<double>(0.6);
  map["max_height_m"] = std::max(given_m, kOracleMapCeiling_m);
  map["sensors"] = YAML::Load("[]");
  run["map"] = map;
  // the fan feeds only a strategy reading its readings: reading the map, it
  // would be cast (and its replay drawn) for nothing
  run["sensors"] = YAML::Load("[]");
}

std::vector<std::string> SensorsOfRuns(const SensorSet& set, const StrategyChoice& strategy) {
  if (set.baseline != kOracleBaseline || strategy.yaml.empty()) return set.sensor_names;
  YAML::Node run;
  run["robot"]["strategy"] = YAML::Load(strategy.yaml);
  if (!RobotKeyIsMap(run, "strategy", "perception")) return set.sensor_names;
  char name[96];
  std::snprintf(name, sizeof name, "true_map_within_%gm", kOracleReach_m);
  return {name};
}

bool IsBaselineName(const std::string& name) { return name == kBlindBaseline || name == kOracleBaseline; }

SensorSet BaselineSet(const std::string& name) {
  SensorSet set;
  set.name = name;
  set.baseline = name;
  set.price_usd = std::numeric_limits<double>::quiet_NaN();
  set.mass_g = std::numeric_limits<double>::quiet_NaN();
  if (name == kBlindBaseline) {
    set.sensors_yaml = "[]";
  } else if (name == kOracleBaseline) {
    set.sensors_yaml = OracleSensorsYaml(set.sensor_names);
  } else {
    throw std::logic_error("BaselineSet: unknown baseline " + name);
  }
  return set;
}

}  // namespace proxsim
