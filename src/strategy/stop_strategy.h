// The built-in strategy `stop`: stop before an obstacle. It looks only at what
// the robot knows: a fresh detection whose measured point stands higher than
// min_height_m above the ground the robot stands on, inside the corridor it
// walks along and within stop_distance_m ahead of its leading toe, makes the
// robot stop at its next double support. It stops once and stays stopped.
#pragma once

#include "strategy/strategy.h"
#include "strategy/strategy_config.h"

namespace proxsim {

/// Whether one sensor's output is a fresh detection in the corridor within the
/// look-ahead, at least min_height_m above the ground.
bool IsObstacleAhead(const SensorOutput& sensor, const RobotKnowledge& self, const StopConfig& rule);

/// The first sensor whose fresh detection stands in the corridor within the
/// look-ahead, at least min_height_m above the ground; -1 when none does.
int FindObstacleAhead(const Observation& observation, const StopConfig& rule);

class StopStrategy : public Strategy {
 public:
  explicit StopStrategy(StopConfig config) : config_(config) {}

  std::string name() const override { return "stop"; }
  void Reset(const StrategySetup& setup) override;
  void Decide(const Observation& observation, RobotCommands& robot, EventLog& events) override;

 private:
  StopConfig config_;
  std::vector<std::string> sensor_names_;
  bool stopping_ = false;
};

}  // namespace proxsim
