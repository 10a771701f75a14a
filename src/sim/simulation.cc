#include "sim/simulation.h"

#include <string>

#include "core/input_error.h"
#include "sensors/noise.h"

namespace proxsim {

Simulation::Simulation(const Scenario& scenario, int threads)
    : scenario_(scenario), sample_count_(scenario.SampleCount()) {
  // the static world: one body, one shape per scene object, ids = scene order
  std::vector<BodyShape> world_shapes;
  world_shapes.reserve(scenario.scene.objects.size());
  for (const SceneObject& object : scenario.scene.objects) {
    world_shapes.push_back({object.shape, object.X_WO, static_cast<std::int32_t>(object_names_.size())});
    object_names_.push_back(object.name);
  }
  caster_.AddBody(std::move(world_shapes), BodyKind::kWorld);
  first_robot_object_id_ = static_cast<std::int32_t>(object_names_.size());
  for (std::size_t id = 0; id < object_names_.size(); ++id) {
    if (object_names_[id].starts_with("floor")) ground_ids_.push_back(static_cast<std::int32_t>(id));
  }

  // the robot: its links are bodies too, with object ids after the scene's
  if (scenario.robot) {
    robot_ = std::make_unique<RobotInScene>(*scenario.robot, caster_, static_cast<std::int32_t>(object_names_.size()));
    for (int link = 0; link < robot_->model().link_count(); ++link) object_names_.push_back(robot_->model().link_name(link));
    if (scenario.robot->stop_distance_m) stop_rule_ = StopRule{.stop_distance_m = *scenario.robot->stop_distance_m};
  }

  // every sensor's link must exist
  std::vector<std::string> problems;
  for (const SensorConfig& sensor : scenario.sensors) {
    int link = -1;
    if (sensor.link != "world") {
      link = robot_ ? robot_->model().LinkIndex(sensor.link) : -1;
      if (link < 0) {
        std::string known;
        for (int i = 0; robot_ && i < robot_->model().link_count(); ++i) known += (i ? ", " : "") + robot_->model().link_name(i);
        problems.push_back(scenario.source + ": sensors." + sensor.name + ".link: unknown link '" + sensor.link +
                           "' (expected world" + (known.empty() ? "" : " or one of " + known) + ")");
      }
    }
    sensor_link_.push_back(link);
  }
  if (!problems.empty()) throw InputError(problems);

  caster_.set_threads(threads);
  caster_.Commit();

  // buffers sized once; every step overwrites them in place
  const std::size_t sensor_count = scenario.sensors.size();
  rays_.resize(sensor_count);
  hits_.resize(sensor_count);
  frame_.sensors.resize(sensor_count);
  for (std::size_t i = 0; i < sensor_count; ++i) {
    rays_[i].max_range_m = static_cast<float>(scenario.sensors[i].spec.max_range_m);
    rays_[i].see_robot = scenario.sensors[i].see_robot;
  }
}

Simulation::~Simulation() = default;

const SampleFrame& Simulation::Step() {
  frame_.sample = next_sample_++;
  frame_.t_s = static_cast<double>(frame_.sample) / scenario_.rate_hz;
  if (robot_) {
    // every link at its pose of this very sample time
    robot_->MoveTo(frame_.t_s);
    caster_.Commit();
  }
  PlaceSensors();
  caster_.Cast(rays_, hits_);
  MeasureAll();
  if (robot_) UpdateRobot();
  return frame_;
}

void Simulation::PlaceSensors() {
  for (std::size_t i = 0; i < scenario_.sensors.size(); ++i) {
    const Pose& X_LS = scenario_.sensors[i].X_LS;
    const Pose X_WS = sensor_link_[i] < 0 ? X_LS : robot_->X_WL(sensor_link_[i]) * X_LS;
    SensorSample& out = frame_.sensors[i];
    out.p_WS = X_WS.translation();
    out.dir_W = X_WS.linear().col(0);  // the beam is the sensor's +x
    rays_[i].origin_W = out.p_WS.cast<float>();
    rays_[i].direction_W = out.dir_W.cast<float>();
  }
}

void Simulation::MeasureAll() {
  for (std::size_t i = 0; i < scenario_.sensors.size(); ++i) {
    const Hit& hit = hits_[i];
    SensorSample& out = frame_.sensors[i];
    out.object_id = hit.object_id;
    out.echo = Echo{};
    if (hit.is_hit()) {
      out.echo.distance_m = hit.distance_m;
      // the robot's links come after the scene's objects
      out.echo.from_robot = hit.object_id >= first_robot_object_id_;
      const Vec3 normal_W = hit.normal_W.cast<double>();
      out.echo.incidence_deg = IncidenceDeg(out.dir_W.x(), out.dir_W.y(), out.dir_W.z(), normal_W.x(),
                                            normal_W.y(), normal_W.z());
      out.p_WH = out.p_WS + out.echo.distance_m * out.dir_W;
    } else {
      out.p_WH.setConstant(std::numeric_limits<double>::quiet_NaN());
    }
    // one keyed draw per (seed, sensor, sample, ray): thread- and order-independent
    const double g = KeyedGaussian({scenario_.seed, static_cast<std::uint32_t>(i),
                                    static_cast<std::uint64_t>(frame_.sample), 0});
    out.reading = Measure(scenario_.sensors[i].spec, out.echo, g);
  }
}

void Simulation::UpdateRobot() {
  const RobotState& state = robot_->state();
  frame_.robot = {.present = true,
                  .gait_phase = state.gait_phase,
                  .support = state.support,
                  .stopped = state.stopped,
                  .distance_walked_m = state.distance_walked_m};

  // the built-in strategy sees readings and the robot's own kinematics only
  if (stop_rule_ && !outcome_.stop_requested) {
    const int trigger = FindStopTrigger(frame_, robot_->SelfKnowledge(), *stop_rule_);
    if (trigger >= 0) {
      robot_->locomotion().RequestStop();
      outcome_.stop_requested = true;
      outcome_.stop_request_t_s = frame_.t_s;
      outcome_.stop_trigger_sensor = trigger;
    }
  }
  if (outcome_.stop_requested && state.stopped && !outcome_.stopped) {
    outcome_.stopped = true;
    outcome_.stop_t_s = frame_.t_s;
  }

  // the truth, for the summary only
  const double clearance_m = robot_->ClearanceTo(caster_, ground_ids_, outcome_.min_clearance_m);
  if (clearance_m < outcome_.min_clearance_m) {
    outcome_.min_clearance_m = clearance_m;
    outcome_.min_clearance_t_s = frame_.t_s;
  }
}

}  // namespace proxsim
