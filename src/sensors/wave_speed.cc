#include "sensors/wave_speed.h"

namespace proxsim {

double WaveSpeed_m_s(SensorType type, double wave_speed_m_s) {
  if (wave_speed_m_s > 0) return wave_speed_m_s;
  return type == SensorType::kUltrasonic ? kSpeedOfSoundInAir_m_s : kSpeedOfLight_m_s;
}

}  // namespace proxsim
