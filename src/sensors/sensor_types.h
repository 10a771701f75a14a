// Each sensor type's declaration in one table (sensor_types.cc): its name,
// the physics family its reading follows, the speed of the wave it times,
// whether its distance feeds the terrain map and the stop rule when the
// scenario does not list the map's sensors, and one line on what it reports.
// The scenario parser, the summary's echo, the terrain map, the wave speed
// and the docs read a type's facts from here; adding a type is a row here,
// its preset (sensor_spec.cc), its physics (sensor_model.cc, range_inverse.cc)
// and its keys (sensor_keys.cc), all in this folder.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "sensors/sensor_spec.h"

namespace proxsim {

/// What the rest of proxsim needs to know about a sensor type.
struct SensorTypeTraits {
  SensorType type;
  const char* name;            ///< the scenario's `type:` value
  bool time_of_flight;         ///< the reading is a timed echo (d_r from d), not a signal inverted to a distance
  double wave_speed_m_s;       ///< the wave it times, m/s (0 for a sensor that times nothing)
  bool feeds_map_by_default;   ///< its reported distance is a point on a surface (map.sensors absent)
  const char* reports;         ///< one line: what its reading is, for docs and messages
};

/// Every type's traits, in SensorType's code order.
std::span<const SensorTypeTraits> AllSensorTypeTraits();

/// The traits of `type`.
const SensorTypeTraits& TraitsOf(SensorType type);

/// The names of the types whose distance feeds the map when the scenario does
/// not list the map's sensors, as the summary states the default ("ideal,
/// laser, ultrasonic, lookup").
std::string DefaultMapSensorTypes();

}  // namespace proxsim
