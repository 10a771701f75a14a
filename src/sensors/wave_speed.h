// The speed c of the wave a time-of-flight sensor times, which sets how far
// the sensor moves while its echo is in flight (flight_time, docs/sensors.md):
// sound in air for an ultrasonic sensor, light for the laser and the ideal
// sensor. A scenario may give its own c per sensor (wave_speed_m_s); 0 there
// means "by the sensor's type", resolved here and nowhere else.
#pragma once

#include "sensors/sensor_spec.h"

namespace proxsim {

/// Sound in dry air at about 20 °C, m/s (what ultrasonic rangers assume).
inline constexpr double kSpeedOfSoundInAir_m_s = 343.0;

/// Light in vacuum, m/s: exact, by the SI's definition of the metre.
inline constexpr double kSpeedOfLight_m_s = 299'792'458.0;

/// The c of a sensor of `type`: `wave_speed_m_s` when it is > 0 (the
/// scenario's override), else sound for ultrasonic and light for the rest.
double WaveSpeed_m_s(SensorType type, double wave_speed_m_s);

}  // namespace proxsim
