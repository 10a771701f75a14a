// The closed loop, one sample at a time. A Simulation owns its scenario, its
// sensor rig (sim/sensor_rig.h), the robot's Locomotion and an optional
// Strategy, and one episode's state (time, pending readings, outcome, events);
// it runs on a World (bodies, acceleration structures, object table) built
// from the scenario once — its own, or one shared with other simulations of
// the same scene and robot in turn (BuildWorld). Reset(seed) starts a new
// episode on the same world.
//
// Every sample t_k = k / rate_hz:
//   locomotion(t) ─► robot FK ─► sensors read (SensorReader) ─► SampleFrame (with truth)
//   delivered readings (latency) ─► Observation (no truth) ─► terrain map ─► strategy ─► RobotCommands
// Commands (from the strategy, or from a script through commands()) take
// effect from the next sample on.
//
// Frames: W world, P pelvis, L a link, S a sensor.
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <array>
#include <string_view>
#include <span>
#include <string>
#include <vector>

#include "core/parallel.h"
#include "gait/external_drive.h"
#include "gait/locomotion.h"
#include "scenario/scenario.h"
#include "sim/contacts.h"
#include "sim/delivery_queue.h"
#include "sim/map_terrain.h"
#include "referee/referee.h"
#include "sim/sample_frame.h"
#include "sim/sensor_reader.h"
#include "sim/sensor_rig.h"
#include "sim/truth_map_feed.h"
#include "sim/world.h"
#include "strategy/strategy.h"
#include "knowledge/terrain_map.h"

namespace proxsim {

/// A person does not step nearer than this (torso to pelvis, horizontally)
/// to a robot on the move (walking, or its last step under way after a stop):
/// it waits (World::HoldPeopleNear), yielding as pedestrians yield to a
/// vehicle. Two people's comfortable passing distance, about 0.45 m each of
/// body and margin.
inline constexpr double kPedestrianKeep_m = 0.9;
/// A robot standing still is passed by a person whose walk stays at least
/// this far from it (torso to pelvis): it passes in front of a robot that
/// stopped for it (which then walks on), and waits (kPedestrianKeep_m) rather
/// than walk into it — the person's shoulders (about 0.25 m) and the robot's
/// torso (0.23 m to a corner for the built-in biped) or toes touch at about
/// 0.45 m, and a person's foot swings up to about 0.35 m ahead of its torso.
inline constexpr double kPedestrianPassStanding_m = 0.8;

/// A world for simulations of scenarios with this one's scene and robot
/// (their sensors, strategies, gaits and maps free), built once and shared:
/// each simulation takes it in turn. Throws InputError on a bad robot model.
std::shared_ptr<World> BuildWorld(const Scenario& scenario, int threads);

class Simulation {
 public:
  /// The scenario's own robot motion (gait or trajectory) and strategy;
  /// `threads` >= 1 for ray casting. Throws InputError on bad input.
  explicit Simulation(Scenario scenario, int threads = 1);

  /// The same on a world built already (BuildWorld) from a scenario with the
  /// same scene and robot (std::invalid_argument naming what differs): the
  /// world is this simulation's until it is destroyed (std::logic_error if
  /// another simulation holds it), and its episode starts afresh.
  Simulation(Scenario scenario, int threads, std::shared_ptr<World> world);

  /// With an injected locomotion (null: the scenario's own, or none without
  /// a robot section) and strategy (null: none, whatever the scenario says).
  Simulation(Scenario scenario, int threads, std::unique_ptr<Locomotion> locomotion,
             std::unique_ptr<Strategy> strategy);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Starts a new episode on the same world, with noise keyed by `seed`:
  /// sample 0 next, the robot at its start, nothing in flight, no outcome.
  void Reset(std::uint64_t seed);

  /// True once every sample of the episode has been taken, or the episode
  /// ended early: the robot collided (robot.on_collision: stop) or fell.
  bool done() const { return next_sample_ >= sample_count_ || referee_->robot().ended; }

  /// Takes the next sample and returns it (valid until the next Step). Requires !done()
  /// and a robot that moves by itself (not robot.locomotion: external).
  const SampleFrame& Step();

  /// Co-simulation (robot.locomotion: external): places the robot in `state`
  /// and takes the next sample there, measured as for the robot's own gait.
  /// Throws InputError naming every fault of the state (nothing changes then),
  /// std::logic_error when done() or when the robot is not driven from outside.
  const SampleFrame& Step(const ExternalState& state);

  /// The external drive when robot.locomotion is external (its joint_names()
  /// give ExternalState::q's order, JointVector() builds it by name); null otherwise.
  const ExternalDrive* external() const { return external_; }

  /// The last sample taken, with the truth beside every reading.
  const SampleFrame& frame() const { return frame_; }

  /// What the sensors had delivered by the last sample's time: a reading
  /// appears here at its t_reported_s (the first sample at or after it), and
  /// not_sampled otherwise. The same as frame() when no sensor has a latency.
  /// What the robot's datasheets and mountings tell it about each sensor (scenario order).
  std::span<const SensorInfo> sensor_info() const { return sensor_info_; }
  const SampleFrame& delivered() const;

  /// What the robot knew at the last sample: the strategy's input.
  const Observation& observation() const { return observation_; }

  /// The terrain map built from the delivered readings (what Observation::map
  /// points to); null without a robot or with `map: {enabled: false}`.
  const TerrainMap* terrain_map() const { return terrain_map_.get(); }

  /// The robot's command interface (the strategy's, shared with scripts); null without a robot.
  RobotCommands* commands();

  std::int64_t sample_count() const { return sample_count_; }
  std::int64_t samples_taken() const { return next_sample_; }
  const Scenario& scenario() const { return scenario_; }
  const World& world() const { return *world_; }
  /// Where each sensor is fixed and its rays (scenario order).
  const SensorRig& rig() const { return *rig_; }

  /// Name of an object id as found in SensorSample::object_id.
  const std::string& object_name(std::int32_t object_id) const { return world_->object_name(object_id); }
  std::size_t object_count() const { return world_->object_names().size(); }

  /// The robot's bodies and its state at the last sample; null without a robot.
  const RobotInScene* robot() const { return world_->robot(); }
  const RobotState* robot_state() const { return locomotion_ ? &state_ : nullptr; }
  const Locomotion* locomotion() const { return locomotion_.get(); }
  const Strategy* strategy() const { return strategy_.get(); }

  /// What the episode knows of the robot so far (summary.json `robot`; referee/referee.h).
  using RobotOutcome = proxsim::RobotOutcome;
  using Outcome = proxsim::EpisodeOutcome;
  /// The episode's outcome as the referee judges it (referee/referee.h): reached_goal, stopped
  /// (by its strategy, standing), collided, fell, refused (standing before an
  /// unsafe step its legs refused) or time_up; with its time and a line for a person.
  Outcome outcome() const;
  const RobotOutcome& robot_outcome() const;

  /// The strategy's events and the episode's own (stopped, goal_reached), in time order.
  const std::vector<StrategyEvent>& events() const { return events_; }

 private:
  class Commands;
  class Events;
  void Build(int threads, std::unique_ptr<Locomotion> locomotion, std::unique_ptr<Strategy> strategy,
             std::shared_ptr<World> world = nullptr);
  // the sample itself, the robot's motion ready
  const SampleFrame& TakeSample();
  void FillObservation();
  StrategySetup MakeSetup() const;
  std::unique_ptr<TerrainMap> MakeTerrainMap() const;
  // this sample's contacts, named for the referee (scene objects by the world, links by the model)
  std::vector<BodyContact> NamedContacts() const;

  Scenario scenario_;
  std::int64_t sample_count_ = 0;
  std::int64_t next_sample_ = 0;
  ParallelRunner runner_;  // shares the sensors of a sample out over the threads
  std::unique_ptr<Locomotion> locomotion_;
  ExternalDrive* external_ = nullptr;  // locomotion_ when it is driven from outside
  std::shared_ptr<World> world_;      // claimed by this simulation while it lives
  std::unique_ptr<SensorRig> rig_;
  std::unique_ptr<SensorReader> reader_;
  std::unique_ptr<DeliveryQueue> delivery_;
  std::unique_ptr<Strategy> strategy_;
  std::unique_ptr<Commands> commands_;
  std::unique_ptr<Events> event_log_;
  std::unique_ptr<TerrainMap> terrain_map_;
  std::unique_ptr<TruthMapFeed> truth_feed_;  // perfect perception for the map (map.truth_within_m), or null
  std::unique_ptr<TerrainQuery> map_footholds_;  // the map as the gait's footholds terrain (gait.footholds: map), or null
  std::vector<SensorInfo> sensor_info_;
  std::vector<FootFrame> feet_;
  double half_width_m_ = 0;
  std::unique_ptr<Referee> referee_;  // judges the episode (fed only with a robot)
  // the episode
  RobotState state_;
  SampleFrame frame_;
  SampleFrame delivered_;
  std::vector<SensorOutput> outputs_;
  RobotKnowledge knowledge_;
  Observation observation_;
  std::vector<StrategyEvent> events_;
  std::unique_ptr<ContactFinder> contacts_;         // null without a robot
  std::vector<Contact> contacts_now_;  // this sample's
};

}  // namespace proxsim
