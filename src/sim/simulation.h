// The sampling loop, one step at a time: at every sample time t_k = k/rate_hz,
// place every sensor in the world (X_WS), cast all their rays in one batch,
// and turn each sensor's first hit into a reading with the paper's model.
// A sensor with a beam owns a contiguous range of rays in that one batch and
// is read with MeasureBeam. Timing (issue 7): a sensor with its own rate_hz
// is read only at the first run sample of each of its periods (status
// not_sampled otherwise); a latency delays what the strategy sees; with
// flight_time the receive point is the sensor's origin at the echo's return,
// extrapolated at the velocity it had between the last two samples.
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

#include "core/parallel.h"
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

  /// What the sensors had delivered by the last sample's time: a reading
  /// appears here at its t_reported_s (the first sample at or after it), and
  /// not_sampled otherwise. The same as frame() when no sensor has a latency.
  const SampleFrame& delivered() const { return latency_ ? delivered_ : frame_; }

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
  // place a sensor where its link is and fill its rays in rays_
  void PlaceSensor(std::size_t sensor);
  // cast every sensor's rays into hits_ and turn them into readings in frame_
  void ReadSensors();
  // one sensor's hits into its reading
  void MeasureSensor(std::size_t sensor);
  // below this many rays a sample is read on one thread (a fork costs more)
  static constexpr std::size_t kParallelReadRays = 512;
  // sensors read by one task: enough rays to outweigh the task's cost
  static constexpr std::size_t kSensorsPerTask = 4;
  // the robot's part of a step after the readings: strategy, state, and the
  // clearance measured during the step
  void UpdateRobot(double clearance_m);

  const Scenario& scenario_;
  std::int64_t sample_count_ = 0;
  std::int64_t next_sample_ = 0;
  ParallelRunner runner_;  // shares the sensors of a sample out over the threads
  RayCaster caster_;
  std::vector<std::string> object_names_;
  std::int32_t first_robot_object_id_ = 0;  // object ids from here on are robot links
  std::unique_ptr<RobotInScene> robot_;
  std::vector<int> sensor_link_;             // link index per sensor; -1 for world
  std::vector<std::int32_t> ground_ids_;     // objects the feet stand on, left out of the clearance
  std::optional<StopRule> stop_rule_;
  RobotOutcome outcome_;
  // the beams: sensor i owns rays [ray_begin_[i], ray_begin_[i + 1]) of every flat buffer
  std::vector<std::size_t> ray_begin_;
  std::vector<BeamRay> beam_rays_;  // the layout in the sensor frame
  std::vector<Ray> rays_;
  std::vector<Vec3> ray_dir_W_;     // each ray's direction in double precision
  std::vector<Hit> hits_;
  std::vector<Echo> echoes_;
  std::vector<Vec3> p_WS_previous_;  // each sensor's origin at the previous sample, for flight_time
  SampleFrame frame_;
  // latency: per sensor a ring of readings waiting to be delivered
  bool latency_ = false;
  struct Pending {
    std::vector<SensorSample> ring;
    std::size_t head = 0;
    std::size_t count = 0;
  };
  std::vector<Pending> pending_;
  SampleFrame delivered_;
  // the sensor's own sampling: whether sample k is one of its samples
  bool IsSensorSample(std::size_t sensor, std::int64_t sample) const;
  void Deliver();
};

}  // namespace proxsim
