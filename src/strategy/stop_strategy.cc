#include "strategy/stop_strategy.h"

#include <cmath>
#include <cstdio>

#include "strategy/drop_ahead.h"

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

namespace {

// Fresh readings in a row that must show the floor missing.
constexpr int kFloorMissingReadings = 2;

}  // namespace

void StopStrategy::Reset(const StrategySetup& setup) {
  stopping_ = false;
  sensors_.assign(setup.sensors.begin(), setup.sensors.end());
  max_drop_m_ = config_.max_drop_m > 0 ? config_.max_drop_m : setup.max_step_m;
  floor_missing_streak_.assign(sensors_.size(), 0);
}

void StopStrategy::Decide(const Observation& observation, RobotCommands& robot, EventLog& events) {
  if (stopping_ || observation.robot == nullptr) return;
  const RobotKnowledge& self = *observation.robot;
  char detail[240];
  if (const int trigger = FindObstacleAhead(observation, config_); trigger >= 0) {
    const SensorOutput& sensor = observation.sensors[trigger];
    const Vec3 from_front = sensor.p_W_measured() - self.p_W_front;
    std::snprintf(detail, sizeof detail, "%s reports a point %.3f m ahead of the leading toe, %.3f m above the ground",
                  sensors_.at(trigger).name.c_str(), from_front.dot(self.heading_W),
                  sensor.p_W_measured().z() - self.ground_z_m);
    robot.Stop();
    stopping_ = true;
    events.Log("obstacle_ahead", detail);
    return;
  }
  for (std::size_t i = 0; i < observation.sensors.size() && i < sensors_.size(); ++i) {
    const SensorOutput& sensor = observation.sensors[i];
    if (!sensor.fresh) continue;  // no news: the streak stands
    const std::optional<DropSign> drop = SeeDropAhead(sensor, sensors_[i], self, config_, max_drop_m_);
    floor_missing_streak_[i] = drop && drop->floor_missing ? floor_missing_streak_[i] + 1 : 0;
    if (!drop || (drop->floor_missing && floor_missing_streak_[i] < kFloorMissingReadings)) continue;
    if (drop->floor_missing) {
      std::snprintf(detail, sizeof detail,
                    "%s reports nothing where the floor should be: its axis passes %.3f m below the ground %.3f m "
                    "ahead of the leading toe with nothing in the way, a drop deeper than %.2f m",
                    sensors_[i].name.c_str(), drop->below_m, drop->ahead_m, max_drop_m_);
    } else {
      std::snprintf(detail, sizeof detail,
                    "%s reports a point %.3f m ahead of the leading toe, %.3f m below the ground: a drop deeper "
                    "than %.2f m",
                    sensors_[i].name.c_str(), drop->ahead_m, drop->below_m, max_drop_m_);
    }
    robot.Stop();
    stopping_ = true;
    events.Log("drop_ahead", detail);
    return;
  }
}

}  // namespace proxsim
