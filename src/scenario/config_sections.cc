#include "scenario/config_sections.h"

#include <functional>
#include <utility>

#include "knowledge/terrain_config.h"
#include "scene/scene.h"
#include "scenario/gait_section.h"
#include "scenario/robot_section.h"
#include "strategy/strategy_config.h"

namespace proxsim {

namespace {

const std::vector<std::pair<std::string, std::function<std::vector<ParamDescription>()>>>& Sections() {
  static const std::vector<std::pair<std::string, std::function<std::vector<ParamDescription>()>>> sections = {
      {"material", [] { return DescribeParams(MaterialSchema()); }},
      {"map", [] { return DescribeParams(TerrainMapSchema()); }},
      {"robot", [] { return DescribeParams(RobotSectionSchema()); }},
      {"robot.gait", [] { return DescribeParams(GaitSectionSchema()); }},
      {"strategy.stop", [] { return DescribeParams(StopSchema()); }},
      {"strategy.circumvent", [] { return DescribeParams(CircumventSchema()); }},
  };
  return sections;
}

}  // namespace

std::vector<std::string> ConfigSectionNames() {
  std::vector<std::string> names;
  for (const auto& [name, params] : Sections()) names.push_back(name);
  return names;
}

std::optional<std::vector<ParamDescription>> ConfigSectionParams(const std::string& name) {
  for (const auto& [section, params] : Sections())
    if (section == name) return params();
  return std::nullopt;
}

}  // namespace proxsim
