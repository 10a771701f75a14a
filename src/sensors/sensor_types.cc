#include "sensors/sensor_types.h"

#include <cassert>

#include "sensors/wave_speed.h"

namespace proxsim {

namespace {

// One row per type, in code order. The reflectance sensor's distance is an
// inverted signal that depends on the surface's albedo and angle (paper §5),
// so it does not place points on the map unless the scenario lists it.
constexpr SensorTypeTraits kTraits[] = {
    {SensorType::kIdeal, "ideal", true, kSpeedOfLight_m_s, true, "the exact distance of the first hit (paper Fig. 8)"},
    {SensorType::kLaser, "laser", true, kSpeedOfLight_m_s, true, "d·(1 + N) within [0, 2] m and 45° (paper §5)"},
    {SensorType::kUltrasonic, "ultrasonic", true, kSpeedOfSoundInAir_m_s, true,
     "d·(1 + N) within [0.1, 1] m and 15° (paper §5)"},
    {SensorType::kReflectance, "reflectance", false, 0.0, false,
     "the IR signal of Eq. (1) and the distance it implies (paper §5)"},
    {SensorType::kLookup, "lookup", false, 0.0, true,
     "a datasheet table's output at d and the distance it implies (Webots' lookupTable)"},
    {SensorType::kMultizone, "multizone", true, kSpeedOfLight_m_s, true,
     "a grid of zones, each with up to 4 targets' distances and ST's status codes (multizone.h)"},
};

constexpr bool InCodeOrder() {
  for (std::size_t i = 0; i < std::size(kTraits); ++i)
    if (static_cast<std::size_t>(kTraits[i].type) != i) return false;
  return true;
}
static_assert(InCodeOrder(), "kTraits must list the types in SensorType's code order");

}  // namespace

std::span<const SensorTypeTraits> AllSensorTypeTraits() { return kTraits; }

const SensorTypeTraits& TraitsOf(SensorType type) {
  const auto code = static_cast<std::size_t>(type);
  assert(code < std::size(kTraits));
  return kTraits[code];
}

std::string DefaultMapSensorTypes() {
  std::string names;
  for (const SensorTypeTraits& traits : kTraits) {
    if (traits.feeds_map_by_default) names += (names.empty() ? "" : ", ") + std::string(traits.name);
  }
  return names;
}

}  // namespace proxsim
