// One declaration per section (core/config_schema.h) drives the reader, the
// bounds, the summary echo, the docs' tables and the YAML writer: each is
// checked here against the declaration, so that a key added to a schema is
// read, judged, echoed, documented and written, or a test here fails.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "core/config_schema.h"
#include "core/input_error.h"
#include "knowledge/terrain_config.h"
#include "scenario/config_sections.h"
#include "scenario/gait_section.h"
#include "scenario/robot_section.h"
#include "scenario/scenario.h"
#include "sim/run_summary.h"
#include "strategy/strategy_config.h"

namespace proxsim {
namespace {

// a scenario with a robot, two sensors, `map` and `strategy` sections as given
Scenario SchemaScenario(const std::string& map_yaml, const std::string& strategy_yaml,
                        const std::string& gait_yaml = "{}", const std::string& robot_yaml = "{}") {
  // the robot's own keys' flow map, its braces taken off, beside the ones given here
  const std::string robot_keys = robot_yaml.substr(1, robot_yaml.size() - 2);
  return LoadScenarioText("proxsim: 1\nrobot: {model: builtin:biped, gait: " + gait_yaml + ", strategy: " +
                              strategy_yaml + (robot_keys.empty() ? "" : ", " + robot_keys) +
                              "}\nsensors: [{name: a, type: laser, link: left_tibia}, "
                              "{name: b, type: reflectance, link: left_tibia}]\nmap: " +
                              map_yaml + "\n",
                          "schema.yaml");
}

std::vector<std::string> SchemaProblems(const std::string& map_yaml, const std::string& strategy_yaml) {
  try {
    SchemaScenario(map_yaml, strategy_yaml);
  } catch (const InputError& error) {
    return error.problems();
  }
  return {};
}

// every number of a section moved off its default (and within its bounds), every flag flipped, every choice's last
template <class Config>
Config EveryKeyChanged(const ConfigSchema<Config>& schema) {
  Config config;
  for (const auto& param : schema) {
    const ParamDescription& d = param.description;
    if (param.ByHand()) continue;  // the section's own code reads it
    switch (d.type) {
      case ParamType::kNumber: {
        if (d.whole) {
          param.set(config, d.bounds.min + 1);
          break;
        }
        const double now = std::get<double>(param.get(config));
        double moved = now + 0.125;
        if (!d.bounds.Contains(moved)) moved = now - 0.001;
        if (!d.bounds.Contains(moved)) moved = std::isfinite(d.bounds.min) ? d.bounds.min + 0.001 : 0.5;
        param.set(config, moved);
        break;
      }
      case ParamType::kFlag:
        param.set(config, !std::get<bool>(param.get(config)));
        break;
      case ParamType::kChoice:
        param.set(config, d.choices.back());
        break;
      case ParamType::kText:
        param.set(config, std::string("text"));
        break;
      case ParamType::kNames:
        param.set(config, std::vector<std::string>{"a"});
        break;
    }
  }
  return config;
}

TEST(ConfigSchema, NumbersAreWrittenShortestAndReadBackExactly) {
  for (const double value : {0.1, 0.02, 1.0 / 3.0, 20.0, 1e-9, -0.0625, 123456789.125}) {
    const std::string text = ParamValueText(value);
    EXPECT_EQ(std::stod(text), value) << text;
  }
  EXPECT_EQ(ParamValueText(0.02), "0.02");
  EXPECT_EQ(ParamValueText(20.0), "20");
  EXPECT_EQ(ParamValueText(true), "true");
  // words a YAML reader would take for something else are quoted
  EXPECT_EQ(ParamValueText(std::string("map")), "map");
  EXPECT_EQ(ParamValueText(std::string("no")), "\"no\"");
  EXPECT_EQ(ParamValueText(std::string("0.5")), "\"0.5\"");
  EXPECT_EQ(ParamValueText(std::vector<std::string>{"laser left", "b"}), "[\"laser left\", b]");
}

TEST(ConfigSchema, BoundsSayWhatTheyAccept) {
  EXPECT_EQ(Positive().Text("m"), "> 0 m");
  EXPECT_EQ(AtLeast(1).Text("m"), ">= 1 m");
  EXPECT_EQ(Between(0.005, 1).Text("m"), "in [0.005, 1] m");
  EXPECT_EQ(AnyFinite().Expected("m"), "a finite number in m");
  EXPECT_TRUE(Positive().Contains(1e-12));
  EXPECT_FALSE(Positive().Contains(0.0));
  EXPECT_TRUE(NonNegative().Contains(0.0));
  EXPECT_FALSE(AnyFinite().Contains(std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(Between(0, 1).Contains(std::nan("")));
}

TEST(ConfigSchema, ValidateJudgesEveryNumberByItsDeclaredBounds) {
  TerrainMapConfig map;
  map.window_m = 0.5;
  map.truth_within_m = 21;
  const std::vector<std::string> map_problems = map.Validate();
  ASSERT_EQ(map_problems.size(), 2u);
  EXPECT_EQ(map_problems[0], "window_m: expected a number >= 1 m, got 0.5");
  EXPECT_EQ(map_problems[1], "truth_within_m: expected a number in [0, 20] m, got 21");

  StopConfig stop;
  stop.corridor_half_width_m = 0;
  ASSERT_EQ(Validate(StrategyConfig(stop)).size(), 1u);
  EXPECT_EQ(Validate(StrategyConfig(stop))[0], "corridor_half_width_m: expected a number > 0 m, got 0");
  // max_drop_m's default 0 means "the legs' max step": not judged; given, it must be > 0
  EXPECT_TRUE(Validate(StrategyConfig(StopConfig{})).empty());
  CircumventConfig circumvent;
  circumvent.margin_m = 0;  // >= 0 is allowed
  EXPECT_TRUE(Validate(StrategyConfig(circumvent)).empty());
  circumvent.assumed_depth_m = -0.1;
  EXPECT_EQ(Validate(StrategyConfig(circumvent)).size(), 1u);
}

TEST(ConfigSchema, TheReaderReportsABoundAtItsKeysLine) {
  const std::vector<std::string> problems =
      SchemaProblems("{window_m: 0.5}", "{name: circumvent,\n  rejoin_m: 0, perception: mapp}");
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_EQ(problems[0], "schema.yaml:3: robot.strategy.perception: expected readings (each fresh reading's point) or map (the robot's terrain map), got 'mapp' (did you mean 'map'?)");
  EXPECT_EQ(problems[1], "schema.yaml:3: robot.strategy.rejoin_m: expected a number > 0 m, got 0");
  EXPECT_EQ(problems[2], "schema.yaml:5: map.window_m: expected a number >= 1 m, got 0.5");
}

TEST(ConfigSchema, TheReaderAcceptsExactlyTheDeclaredKeys) {
  const std::vector<std::string> problems = SchemaProblems("{windw_m: 5}", "{name: stop, margin_m: 0.2}");
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("robot.strategy.margin_m"), std::string::npos) << problems[0];
  EXPECT_NE(problems[1].find("'window_m'"), std::string::npos) << problems[1];
}

// The YAML writer's text, read by the scenario reader, gives the same values.
TEST(ConfigSchema, WhatTheWriterWritesTheReaderReadsBack) {
  const StopConfig stop = EveryKeyChanged(StopSchema());
  const CircumventConfig circumvent = EveryKeyChanged(CircumventSchema());
  const TerrainMapConfig map = EveryKeyChanged(TerrainMapSchema());
  ASSERT_TRUE(map.Validate().empty());
  for (const StrategyConfig& strategy : {StrategyConfig(stop), StrategyConfig(circumvent)}) {
    ASSERT_TRUE(Validate(strategy).empty());
    const std::string map_yaml = ParamsYaml(TerrainMapSchema(), map);
    const Scenario s = SchemaScenario(map_yaml, StrategyYaml(strategy));
    ASSERT_TRUE(s.robot && s.robot->strategy);
    EXPECT_EQ(StrategyYaml(*s.robot->strategy), StrategyYaml(strategy));
    EXPECT_EQ(ParamsYaml(TerrainMapSchema(), s.map), map_yaml);
  }
  EXPECT_NE(StrategyYaml(stop), StrategyYaml(StopConfig{}));

  RobotConfig robot = EveryKeyChanged(GaitSectionSchema());
  robot.gait.keyframe.clear();  // the built-in biped has no keyframe to name
  ASSERT_TRUE(CheckParamBounds(GaitSectionSchema(), robot).empty());
  const std::string gait_yaml = ParamsYaml(GaitSectionSchema(), robot);
  const Scenario s = SchemaScenario("{}", "{name: stop}", gait_yaml);
  ASSERT_TRUE(s.robot);
  EXPECT_EQ(ParamsYaml(GaitSectionSchema(), *s.robot), gait_yaml);
  EXPECT_NE(gait_yaml.find("crouch_knee_deg: "), std::string::npos) << gait_yaml;

  // the robot's own choices and geom_group (its maps and paths are read by hand)
  const RobotConfig changed = EveryKeyChanged(RobotSectionSchema());
  const std::string robot_yaml = ParamsYaml(RobotSectionSchema(), changed);
  EXPECT_EQ(robot_yaml, "{model_scene: ignore, geom_group: 1, geometry: collision, on_collision: continue, "
                        "locomotion: external}");
  const Scenario with_robot = SchemaScenario("{}", "{name: stop}", "{}", robot_yaml);
  EXPECT_EQ(ParamsYaml(RobotSectionSchema(), *with_robot.robot), robot_yaml);
}

// summary.json's inputs carry every declared key of the map and the strategy,
// with the value the scenario gave.
TEST(ConfigSchema, TheSummaryEchoesEveryDeclaredKey) {
  const StopConfig stop = EveryKeyChanged(StopSchema());
  const TerrainMapConfig map = EveryKeyChanged(TerrainMapSchema());
  const Scenario s = SchemaScenario(ParamsYaml(TerrainMapSchema(), map), StrategyYaml(stop));
  const nlohmann::json inputs = InputsJson(s);
  for (const auto& param : TerrainMapSchema()) {
    ASSERT_TRUE(inputs["map"].contains(param.key())) << param.key();
    EXPECT_EQ(ParamValueText(param.get(map)), ParamValueText(param.get(s.map))) << param.key();
  }
  const nlohmann::json& echoed = inputs["robot"]["strategy"];
  EXPECT_EQ(echoed["name"], "stop");
  for (const auto& param : StopSchema()) {
    ASSERT_TRUE(echoed.contains(param.key())) << param.key();
    EXPECT_FALSE(echoed[param.key()].is_null()) << param.key();
  }
  EXPECT_EQ(echoed["stop_distance_m"].get<double>(), stop.stop_distance_m);
  RobotConfig robot = EveryKeyChanged(GaitSectionSchema());
  robot.gait.keyframe.clear();
  const nlohmann::json gait =
      InputsJson(SchemaScenario("{}", "{name: stop}", ParamsYaml(GaitSectionSchema(), robot)))["robot"]["gait"];
  for (const auto& param : GaitSectionSchema()) {
    ASSERT_TRUE(gait.contains(param.key())) << param.key();
    EXPECT_EQ(gait[param.key()].is_null(), param.key() == "keyframe") << param.key();
  }
  // every robot key is echoed, by its declaration or by the section's code (stop_distance_m: as the strategy)
  const nlohmann::json robot_echo = InputsJson(SchemaScenario("{}", "{name: stop}", "{}",
                                                              ParamsYaml(RobotSectionSchema(), EveryKeyChanged(RobotSectionSchema()))))["robot"];
  for (const auto& param : RobotSectionSchema()) {
    if (param.key() == "stop_distance_m") continue;
    EXPECT_TRUE(robot_echo.contains(param.key())) << param.key();
  }
  EXPECT_EQ(robot_echo["geom_group"].dump(), "1");
  EXPECT_EQ(robot_echo["locomotion"], "external");
  EXPECT_EQ(echoed["perception"], "map");
  // a key left out: its default, or null where the default means "not given"
  const nlohmann::json defaults = InputsJson(SchemaScenario("{}", "{name: stop}"));
  EXPECT_TRUE(defaults["robot"]["strategy"]["max_drop_m"].is_null());
  EXPECT_EQ(defaults["robot"]["strategy"]["corridor_half_width_m"].get<double>(), StopConfig{}.corridor_half_width_m);
  EXPECT_EQ(defaults["map"]["sensors"], "types: ideal, laser, ultrasonic, lookup, multizone");
}

// docs/scenario.md and docs/terrain_map.md hold each section's table as
// `proxsim columns --keys SECTION` prints it.
TEST(ConfigSchema, TheDocsTablesAreTheDeclarations) {
  const std::vector<std::pair<std::string, std::string>> pages = {
      {"material", "scenario.md"}, {"map", "terrain_map.md"}, {"robot", "scenario.md"}, {"robot.gait", "scenario.md"}, {"strategy.stop", "scenario.md"}, {"strategy.circumvent", "scenario.md"}};
  ASSERT_EQ(ConfigSectionNames().size(), pages.size()) << "a new section: add its docs page here";
  for (const auto& [section, page] : pages) {
    const auto params = ConfigSectionParams(section);
    ASSERT_TRUE(params) << section;
    testing::ExpectCliTableInDocs("columns --keys " + section, ParamsMarkdown(*params), page,
                                  "<!-- " + section + " keys: the output of `proxsim columns --keys " + section +
                                      "` -->\n",
                                  "<!-- end of " + section + " keys -->");
  }
}

}  // namespace
}  // namespace proxsim
