// The terrain map's parameters (`map:` in the scenario file), as a plain
// struct with defaults and one Validate() that lists every violation. The
// thresholds are the (a rise of 4 cm is an obstacle, a drop of 5 cm a
// hole); the step limits are what a small biped can step on, up or down.
#pragma once

#include <string>
#include <vector>

#include "core/config_schema.h"

namespace proxsim {

struct TerrainMapConfig {
  bool enabled = true;            ///< false: no map is built, no terrain/ written
  double resolution_m = 0.02;     ///< cell side, in [0.005, 1] m
  /// above the ground the robot stands on when it reads; the map keeps the
  /// highest surface below it (the truth: below max_height_m above the highest ground stood on)
  double max_height_m = 0.6;
  double obstacle_min_m = 0.04;   ///< a cell this much above the ground is raised (obstacle or step up), > 0
  double drop_min_m = 0.05;       ///< a cell this much below the ground is dropped (hole or step down), > 0
  double step_max_m = 0.20;       ///< the highest step the robot can take up or down, >= obstacle_min_m and drop_min_m
  double step_min_size_m = 0.25;  ///< a step's top (or lower floor) must be at least this long and wide, > 0
  /// The rolling window: cells farther than this from the robot's pelvis in x
  /// or y leave the map, a tile at a time (their state goes to the outputs).
  /// 20 m: five times the longest reach of the built-in sensors (4 m), and
  /// longer than a generated room or course, so that only a long walk retires
  /// anything. >= 1 m.
  double window_m = 20.0;
  /// Sensors whose readings feed the map, by name; empty with sensors_given
  /// false: every sensor but the reflectance ones (their distance assumes
  /// normal incidence and a white surface: an oblique floor reads farther).
  std::vector<std::string> sensors;
  bool sensors_given = false;     ///< `map.sensors` was in the file (an empty list: no sensor)
  /// > 0: perfect perception — every cell within this distance of the
  /// robot's pelvis takes the scene's true height (sim/truth_map_feed.h), as
  /// the outcome study's oracle baseline does; a robot's own sensors never
  /// see this way. 0 (default): off. In [0, 20] m.
  double truth_within_m = 0.0;

  /// Every violated condition, one message each, worded after the scenario
  /// key; empty if valid: the schema's bounds, then step_max_m against the thresholds.
  std::vector<std::string> Validate() const;
};

/// The `map:` section's keys (core/config_schema.h): the reader, the summary
/// echo, docs/terrain_map.md's table and Validate() follow it.
const ConfigSchema<TerrainMapConfig>& TerrainMapSchema();

}  // namespace proxsim
