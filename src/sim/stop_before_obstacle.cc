#include "sim/stop_before_obstacle.h"

#include <cmath>

namespace proxsim {

int FindStopTrigger(const SampleFrame& frame, const RobotSelfKnowledge& self, const StopRule& rule) {
  const Vec3 lateral_W = Vec3::UnitZ().cross(self.heading_W);
  for (std::size_t i = 0; i < frame.sensors.size(); ++i) {
    const SensorSample& s = frame.sensors[i];
    if (!s.reading.detected()) continue;
    // the point the sensor reports, not the truth
    const Vec3 p_W = s.p_WS + s.reading.d_m * s.dir_W;
    if (p_W.z() - self.ground_z_m < rule.min_height_m) continue;  // the floor
    const Vec3 from_front = p_W - self.p_W_front;
    const double ahead_m = from_front.dot(self.heading_W);
    const double aside_m = from_front.dot(lateral_W);
    if (ahead_m <= rule.stop_distance_m && std::abs(aside_m) <= rule.corridor_half_width_m) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

}  // namespace proxsim
