#include "sensors/wave_speed.h"

#include "sensors/sensor_types.h"

namespace proxsim {

double WaveSpeed_m_s(SensorType type, double wave_speed_m_s) {
  if (wave_speed_m_s > 0) return wave_speed_m_s;
  // a type that times no wave (reflectance, lookup) takes light's, as before: it never uses it
  const double by_type = TraitsOf(type).wave_speed_m_s;
  return by_type > 0 ? by_type : kSpeedOfLight_m_s;
}

}  // namespace proxsim
