// The parameters of a proximity sensor (paper §5), as a plain struct with the
// paper's three sensors and an ideal one as named presets. Every value may be
// overridden per sensor in the scenario file; Validate() lists every violated
// condition at once.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace proxsim {

enum class SensorType { kIdeal, kLaser, kUltrasonic, kReflectance };

/// "ideal", "laser", "ultrasonic" or "reflectance".
const char* SensorTypeName(SensorType type);
/// The type named `name`, or nullopt.
std::optional<SensorType> SensorTypeFromName(std::string_view name);
/// Every type name, for messages.
const std::vector<std::string>& SensorTypeNames();

/// Gaussian noise N = σ·G + m of paper §4.3; it scales the reading by (1 + N).
struct NoiseSpec {
  double sigma = 0.0;  ///< standard deviation σ, dimensionless, >= 0
  double mean = 0.0;   ///< mean m, dimensionless
};

struct SensorSpec {
  SensorType type = SensorType::kIdeal;
  double min_range_m = 0.0;          ///< d_min: closer hits are `too_close`; >= 0
  double max_range_m = 2.0;          ///< d_max: farther hits are `no_echo`; > d_min
  double max_incidence_deg = 90.0;   ///< α*: hits at larger incidence are `grazing`; in [0, 90]
  NoiseSpec noise;

  /// The paper's values for a type (§5; the ideal sensor: [0, 2] m, 90°, no noise).
  static SensorSpec Preset(SensorType type);

  /// Every violated condition, one message each, worded after the scenario key; empty if valid.
  std::vector<std::string> Validate() const;
};

}  // namespace proxsim
