// The built-in strategy `stop`: stop before an obstacle or a drop. It looks
// only at what the robot knows: a fresh detection whose measured point stands
// higher than min_height_m above the ground the robot stands on, inside the
// corridor it walks along and within stop_distance_m ahead of its leading toe
// (an obstacle), or a drop deeper than max_drop_m (by default the legs'
// gait.max_step_m) seen there (strategy/drop_ahead.h: a point well below the
// ground, or the floor missing where a sensor should see it, on two fresh
// readings in a row of the same sensor, so that one lost echo, a dropout, does
// not stop the robot), makes the robot stop at its next double support.
// Events: `obstacle_ahead`, `drop_ahead`, `walking_on`. It stays stopped,
// but for an obstacle of the map (`perception: map`) that leaves its corridor:
// once the corridor has stayed clear for a second — a person who crossed has
// walked on — it walks on.
#pragma once

#include <optional>
#include <span>

#include <vector>

#include "strategy/strategy.h"
#include "strategy/strategy_config.h"

namespace proxsim {

/// Whether one sensor's output is a fresh detection in the corridor within the
/// look-ahead, at least min_height_m above the ground wherever in its beam's
/// cone the echo came from (knowledge/echo_cone.h; a zone: its axis point).
bool IsObstacleAhead(const SensorOutput& sensor, const SensorInfo& info, const RobotKnowledge& self,
                     const StopConfig& rule);
/// The reported point that makes it one (the reading's, else the first zone's), or nullopt.
std::optional<Vec3> ObstaclePointAhead(const SensorOutput& sensor, const SensorInfo& info, const RobotKnowledge& self,
                                       const StopConfig& rule);

/// The first sensor whose fresh detection is an obstacle ahead (IsObstacleAhead;
/// `sensors` in the observation's order); -1 when none does.
int FindObstacleAhead(const Observation& observation, std::span<const SensorInfo> sensors, const StopConfig& rule);

class StopStrategy : public Strategy {
 public:
  explicit StopStrategy(StopConfig config) : config_(config) {}

  std::string name() const override { return "stop"; }
  void Reset(const StrategySetup& setup) override;
  void Decide(const Observation& observation, RobotCommands& robot, EventLog& events) override;

 private:
  StopConfig config_;
  std::vector<SensorInfo> sensors_;
  double max_drop_m_ = 0;  // NaN: the legs' step is not known, no drop rule
  std::vector<int> floor_missing_streak_;  // per sensor: fresh readings in a row with the floor missing
  bool stopping_ = false;
  bool stopped_for_map_obstacle_ = false;  // the stop is the map's obstacle's: it may clear
  WayClearWait corridor_clear_;            // the wait for the corridor to clear
};

}  // namespace proxsim
