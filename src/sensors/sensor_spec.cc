#include "sensors/sensor_spec.h"

#include <cmath>
#include <sstream>

namespace proxsim {

namespace {
struct TypeName {
  SensorType type;
  const char* name;
};
constexpr TypeName kTypeNames[] = {
    {SensorType::kIdeal, "ideal"},
    {SensorType::kLaser, "laser"},
    {SensorType::kUltrasonic, "ultrasonic"},
    {SensorType::kReflectance, "reflectance"},
};
}  // namespace

const char* SensorTypeName(SensorType type) {
  for (const auto& entry : kTypeNames) {
    if (entry.type == type) return entry.name;
  }
  return "?";
}

std::optional<SensorType> SensorTypeFromName(std::string_view name) {
  for (const auto& entry : kTypeNames) {
    if (name == entry.name) return entry.type;
  }
  return std::nullopt;
}

const std::vector<std::string>& SensorTypeNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const auto& entry : kTypeNames) all.emplace_back(entry.name);
    return all;
  }();
  return names;
}

SensorSpec SensorSpec::Preset(SensorType type) {
  SensorSpec spec;
  spec.type = type;
  switch (type) {
    case SensorType::kIdeal:  // exact distances, for comparison (the paper's Fig. 8)
      spec.min_range_m = 0.0;
      spec.max_range_m = 2.0;
      spec.max_incidence_deg = 90.0;
      spec.noise = {0.0, 0.0};
      break;
    case SensorType::kLaser:  // §5 "A laser range finder"
      spec.min_range_m = 0.0;
      spec.max_range_m = 2.0;
      spec.max_incidence_deg = 45.0;
      spec.noise = {0.01, 0.0};
      break;
    case SensorType::kUltrasonic:  // §5 "An ultrasonic sensor"
      spec.min_range_m = 0.1;
      spec.max_range_m = 1.0;
      spec.max_incidence_deg = 15.0;
      spec.noise = {0.01, 0.0};
      break;
    case SensorType::kReflectance:  // §5 "A reflectance sensor"
      spec.min_range_m = 0.0;
      spec.max_range_m = 1.0;
      spec.max_incidence_deg = 90.0;
      spec.noise = {0.01, 0.0};
      break;
  }
  return spec;
}

std::vector<std::string> SensorSpec::Validate() const {
  std::vector<std::string> problems;
  auto fail = [&](const std::string& key, const std::string& expected, double got) {
    std::ostringstream message;
    message << key << ": expected " << expected << ", got " << got;
    problems.push_back(message.str());
  };
  auto finite = [](double v) { return std::isfinite(v); };
  if (!finite(min_range_m) || min_range_m < 0) fail("range_m[0]", "a finite minimum range >= 0 m", min_range_m);
  if (!finite(max_range_m) || max_range_m <= 0) fail("range_m[1]", "a finite maximum range > 0 m", max_range_m);
  if (finite(min_range_m) && finite(max_range_m) && max_range_m <= min_range_m) {
    fail("range_m", "[min, max] with min < max (max given)", max_range_m);
  }
  if (!finite(max_incidence_deg) || max_incidence_deg < 0 || max_incidence_deg > 90) {
    fail("max_incidence_deg", "an angle in [0, 90] degrees", max_incidence_deg);
  }
  if (!finite(noise.sigma) || noise.sigma < 0) fail("noise.sigma", "a finite standard deviation >= 0", noise.sigma);
  if (!finite(noise.mean)) fail("noise.mean", "a finite mean", noise.mean);
  return problems;
}

}  // namespace proxsim
