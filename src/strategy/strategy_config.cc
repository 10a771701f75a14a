#include "strategy/strategy_config.h"

namespace proxsim {

namespace {

const std::vector<std::pair<Perception, std::string>> kPerceptionNames = {{Perception::kReadings, "readings"},
                                                                          {Perception::kMap, "map"}};
const char* const kPerceptionMeaning =
    "`readings`: each fresh reading's point (the paper's way); `map`: the obstacles of the robot's terrain map";

// the perception key, with what each choice reads for a wrong one's message
template <class C>
ConfigParam<C> PerceptionParam() {
  return WithGlosses(ChoiceParam("perception", &C::perception, kPerceptionNames, kPerceptionMeaning),
                     {"each fresh reading's point", "the robot's terrain map"});
}

}  // namespace

const ConfigSchema<StopConfig>& StopSchema() {
  using C = StopConfig;
  static const ConfigSchema<C> schema = {
      PerceptionParam<C>(),
      NumberParam("stop_distance_m", &C::stop_distance_m, Positive(), "m", "look-ahead from the leading toe"),
      NumberParam("min_height_m", &C::min_height_m, Positive(), "m",
                  "a measured point this far above the ground the robot stands on is an obstacle"),
      NumberParam("corridor_half_width_m", &C::corridor_half_width_m, Positive(), "m",
                  "lateral half-width of the corridor the feet sweep"),
      OptionalNumberParam("max_drop_m", &C::max_drop_m, Positive(), "m", "the legs' `gait.max_step_m`",
                          "a drop ahead proven deeper than this stops the robot (event `drop_ahead`, "
                          "[strategies.md](strategies.md))"),
  };
  return schema;
}

const ConfigSchema<CircumventConfig>& CircumventSchema() {
  using C = CircumventConfig;
  static const ConfigSchema<C> schema = {
      PerceptionParam<C>(),
      NumberParam("margin_m", &C::margin_m, NonNegative(), "m", "kept between the robot's half-width and the obstacle"),
      NumberParam("detect_distance_m", &C::detect_distance_m, Positive(), "m",
                  "an obstacle this close ahead of the leading toe is avoided"),
      NumberParam("stop_distance_m", &C::stop_distance_m, Positive(), "m",
                  "safety: stop when a point is this close in the walking corridor"),
      NumberParam("min_height_m", &C::min_height_m, Positive(), "m", "as for `stop`"),
      NumberParam("max_detour_m", &C::max_detour_m, Positive(), "m",
                  "largest sideways shift of a detour; beyond it the way is blocked"),
      NumberParam("assumed_depth_m", &C::assumed_depth_m, NonNegative(), "m",
                  "depth given to an obstacle whose far side has not been seen"),
      NumberParam("rejoin_m", &C::rejoin_m, Positive(), "m",
                  "path length past the obstacle over which the detour rejoins the path"),
  };
  return schema;
}

std::vector<std::string> Validate(const StrategyConfig& config) {
  if (const auto* stop = std::get_if<StopConfig>(&config)) return CheckParamBounds(StopSchema(), *stop);
  return CheckParamBounds(CircumventSchema(), std::get<CircumventConfig>(config));
}

std::string StrategyYaml(const StrategyConfig& config) {
  const std::string name = std::string("name: ") + StrategyName(config);
  if (const auto* stop = std::get_if<StopConfig>(&config)) return ParamsYaml(StopSchema(), *stop, name);
  return ParamsYaml(CircumventSchema(), std::get<CircumventConfig>(config), name);
}

}  // namespace proxsim
