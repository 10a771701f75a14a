// Each sensor type is declared in one place (src/sensors/): its keys
// (sensor_keys.cc) make the parser's list, docs/scenario.md's table and the
// summary's echo; its traits (sensor_types.cc) say what the other modules
// used to decide on their own.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <yaml-cpp/yaml.h>

#include "cli_helpers.h"
#include "scenario/scenario.h"
#include "sensors/sensor_keys.h"
#include "sensors/sensor_types.h"
#include "sim/run_summary.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadFile;
using testing::RunProxsim;

TEST(SensorHomeTest, DocsHoldTheSensorKeysTheCliPrints) {
  testing::ExpectCliTableInDocs("columns --sensor-keys", SensorKeysMarkdown(), "scenario.md",
                                 "<!-- sensor keys: the output of `proxsim columns --sensor-keys` -->\n",
                                 "<!-- end of sensor keys -->");
}

// Every leaf key path of a YAML map ("noise.sigma", "beam.pattern.gaussian.width_deg"), lists as leaves.
void LeafPaths(const YAML::Node& node, const std::string& path, std::vector<std::pair<std::string, YAML::Node>>& out) {
  if (!node.IsMap()) {
    out.emplace_back(path, node);
    return;
  }
  for (auto it = node.begin(); it != node.end(); ++it) {
    LeafPaths(it->second, path.empty() ? it->first.Scalar() : path + "." + it->first.Scalar(), out);
  }
}

// The value at a dotted path in a JSON object, or null when a part is missing.
const nlohmann::json* AtPath(const nlohmann::json& object, const std::string& path) {
  const nlohmann::json* node = &object;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    const std::string part = path.substr(start, dot - start);
    if (!node->is_object() || !node->contains(part)) return nullptr;
    node = &(*node)[part];
    start = dot + 1;
  }
  return node;
}

// The numbers of a nested list, in order.
void Flatten(const YAML::Node& node, std::vector<double>& out) {
  if (node.IsSequence()) {
    for (const YAML::Node& item : node) Flatten(item, out);
  } else {
    out.push_back(node.as<double>());
  }
}
void Flatten(const nlohmann::json& node, std::vector<double>& out) {
  if (node.is_array()) {
    for (const nlohmann::json& item : node) Flatten(item, out);
  } else {
    out.push_back(node.get<double>());
  }
}

// Sensors that between them give every key of sensor_keys.cc a value that
// differs from its default, so an echo of the preset would not pass.
constexpr const char* kEverySensorKey = R"(proxsim: 1
duration_s: 0.1
sensors:
  - name: beamed
    type: vl53l0x
    link: world
    pose: {xyz_m: [0.1, 0.2, 0.3], rpy_deg: [0, 10, 20]}
    see_robot: false
    range_m: [0.05, 1.5]
    max_incidence_deg: 40
    noise: {model: additive, sigma: 0.004, mean: 0.001, resolution_m: 0.002, dropout: 0.05}
    beam: {aperture_deg: 20, rays: 7, pattern: {gaussian: {width_deg: 6}}}
    echo_model: physical
    echo_threshold: 0.2
    specular_exponent: 12
    rate_hz: 25
    latency_s: 0.02
    flight_time: true
    wave_speed_m_s: 300
    range_table: [[0.5, 0, 1.0], [0.9, 0, 1.4], [0.5, 3, 0.6]]
  - name: tabled
    type: lookup
    lookup_table: [[0.1, 2.0, 0.01], [0.5, 1.0, 0.02], [0.9, 0.5, 0.03]]
  - name: zoned
    type: multizone
    zones: [4, 2]
    fov_deg: [50, 30]
    zone_rays: 9
    targets: 3
    target_separation_m: 0.4
    target_order: strongest
    distance: perpendicular
  - name: sonar
    type: ultrasonic
    beam: {aperture_deg: 40, rays: 19, reach: [[0.2, 20], [1.0, 8]]}
    echo_timeout_s: 0.02
    rate_hz: 10
    fire: 0.03
    crosstalk: false
    echoes: all
    echo_separation_m: 0.05
  - name: ranged
    type: vl53l1x
    distance_mode: short
    roi: [8, 12]
    timing_budget_ms: 50
    noise: {sigma_table: [[0.5, 0, 0.01], [0.9, 2, 0.02]]}
  - name: cornered
    type: vl53l5cx
    zones: [4, 4]
    corner_range_table: [[0.5, 0, 1.2], [0.9, 0, 2.0]]
  - name: reflect
    type: reflectance
    use_material: true
    beam: {aperture_deg: 10, rays: 7, pattern: {table: [[0, 1.0], [5, 0.5]]}}
)";

TEST(SensorHomeTest, TheSummaryEchoesEveryKeyAScenarioGave) {
  const fs::path dir = FreshDir("sensor_home_echo");
  fs::create_directories(dir);
  std::ofstream(dir / "every_key.yaml") << kEverySensorKey;
  const Scenario scenario = LoadScenarioFile((dir / "every_key.yaml").string());
  const nlohmann::json echo = InputsJson(scenario)["sensors"];
  const YAML::Node document = YAML::Load(kEverySensorKey);
  ASSERT_EQ(echo.size(), document["sensors"].size());

  std::set<std::string> given_keys;
  for (std::size_t i = 0; i < echo.size(); ++i) {
    std::vector<std::pair<std::string, YAML::Node>> leaves;
    LeafPaths(document["sensors"][i], "", leaves);
    for (const auto& [path, value] : leaves) {
      given_keys.insert(path);
      const nlohmann::json* echoed = AtPath(echo[i], path);
      ASSERT_NE(echoed, nullptr) << "sensors[" << i << "]." << path << " is not echoed in " << echo[i].dump();
      if (path == "type") continue;  // a part's name is echoed as `part`, the type as its physics
      if (value.IsScalar() && echoed->is_number()) {
        EXPECT_NEAR(echoed->get<double>(), value.as<double>(), 1e-12) << path;
      } else if (value.IsScalar() && echoed->is_boolean()) {
        EXPECT_EQ(echoed->get<bool>(), value.as<bool>()) << path;
      } else if (value.IsScalar() && echoed->is_string()) {
        EXPECT_EQ(echoed->get<std::string>(), value.as<std::string>()) << path;
      } else if (value.IsSequence()) {
        // lists of numbers (range_m, xyz_m, rpy_deg, tables) come back as they were given
        std::vector<double> given_numbers, echoed_numbers;
        Flatten(value, given_numbers);
        Flatten(*echoed, echoed_numbers);
        ASSERT_EQ(echoed_numbers.size(), given_numbers.size()) << path;
        for (std::size_t k = 0; k < given_numbers.size(); ++k) EXPECT_NEAR(echoed_numbers[k], given_numbers[k], 1e-9) << path;
      }
    }
  }
  EXPECT_EQ(echo[0]["part"], "vl53l0x");
  EXPECT_EQ(echo[0]["type"], "laser");
  EXPECT_EQ(echo[1]["lookup_table"][1][1].get<double>(), 1.0);

  // the scenario above gives every declared key (a new key needs a line there, and an echo)
  for (const SensorKey& key : SensorKeys()) {
    const bool given = std::any_of(given_keys.begin(), given_keys.end(), [&](const std::string& path) {
      return path == key.path || path.starts_with(std::string(key.path) + ".");
    });
    EXPECT_TRUE(given) << key.path << " is declared in sensor_keys.cc but the test's scenario does not give it";
  }
}

TEST(SensorHomeTest, TheParserTakesExactlyTheDeclaredKeys) {
  const fs::path dir = FreshDir("sensor_home_keys");
  fs::create_directories(dir);
  std::ofstream(dir / "typo.yaml") << "proxsim: 1\nsensors:\n  - {name: a, type: laser, noise: {sigm: 0.1}, beam_width: 3}\n";
  try {
    LoadScenarioFile((dir / "typo.yaml").string());
    FAIL() << "a typo was accepted";
  } catch (const std::exception& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("unknown key 'sigm' (did you mean 'sigma'?)"), std::string::npos) << message;
    EXPECT_NE(message.find("unknown key 'beam_width'"), std::string::npos) << message;
  }
}

// The HC-SR04's 60 ms measurement cycle: its default rate, and a faster one refused with the datasheet's words.
TEST(SensorHomeTest, APartsMeasurementCycleLimitsItsRate) {
  const fs::path dir = FreshDir("sensor_home_cycle");
  fs::create_directories(dir);
  std::ofstream(dir / "fast.yaml") << "proxsim: 1\nsensors:\n  - {name: a, type: hc_sr04, rate_hz: 20}\n";
  const auto fast = RunProxsim("validate " + (dir / "fast.yaml").string());
  EXPECT_EQ(fast.exit_code, 2) << fast.output;
  EXPECT_NE(fast.output.find("rate_hz: expected at most 16.67 Hz for a hc_sr04 (HC-SR04 datasheet: \"we suggest to use "
                             "over 60ms measurement cycle\"), got 20"),
            std::string::npos)
      << fast.output;
  std::ofstream(dir / "default.yaml") << "proxsim: 1\nduration_s: 1\nrate_hz: 100\nsensors:\n  - {name: a, type: hc_sr04}\n";
  const Scenario scenario = LoadScenarioFile((dir / "default.yaml").string());
  EXPECT_NEAR(scenario.sensors[0].rate_hz, 1 / 0.060, 1e-12);
  EXPECT_NEAR(InputsJson(scenario)["sensors"][0]["rate_hz"].get<double>(), 1 / 0.060, 1e-12);
}

TEST(SensorHomeTest, TraitsAreInCodeOrderAndNameTheMapDefault) {
  for (const SensorTypeTraits& traits : AllSensorTypeTraits()) {
    EXPECT_EQ(&TraitsOf(traits.type), &traits);
    EXPECT_EQ(SensorTypeFromName(traits.name), traits.type);
    // a timed echo has a wave, a signal sensor none
    EXPECT_EQ(traits.time_of_flight, traits.wave_speed_m_s > 0) << traits.name;
  }
  EXPECT_EQ(DefaultMapSensorTypes(), "ideal, laser, ultrasonic, lookup, multizone");
}

}  // namespace
}  // namespace proxsim
