// A strategy: the robot's decision-making in the closed loop. Every sample,
// after the sensors' readings are delivered (latency applied), the
// simulation hands the strategy what the robot knows — what its devices
// output and where its own kinematics put its sensors and feet — and the
// strategy commands the robot through RobotCommands.
//
// What it knows is knowledge/observation.h's, a module below both the gait and
// the strategies that sees no truth; a strategy reads the terrain map through
// Observation::map (knowledge/terrain_map.h).
//
// Frames: W world, P pelvis (the robot's root link), S a sensor.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "knowledge/observation.h"

namespace proxsim {

/// How long the way must stay clear on the map before a built-in strategy
/// stopped for an obstacle walks on: a person crossing has stepped well out
/// of the way (a second at walking pace is more than a body's width); a
/// static obstacle never clears.
inline constexpr double kClearBeforeWalkingOn_s = 1.0;

/// A stopped robot's wait for its way to clear: fed each sample whether the
/// way is clear, it says when it has stayed clear for kClearBeforeWalkingOn_s.
class WayClearWait {
 public:
  /// Whether the way, clear or not at t_s, has now been clear for kClearBeforeWalkingOn_s.
  bool StayedClear(bool clear, double t_s) {
    if (!clear) {
      clear_since_t_s_ = -1;
      return false;
    }
    if (clear_since_t_s_ < 0) clear_since_t_s_ = t_s;
    return t_s - clear_since_t_s_ >= kClearBeforeWalkingOn_s;
  }
  /// A new wait (the way not yet seen clear).
  void Restart() { clear_since_t_s_ = -1; }

 private:
  double clear_since_t_s_ = -1;  // when the way last became clear; < 0: not clear
};

/// What a strategy knows before the first sample of an episode.
struct StrategySetup {
  std::span<const SensorInfo> sensors;  ///< in scenario order
  std::vector<Vec2> path_m;             ///< the path the robot was given (world x-y), its goal last
  double rate_hz = 0.0;                 ///< samples per second
  double max_step_m = std::numeric_limits<double>::quiet_NaN();  ///< highest step up or down its legs take; NaN: not known
  double stride_m = std::numeric_limits<double>::quiet_NaN();    ///< the stride its gait walks at the start; NaN: not known
};

/// The commands a strategy (or a script driving the simulation) gives the robot.
/// They take effect from the next sample on.
class RobotCommands {
 public:
  virtual ~RobotCommands() = default;
  /// Stop at the next double support and stand there, both feet down.
  virtual void Stop() = 0;
  /// Walk again after a stop.
  virtual void Resume() = 0;
  /// Stride (heel strike to heel strike of one foot) from the next step on, m > 0.
  virtual void SetStride(double stride_m) = 0;
  /// Replaces the rest of the path (world x-y, metres); the gait turns toward
  /// it at heel strikes. A robot that stood at the end of its path walks again.
  virtual void SetPath(std::vector<Vec2> waypoints_m) = 0;
};

/// Something a strategy noticed or decided, for summary.json `robot.events`.
struct StrategyEvent {
  double t_s = 0.0;
  std::string event;   ///< short snake_case name: obstacle_seen, detour_planned, rejoined, stopped...
  std::string detail;  ///< one line for a person
};

/// Where a strategy writes its events.
class EventLog {
 public:
  virtual ~EventLog() = default;
  virtual void Log(std::string event, std::string detail) = 0;
};

class Strategy {
 public:
  virtual ~Strategy() = default;
  /// "stop", "circumvent", or a user strategy's own name.
  virtual std::string name() const = 0;
  /// A new episode starts: forget the last one.
  virtual void Reset(const StrategySetup& setup) = 0;
  /// One sample: look at what the robot knows, command it, log what matters.
  virtual void Decide(const Observation& observation, RobotCommands& robot, EventLog& events) = 0;
};

}  // namespace proxsim
