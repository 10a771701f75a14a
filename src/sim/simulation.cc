#include "sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "core/input_error.h"
#include "sensors/sensor_types.h"
#include "sim/make_locomotion.h"
#include "sim/robot_knowledge.h"
#include "sim/start_check.h"
#include "strategy/make_strategy.h"

namespace proxsim {

// The robot's commands: forwarded to the locomotion, the first stop recorded.
class Simulation::Commands : public RobotCommands {
 public:
  explicit Commands(Simulation& sim) : sim_(sim) {}
  void Stop() override {
    sim_.referee_->StopCommanded(sim_.frame_.t_s);
    sim_.locomotion_->RequestStop();
  }
  void Resume() override {
    sim_.referee_->Resumed();
    sim_.locomotion_->Resume();
  }
  void SetStride(double stride_m) override {
    if (!(stride_m > 0) || !std::isfinite(stride_m)) {
      throw std::invalid_argument("SetStride: the stride must be a finite number of metres > 0, got " +
                                  std::to_string(stride_m));
    }
    sim_.locomotion_->SetStride(stride_m);
  }
  void SetPath(std::vector<Vec2> waypoints_m) override {
    for (const Vec2& p : waypoints_m) {
      if (!p.allFinite()) throw std::invalid_argument("SetPath: every waypoint must be a finite [x, y] in metres");
    }
    sim_.locomotion_->SetPath(std::move(waypoints_m));
  }

 private:
  Simulation& sim_;
};

// The event log: every entry stamped with the last sample's time.
class Simulation::Events : public EventLog {
 public:
  explicit Events(Simulation& sim) : sim_(sim) {}
  void Log(std::string event, std::string detail) override {
    sim_.events_.push_back({sim_.frame_.t_s, std::move(event), std::move(detail)});
  }

 private:
  Simulation& sim_;
};

Simulation::Simulation(Scenario scenario, int threads)
    : scenario_(std::move(scenario)), sample_count_(scenario_.SampleCount()), runner_(threads) {
  std::unique_ptr<Strategy> strategy;
  if (scenario_.robot && scenario_.robot->strategy) strategy = MakeStrategy(*scenario_.robot->strategy);
  Build(threads, nullptr, std::move(strategy));
}

Simulation::Simulation(Scenario scenario, int threads, std::shared_ptr<World> world)
    : scenario_(std::move(scenario)), sample_count_(scenario_.SampleCount()), runner_(threads) {
  if (!world) throw std::invalid_argument("Simulation: no world given");
  if (const std::string mismatch = world->MismatchWith(scenario_); !mismatch.empty())
    throw std::invalid_argument("Simulation: the world was built from another scene or robot: " + mismatch);
  std::unique_ptr<Strategy> strategy;
  if (scenario_.robot && scenario_.robot->strategy) strategy = MakeStrategy(*scenario_.robot->strategy);
  Build(threads, nullptr, std::move(strategy), std::move(world));
}

std::shared_ptr<World> BuildWorld(const Scenario& scenario, int threads) {
  std::optional<RobotModel> model;
  if (scenario.robot) model = LoadRobotModel(*scenario.robot);
  return std::make_shared<World>(scenario, model ? &*model : nullptr, threads);
}

Simulation::Simulation(Scenario scenario, int threads, std::unique_ptr<Locomotion> locomotion,
                       std::unique_ptr<Strategy> strategy)
    : scenario_(std::move(scenario)), sample_count_(scenario_.SampleCount()), runner_(threads) {
  Build(threads, std::move(locomotion), std::move(strategy));
}

Simulation::~Simulation() {
  if (world_) world_->Release(this);
}

const SampleFrame& Simulation::delivered() const { return delivery_->active() ? delivered_ : frame_; }

RobotCommands* Simulation::commands() { return commands_.get(); }

void Simulation::Build(int threads, std::unique_ptr<Locomotion> locomotion, std::unique_ptr<Strategy> strategy,
                       std::shared_ptr<World> world) {
  locomotion_ = std::move(locomotion);
  const bool own_locomotion = !locomotion_ && scenario_.robot;
  // (on a world built already, the legs move a copy of the model its bodies were built from)
  if (own_locomotion)
    locomotion_ = world ? MakeLocomotion(*scenario_.robot, scenario_.rate_hz, *world->robot_model())
                        : MakeLocomotion(*scenario_.robot, scenario_.rate_hz);
  external_ = dynamic_cast<ExternalDrive*>(locomotion_.get());
  const RobotModel* model = locomotion_ ? &locomotion_->model() : nullptr;
  world_ = world ? std::move(world) : std::make_shared<World>(scenario_, model, threads);
  world_->Claim(this);
  // (a simulation that fails to build hands a shared world back)
  struct ReleaseUnlessBuilt {
    World& world;
    const void* user;
    bool built = false;
    ~ReleaseUnlessBuilt() {
      if (!built) world.Release(user);
    }
  } claim{*world_, this};
  world_->ResetEpisode();
  rig_ = std::make_unique<SensorRig>(scenario_, model);
  // (after the robot and the world, whose problems come first) a run without
  // sensors would write an empty report and claim success; a walking robot
  // without sensors is the blind baseline of an outcome study (its outcome
  // is the measurement)
  if (scenario_.sensors.empty() && !scenario_.robot) {
    throw InputError(scenario_.source + ": sensors: no sensors: nothing to measure (add at least one under 'sensors:', "
                     "or a robot whose walk without sensors is the measurement)");
  }
  reader_ = std::make_unique<SensorReader>(scenario_, *world_, *rig_);
  delivery_ = std::make_unique<DeliveryQueue>(scenario_.sensors, scenario_.rate_hz);
  event_log_ = std::make_unique<Events>(*this);
  for (const SensorConfig& sensor : scenario_.sensors) {
    sensor_info_.push_back({.name = sensor.name,
                            .type = sensor.spec.type,
                            .min_range_m = sensor.spec.min_range_m,
                            .max_range_m = sensor.spec.max_range_m,
                            .link = sensor.link,
                            .max_incidence_deg = sensor.spec.max_incidence_deg,
                            .aperture_deg = sensor.spec.beam && sensor.spec.beam->rays > 1 ? sensor.spec.beam->aperture_deg : 0.0});
  }
  if (locomotion_) {
    if (scenario_.map.enabled) terrain_map_ = MakeTerrainMap();
    if (terrain_map_ && scenario_.map.truth_within_m > 0)
      truth_feed_ = std::make_unique<TruthMapFeed>(scenario_.map.truth_within_m, scenario_.map.resolution_m);
    // the gait plans its footsteps on the scene's true surface, or on the
    // robot's own map (gait.footholds: map), the true surface then deciding each landing
    if (terrain_map_ && scenario_.robot && scenario_.robot->footholds == Footholds::kMap)
      map_footholds_ = std::make_unique<MapTerrain>(*terrain_map_);
    locomotion_->SetTerrain(&world_->terrain(), map_footholds_.get());
    // the scenario's own robot must start clear of the scene's objects, on its
    // ground (an injected motion is the caller's, and a co-simulated robot has
    // no state before its first sample: neither is stepped here)
    if (own_locomotion && !external_) {
      const std::vector<std::string> problems = StartProblems(scenario_, *world_, *locomotion_);
      if (!problems.empty()) throw InputError(problems);
    }
    commands_ = std::make_unique<Commands>(*this);
    strategy_ = std::move(strategy);
    feet_ = locomotion_->Feet();
    half_width_m_ = ReferenceHalfWidth_m(*world_->robot());
    contacts_ = std::make_unique<ContactFinder>(*world_->robot(), world_->ground_caster(), world_->ground_ids(), feet_);
    contacts_->SetMoving(world_->moving_caster());
  }
  // the goal: within half the stride walked (the legs may set it rather than the scenario)
  double goal_tolerance_m = 0;
  if (locomotion_ && scenario_.robot) {
    const auto cycle = locomotion_->gait_cycle();
    goal_tolerance_m = 0.5 * (cycle ? cycle->stride_m : scenario_.robot->gait.stride_m);
  }
  referee_ = std::make_unique<Referee>(scenario_, goal_tolerance_m, *event_log_);
  frame_.sensors.resize(scenario_.sensors.size());
  delivered_.sensors.resize(scenario_.sensors.size());
  outputs_.resize(scenario_.sensors.size());
  if (strategy_) strategy_->Reset(MakeSetup());
  claim.built = true;
}

std::unique_ptr<TerrainMap> Simulation::MakeTerrainMap() const {
  // the sensors listed, or every one whose type's distance is a point on a surface (sensors/sensor_types.cc)
  const TerrainMapConfig& config = scenario_.map;
  std::vector<SensorSpec> specs;
  std::vector<bool> feeds_map;
  for (const SensorConfig& sensor : scenario_.sensors) {
    specs.push_back(sensor.spec);
    feeds_map.push_back(config.sensors_given
                            ? std::find(config.sensors.begin(), config.sensors.end(), sensor.name) != config.sensors.end()
                            : TraitsOf(sensor.spec.type).feeds_map_by_default);
  }
  return std::make_unique<TerrainMap>(config, std::move(specs), std::move(feeds_map));
}

StrategySetup Simulation::MakeSetup() const {
  StrategySetup setup;
  setup.sensors = sensor_info_;
  if (scenario_.robot) setup.path_m = scenario_.robot->waypoints_m;
  setup.rate_hz = scenario_.rate_hz;
  if (const auto cycle = locomotion_ ? locomotion_->gait_cycle() : std::nullopt) {
    setup.max_step_m = cycle->max_step_m;
    setup.stride_m = cycle->stride_m;
  }
  return setup;
}

void Simulation::Reset(std::uint64_t seed) {
  scenario_.seed = seed;
  next_sample_ = 0;
  frame_.sample = 0;
  frame_.t_s = 0;
  frame_.robot = RobotSample{};
  reader_->Reset();
  delivery_->Clear();
  referee_->Reset();
  contacts_now_.clear();
  events_.clear();
  state_ = RobotState{};
  // (the map first: a gait planning on it plans its first step as it starts afresh)
  if (terrain_map_) terrain_map_->Reset();
  if (truth_feed_) truth_feed_->Reset();
  world_->ResetEpisode();
  if (locomotion_) locomotion_->Reset();
  if (strategy_) strategy_->Reset(MakeSetup());
}

const SampleFrame& Simulation::Step() {
  if (done()) throw std::logic_error("Simulation::Step: every sample of the episode has been taken");
  if (external_) {
    throw std::logic_error("Simulation::Step: robot.locomotion is external: every sample needs the robot's state "
                           "(Step(state))");
  }
  return TakeSample();
}

const SampleFrame& Simulation::Step(const ExternalState& state) {
  if (done()) throw std::logic_error("Simulation::Step: every sample of the episode has been taken");
  if (!external_) {
    throw std::logic_error("Simulation::Step(state): the robot is not driven from outside (set robot.locomotion: external)");
  }
  external_->Set(state, static_cast<double>(next_sample_) / scenario_.rate_hz);
  return TakeSample();
}

const SampleFrame& Simulation::TakeSample() {
  frame_.sample = next_sample_++;
  frame_.t_s = static_cast<double>(frame_.sample) / scenario_.rate_hz;
  RobotInScene* robot = world_->robot();
  // the scene's moving objects where they are at this sample's time
  if (world_->has_moving_objects()) {
    // people yield to a robot on the move (walking, or its last step under
    // way after a stop) and pass a robot standing still without walking into
    // it, as pedestrians do (state_: the last sample's)
    if (locomotion_ && frame_.sample > 0)
      world_->HoldPeopleNear(state_.X_WP.translation().head<2>(), kPedestrianKeep_m,
                             state_.stopped ? kPedestrianPassStanding_m : std::numeric_limits<double>::infinity(),
                             frame_.t_s, 1.0 / scenario_.rate_hz);
    const double moved_m = world_->MoveObjects(frame_.t_s);
    // the clearance's remembered bounds against them shrink by as much as they moved
    if (robot) robot->LowerClearanceBounds(world_->moving_caster(), moved_m);
    if (!locomotion_) world_->caster().Commit();
  }
  if (locomotion_) {
    // every link at its pose of this very sample time
    state_ = locomotion_->Advance(frame_.t_s);
    // (the ground known at the last sample: where a fall with no place of its own lands)
    referee_->LegEvents(locomotion_->TakeEvents(), frame_.t_s, state_, knowledge_.ground_z_m);
    robot->Place(state_);
    world_->caster().Commit();
    frame_.robot = {.present = true,
                    .gait_phase = state_.gait_phase,
                    .support = state_.support,
                    .stopped = state_.stopped,
                    .distance_walked_m = state_.distance_walked_m};
  }
  // the robot's clearance truth depends on its pose only, not on the
  // readings: it is measured while the sensors are read
  double clearance_m = std::numeric_limits<double>::infinity();
  runner_.Invoke([this] { reader_->Read(frame_, runner_); },
                 [&] {
                   if (!locomotion_) return;
                   // the still scene (remembered bounds), then the moving objects (measured
                   // afresh); each exact below the cap: the running minimum, or the reach of a
                   // contact once the minimum is below it (a touch does not make every later
                   // sample search for contacts)
                   const double cap_m = std::max(referee_->robot().min_clearance_m, kContactTolerance_m);
                   const double still_m = robot->ClearanceTo(world_->ground_ids(), cap_m);
                   clearance_m = still_m;
                   if (const RayCaster* moving = world_->moving_caster())
                     clearance_m = std::min(clearance_m, robot->ClearanceTo({}, cap_m, nullptr, moving));
                   contacts_now_ = contacts_->Find(still_m);
                 });
  if (delivery_->active()) delivery_->Deliver(frame_, delivered_);
  if (locomotion_) KnowRobot(state_, *robot, feet_, half_width_m_, knowledge_);
  FillObservation();
  // the map learns from what was delivered, before the strategy reads it
  // (with perfect perception, the oracle's, the scene's true heights beside them)
  if (terrain_map_) {
    std::span<const RayEvidence> columns;
    if (truth_feed_ && observation_.robot != nullptr) {
      const RobotKnowledge& self = *observation_.robot;
      columns = truth_feed_->Columns(*world_, self.X_WP.translation().head<2>(), self.heading_W.head<2>().normalized(),
                                     self.ground_z_m + scenario_.map.max_height_m, observation_.t_s);
    }
    terrain_map_->Update(observation_, columns);
  }
  if (locomotion_) {
    // the strategy sees what the robot knows and nothing else; the referee judges the sample after it
    if (strategy_) strategy_->Decide(observation_, *commands_, *event_log_);
    referee_->Judge(frame_.t_s, state_, clearance_m);
    referee_->Contacts(frame_.t_s, NamedContacts());
  }
  return frame_;
}

void Simulation::FillObservation() {
  const SampleFrame& delivered = this->delivered();
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    const SensorSample& sample = delivered.sensors[i];
    SensorOutput& out = outputs_[i];
    out.fresh = sample.reading.status != ReadingStatus::kNotSampled;
    out.detected = sample.reading.detected();
    if (out.fresh) {
      out.d_m = sample.reading.d_m;
      out.signal = sample.reading.signal;
      out.output = sample.reading.output;
      out.t_reported_s = sample.t_reported_s;
      out.p_WS = sample.p_WS;
      out.dir_W = sample.dir_W;
      out.cos_to_axis = sample.cos_to_axis;
      out.measurements = sample.measurements;
    } else {
      // no news: the device shows its maximum range, at the pose the kinematics give now
      out.d_m = scenario_.sensors[i].spec.max_range_m;
      out.signal = out.output = out.t_reported_s = std::numeric_limits<double>::quiet_NaN();
      out.p_WS = frame_.sensors[i].p_WS;
      out.dir_W = frame_.sensors[i].dir_W;
      out.cos_to_axis = 1.0;
    }
  }
  observation_ = Observation{.t_s = frame_.t_s,
                             .sample = frame_.sample,
                             .sensors = outputs_,
                             .robot = locomotion_ ? &knowledge_ : nullptr,
                             .map = terrain_map_.get()};
}

std::vector<BodyContact> Simulation::NamedContacts() const {
  const RobotModel& model = world_->robot()->model();
  std::vector<BodyContact> named;
  named.reserve(contacts_now_.size());
  for (const Contact& contact : contacts_now_) {
    const bool self = contact.object_id < 0;
    named.push_back({.link = model.link_name(contact.link),
                     .object = self ? model.link_name(contact.other_link) : world_->object_name(contact.object_id),
                     .self = self,
                     .depth_m = contact.depth_m,
                     .p_W = contact.p_W});
  }
  return named;
}

Simulation::Outcome Simulation::outcome() const { return referee_->outcome(frame_.t_s); }

const Simulation::RobotOutcome& Simulation::robot_outcome() const { return referee_->robot(); }

}  // namespace proxsim
