#include "strategy/stop_strategy.h"

#include <cmath>
#include <cstdio>

#include "knowledge/echo_cone.h"
#include "knowledge/map_queries.h"
#include "strategy/drop_ahead.h"

namespace proxsim {

namespace {

// whether a reported point is in the robot's way (its height judged by the caller)
bool PointIsAhead(const Vec3& p_W, const RobotKnowledge& self, const StopConfig& rule) {
  const Vec3 lateral_W = Vec3::UnitZ().cross(self.heading_W);
  const Vec3 from_front = p_W - self.p_W_front;
  return from_front.dot(self.heading_W) <= rule.stop_distance_m &&
         std::abs(from_front.dot(lateral_W)) <= rule.corridor_half_width_m;
}

}  // namespace

std::optional<Vec3> ObstaclePointAhead(const SensorOutput& sensor, const SensorInfo& info, const RobotKnowledge& self,
                                       const StopConfig& rule) {
  // the points the sensor reports, not the truth: its reading's (raised
  // wherever in its cone the echo came from: knowledge/echo_cone.h), and
  // every one the part reports beside it (a multi-zone part's targets, a beam's echoes)
  std::optional<Vec3> ahead;
  ForEachRaisedEcho(sensor, info, self.ground_z_m, rule.min_height_m, [&](const Measurement& measurement) {
    if (!ahead && PointIsAhead(measurement.p_W(), self, rule)) ahead = measurement.p_W();
  });
  return ahead;
}

bool IsObstacleAhead(const SensorOutput& sensor, const SensorInfo& info, const RobotKnowledge& self,
                     const StopConfig& rule) {
  return ObstaclePointAhead(sensor, info, self, rule).has_value();
}

int FindObstacleAhead(const Observation& observation, std::span<const SensorInfo> sensors, const StopConfig& rule) {
  if (observation.robot == nullptr) return -1;
  for (std::size_t i = 0; i < observation.sensors.size() && i < sensors.size(); ++i) {
    if (IsObstacleAhead(observation.sensors[i], sensors[i], *observation.robot, rule)) return static_cast<int>(i);
  }
  return -1;
}

namespace {

// Fresh readings in a row that must show the floor missing.
constexpr int kFloorMissingReadings = 2;

}  // namespace

void StopStrategy::Reset(const StrategySetup& setup) {
  stopping_ = stopped_for_map_obstacle_ = false;
  corridor_clear_.Restart();
  sensors_.assign(setup.sensors.begin(), setup.sensors.end());
  max_drop_m_ = config_.max_drop_m > 0 ? config_.max_drop_m : setup.max_step_m;
  floor_missing_streak_.assign(sensors_.size(), 0);
}

void StopStrategy::Decide(const Observation& observation, RobotCommands& robot, EventLog& events) {
  if (observation.robot == nullptr) return;
  if (stopping_ && !stopped_for_map_obstacle_) return;
  const RobotKnowledge& self = *observation.robot;
  char detail[240];
  if (config_.perception == Perception::kMap) {
    // the map's obstacles in the corridor ahead of the leading toe, centred
    // on the pelvis's line (both feet's, not the leading foot's: furniture
    // beside the path is not in the way); the legs plan steps and holes on their own map
    if (observation.map == nullptr) return;
    const Vec2 heading = self.heading_W.head<2>().normalized();
    const Vec2 p_WP = self.X_WP.translation().head<2>();
    const Vec2 from = p_WP + (self.p_W_front.head<2>() - p_WP).dot(heading) * heading;
    const Hazard* obstacle =
        ObstacleInCorridor(*observation.map, from, heading, config_.stop_distance_m, config_.corridor_half_width_m);
    if (stopping_) {
      // stopped for something the map showed: a person who walked on leaves
      // the corridor clear, and the robot walks again once it has stayed clear
      if (corridor_clear_.StayedClear(obstacle == nullptr, observation.t_s)) {
        robot.Resume();
        stopping_ = stopped_for_map_obstacle_ = false;
        corridor_clear_.Restart();
        std::snprintf(detail, sizeof detail, "the corridor ahead has been clear for %.1f s: walking on",
                      kClearBeforeWalkingOn_s);
        events.Log("walking_on", detail);
      }
      return;
    }
    if (obstacle == nullptr) return;
    std::snprintf(detail, sizeof detail,
                  "the map shows an obstacle %.2f m high over (%.2f, %.2f)-(%.2f, %.2f), %.3f m from the leading toe",
                  obstacle->height_m, obstacle->min_W.x(), obstacle->min_W.y(), obstacle->max_W.x(),
                  obstacle->max_W.y(), obstacle->DistanceTo(self.p_W_front.head<2>()));
    robot.Stop();
    stopping_ = stopped_for_map_obstacle_ = true;
    events.Log("obstacle_ahead", detail);
    return;
  }
  if (const int trigger = FindObstacleAhead(observation, sensors_, config_); trigger >= 0) {
    const Vec3 p_W = *ObstaclePointAhead(observation.sensors[trigger], sensors_[trigger], self, config_);
    const Vec3 from_front = p_W - self.p_W_front;
    std::snprintf(detail, sizeof detail, "%s reports a point %.3f m ahead of the leading toe, %.3f m above the ground",
                  sensors_.at(trigger).name.c_str(), from_front.dot(self.heading_W), p_W.z() - self.ground_z_m);
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
