// The scenario's `robot.strategy` section as plain structs: which built-in
// strategy drives the robot, and its parameters (metres). Read by io/ from
// the scenario file and by strategy/ to build the strategy; nothing else.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "core/config_schema.h"

namespace proxsim {

/// What a built-in strategy reads: each fresh reading's point (`readings`,
/// the paper's way), or the robot's terrain map (`map`: its obstacles,
/// knowledge/map_queries.h; steps and holes are the legs' to plan on their
/// own map, gait.footholds: map).
enum class Perception { kReadings, kMap };

/// `{name: stop}`: stop before an obstacle or a drop the sensors report ahead.
struct StopConfig {
  Perception perception = Perception::kReadings;  ///< readings | map
  double stop_distance_m = 0.5;         ///< look-ahead from the leading toe, > 0
  double min_height_m = 0.03;           ///< a point this far above the stance ground is an obstacle, > 0
  /// lateral half-width of the corridor the feet sweep, > 0: about the
  /// leading toe (readings, the paper's rule) or the pelvis's line (map)
  double corridor_half_width_m = 0.30;
  double max_drop_m = 0.0;              ///< a drop ahead deeper than this stops the robot, > 0; 0: the legs' gait.max_step_m
};

/// `{name: circumvent}`: walk around an obstacle seen ahead, back to the path.
struct CircumventConfig {
  Perception perception = Perception::kReadings;  ///< readings | map
  double margin_m = 0.15;            ///< kept between the robot's half-width and the obstacle, >= 0
  double detect_distance_m = 1.5;    ///< an obstacle this close ahead of the leading toe is avoided, > 0
  double stop_distance_m = 0.3;      ///< safety: stop when a point is this close in the walking corridor, > 0
  double min_height_m = 0.03;        ///< a point this far above the stance ground is an obstacle, > 0
  double max_detour_m = 1.5;         ///< largest sideways shift of a detour; beyond it the way is blocked, > 0
  double assumed_depth_m = 0.3;      ///< depth given to an obstacle whose far side has not been seen, >= 0
  double rejoin_m = 1.0;             ///< path length past the obstacle over which the detour rejoins, > 0
};

using StrategyConfig = std::variant<StopConfig, CircumventConfig>;

/// The keys of `{name: stop}` and `{name: circumvent}` (core/config_schema.h),
/// `name` aside: the reader, the summary echo, docs/scenario.md's tables and
/// Validate() follow them.
const ConfigSchema<StopConfig>& StopSchema();
const ConfigSchema<CircumventConfig>& CircumventSchema();

/// Every parameter out of its bounds, "KEY: expected …, got …"; empty if valid.
std::vector<std::string> Validate(const StrategyConfig& config);

/// The strategy as the scenario's flow map, `{name: stop, stop_distance_m: 0.5, ...}`.
std::string StrategyYaml(const StrategyConfig& config);

/// "stop" or "circumvent".
inline const char* StrategyName(const StrategyConfig& config) {
  return std::holds_alternative<StopConfig>(config) ? "stop" : "circumvent";
}

}  // namespace proxsim
