// A part's distance modes (`distance_mode:`): the VL53L1X ranges in short,
// medium or long mode, each with its own longest range by target and light
// and its own ranging error (ST VL53L1X datasheet DocID031281 Rev 3, Tables
// 4, 6, 7 and 8; docs/sensors.md cites every row). A mode sets the part's
// range_m, range_table and noise.sigma_table; the scenario's keys still
// override any of them.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "sensors/sensor_spec.h"

namespace proxsim {

struct DistanceMode {
  const char* part;           ///< the part it belongs to
  const char* name;           ///< "short", "medium", "long"
  double max_range_m;         ///< the table's longest range
  std::vector<std::array<double, 3>> range_table;  ///< [reflectance, ambient_klux, max_range_m]
  std::vector<std::array<double, 3>> sigma_table;  ///< [reflectance, ambient_klux, σ m] (additive)
};

/// Every distance mode of every part.
std::span<const DistanceMode> DistanceModes();
/// The mode `name` of `part`, or null.
const DistanceMode* FindDistanceMode(const std::string& part, const std::string& name);
/// The names of a part's modes, "short, medium, long" ("" without modes).
std::string DistanceModeNames(const std::string& part);
/// Where the modes' figures come from.
inline constexpr const char* kDistanceModeSource =
    "ST VL53L1X datasheet DocID031281 Rev 3, Tables 4, 6-8 (100 ms timing budget)";
/// The part's default mode ("" without modes).
std::string DefaultDistanceMode(const std::string& part);

/// Sets the spec's distance_mode, range, range table and σ table from `mode`.
void ApplyDistanceMode(const DistanceMode& mode, SensorSpec& spec);

}  // namespace proxsim
