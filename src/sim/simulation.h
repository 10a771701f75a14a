// The sampling loop, one step at a time: at every sample time t_k = k/rate_hz,
// place every sensor in the world (X_WS), cast all their rays in one batch,
// and turn each sensor's first hit into a reading with the paper's model.
// All state lives in this object, so a run, a test or a strategy written in
// another language can step it sample by sample.
//
// Frames: W world, L a link a sensor is fixed on ("world" is W itself), S a sensor.
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/scenario.h"
#include "raycast/ray_caster.h"
#include "sim/robot_in_scene.h"
#include "sim/sample_frame.h"
#include "sim/stop_before_obstacle.h"

namespace proxsim {

class Simulation {
 public:
  /// Builds the scene's acceleration structures; `threads` >= 1 for ray casting.
  Simulation(const Scenario& scenario, int threads);
  ~Simulation();

  /// True once every sample of the run has been taken.
  bool done() const { return next_sample_ >= sample_count_; }

  /// Takes the next sample and returns it (valid until the next Step).
  const SampleFrame& Step();

  /// The last sample taken.
  const SampleFrame& frame() const { return frame_; }

  std::int64_t sample_count() const { return sample_count_; }
  const Scenario& scenario() const { return scenario_; }

  /// Name of an object id as found in SensorSample::object_id.
  const std::string& object_name(std::int32_t object_id) const { return object_names_.at(object_id); }
  std::size_t object_count() const { return object_names_.size(); }

  /// The robot, or null when the scenario has none (world-mounted sensors only).
  const RobotInScene* robot() const { return robot_.get(); }
  RobotInScene* robot() { return robot_.get(); }

  /// What the run knows of the robot so far (DESIGN.md summary `robot`).
  struct RobotOutcome {
    bool stop_requested = false;
    double stop_request_t_s = 0;   ///< when the strategy asked for a stop
    int stop_trigger_sensor = -1;  ///< whose reading triggered it
    bool stopped = false;
    double stop_t_s = 0;           ///< when the robot stood still
    double min_clearance_m = std::numeric_limits<double>::infinity();
    double min_clearance_t_s = 0;
  };
  const RobotOutcome& robot_outcome() const { return outcome_; }

 private:
  // place the sensors where their links are and fill rays_ (one ray per sensor)
  void PlaceSensors();
  // turn hits_ into readings in frame_
  void MeasureAll();
  // the robot's part of a step after the readings: strategy, clearance, state
  void UpdateRobot();

  const Scenario& scenario_;
  std::int64_t sample_count_ = 0;
  std::int64_t next_sample_ = 0;
  RayCaster caster_;
  std::vector<std::string> object_names_;
  std::int32_t first_robot_object_id_ = 0;  // object ids from here on are robot links
  std::unique_ptr<RobotInScene> robot_;
  std::vector<int> sensor_link_;             // link index per sensor; -1 for world
  std::vector<std::int32_t> ground_ids_;     // objects the feet stand on, left out of the clearance
  std::optional<StopRule> stop_rule_;
  RobotOutcome outcome_;
  std::vector<Ray> rays_;
  std::vector<Hit> hits_;
  SampleFrame frame_;
};

}  // namespace proxsim
