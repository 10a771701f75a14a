#include "strategy/stop_strategy.h"

#include <cmath>
#include <cstdio>

namespace proxsim {

bool IsObstacleAhead(const SensorOutput& sensor, const RobotKnowledge& self, const StopConfig& rule) {
  if (!sensor.fresh || !sensor.detected) return false;
  // the point the sensor reports, not the truth
  const Vec3 p_W = sensor.p_W_measured();
  if (p_W.z() - self.ground_z_m < rule.min_height_m) return false;  // the floor
  const Vec3 lateral_W = Vec3::UnitZ().cross(self.heading_W);
  const Vec3 from_front = p_W - self.p_W_front;
  return from_front.dot(self.heading_W) <= rule.stop_distance_m &&
         std::abs(from_front.dot(lateral_W)) <= rule.corridor_half_width_m;
}

int FindObstacleAhead(const Observation& observation, const StopConfig& rule) {
  if (observation.robot == nullptr) return -1;
  for (std::size_t i = 0; i < observation.sensors.size(); ++i) {
    if (IsObstacleAhead(observation.sensors[i], *observation.robot, rule)) return static_cast<int>(i);
  }
  return -1;
}

void StopStrategy::Reset(const StrategySetup& setup) {
  stopping_ = false;
  sensor_names_.clear();
  for (const SensorInfo& sensor : setup.sensors) sensor_names_.push_back(sensor.name);
}

void StopStrategy::Decide(const Observation& observation, RobotCommands& robot, EventLog& events) {
  if (stopping_) return;
  const int trigger = FindObstacleAhead(observation, config_);
  if (trigger < 0) return;
  robot.Stop();
  stopping_ = true;
  const SensorOutput& sensor = observation.sensors[trigger];
  const Vec3 from_front = sensor.p_W_measured() - observation.robot->p_W_front;
  char detail[200];
  std::snprintf(detail, sizeof detail, "%s reports a point %.3f m ahead of the leading toe, %.3f m above the ground",
                sensor_names_.at(trigger).c_str(), from_front.dot(observation.robot->heading_W),
                sensor.p_W_measured().z() - observation.robot->ground_z_m);
  events.Log("obstacle_ahead", detail);
}

}  // namespace proxsim
