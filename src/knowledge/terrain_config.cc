#include "knowledge/terrain_config.h"

namespace proxsim {

const ConfigSchema<TerrainMapConfig>& TerrainMapSchema() {
  using C = TerrainMapConfig;
  static const ConfigSchema<C> schema = [] {
    ConfigSchema<C> s = {
        FlagParam("enabled", &C::enabled, "`false`: no map is built, no `terrain/` written"),
        NumberParam("resolution_m", &C::resolution_m, Between(0.005, 1.0), "m", "the cells' side"),
        NumberParam("max_height_m", &C::max_height_m, AnyFinite(), "m",
                    "above the ground the robot stands on when it reads: the map keeps the highest surface below it"),
        NumberParam("obstacle_min_m", &C::obstacle_min_m, Positive(), "m",
                    "a cell this much above the ground is raised (an obstacle or a step up)"),
        NumberParam("drop_min_m", &C::drop_min_m, Positive(), "m",
                    "a cell this much below the ground is dropped (a hole or a step down)"),
        NumberParam("step_max_m", &C::step_max_m, Positive(), "m",
                    "the highest step the robot takes up or down; at least `obstacle_min_m` and `drop_min_m`"),
        NumberParam("step_min_size_m", &C::step_min_size_m, Positive(), "m",
                    "a step's top (or lower floor) is at least this long and wide"),
        NumberParam("window_m", &C::window_m, AtLeast(1.0), "m",
                    "the rolling window: what lies farther than this from the pelvis (in x or y) leaves memory"),
        NumberParam("truth_within_m", &C::truth_within_m, Between(0.0, 20.0), "m",
                    "> 0: perfect perception (the outcome study's oracle), every cell within this reach takes the "
                    "scene's true height; 0: off"),
    };
    // the sensors feeding the map: not given is a rule by type, an empty list no sensor
    ConfigParam<C> sensors;
    sensors.description = Describe("sensors", ParamType::kNames, "every sensor but the reflectance ones",
                                   "the names of the sensors whose readings feed the map");
    sensors.get = [](const C& c) { return ParamValue(c.sensors); };
    sensors.set = [](C& c, const ParamValue& v) {
      c.sensors = std::get<std::vector<std::string>>(v);
      c.sensors_given = true;
    };
    sensors.is_unset = [](const C& c) { return !c.sensors_given; };
    s.push_back(std::move(sensors));
    return s;
  }();
  return schema;
}

std::vector<std::string> TerrainMapConfig::Validate() const {
  std::vector<std::string> problems = CheckParamBounds(TerrainMapSchema(), *this);
  const bool judged = Positive().Contains(step_max_m) && Positive().Contains(obstacle_min_m) &&
                      Positive().Contains(drop_min_m);
  if (judged && (step_max_m < obstacle_min_m || step_max_m < drop_min_m)) {
    problems.push_back("step_max_m: expected at least obstacle_min_m (" + ParamValueText(obstacle_min_m) +
                       ") and drop_min_m (" + ParamValueText(drop_min_m) + "), got " + ParamValueText(step_max_m));
  }
  return problems;
}

}  // namespace proxsim
