#include "sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/input_error.h"
#include "io/nearest_key.h"
#include "sensors/noise.h"

namespace proxsim {

Simulation::Simulation(const Scenario& scenario, int threads)
    : scenario_(scenario), sample_count_(scenario.SampleCount()), runner_(threads) {
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
        std::vector<std::string> names;
        for (int i = 0; robot_ && i < robot_->model().link_count(); ++i) {
          names.push_back(robot_->model().link_name(i));
          known += (i ? ", " : "") + names.back();
        }
        const auto nearest = NearestKey(sensor.link, names);
        const std::string where =
            scenario.source + (sensor.link_line > 0 ? ":" + std::to_string(sensor.link_line) : std::string());
        problems.push_back(where + ": sensors." + sensor.name + ".link: unknown link '" + sensor.link + "'" +
                           (nearest ? " (did you mean '" + *nearest + "'?)" : "") + "; expected world" +
                           (known.empty() ? "" : " or one of " + known));
      }
    }
    sensor_link_.push_back(link);
  }
  if (!problems.empty()) throw InputError(problems);

  caster_.set_threads(threads);
  caster_.Commit();
  // the clearance truth's point-query structure over the scene without the
  // ground is built here with the other structures, not at the first sample
  if (robot_) caster_.DistanceToWorld(Vec3::Zero(), ground_ids_);

  // buffers sized once; every step overwrites them in place. Sensor i owns the
  // rays [ray_begin_[i], ray_begin_[i + 1]): one for the paper's sensors, a beam's otherwise.
  const std::size_t sensor_count = scenario.sensors.size();
  ray_begin_.push_back(0);
  for (const SensorConfig& sensor : scenario.sensors) {
    const std::vector<BeamRay> beam = MakeBeamRays(sensor.spec.beam);
    beam_rays_.insert(beam_rays_.end(), beam.begin(), beam.end());
    ray_begin_.push_back(beam_rays_.size());
  }
  rays_.resize(beam_rays_.size());
  ray_dir_W_.resize(beam_rays_.size());
  hits_.resize(beam_rays_.size());
  echoes_.resize(beam_rays_.size());
  frame_.sensors.resize(sensor_count);
  p_WS_previous_.assign(sensor_count, Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  for (std::size_t i = 0; i < sensor_count; ++i) {
    for (std::size_t r = ray_begin_[i]; r < ray_begin_[i + 1]; ++r) {
      rays_[r].max_range_m = static_cast<float>(scenario.sensors[i].spec.max_range_m);
      rays_[r].see_robot = scenario.sensors[i].see_robot;
    }
  }

  // latency: a ring per sensor long enough for every reading still in flight
  pending_.resize(sensor_count);
  for (std::size_t i = 0; i < sensor_count; ++i) {
    const double latency_s = scenario.sensors[i].latency_s;
    if (latency_s > 0) latency_ = true;
    pending_[i].ring.resize(static_cast<std::size_t>(std::ceil(latency_s * scenario.rate_hz)) + 2);
  }
  delivered_.sensors.resize(sensor_count);
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
  // the robot's clearance truth depends on its pose only, not on the
  // readings: it is measured while the sensors are read
  double clearance_m = std::numeric_limits<double>::infinity();
  runner_.Invoke([this] { ReadSensors(); },
                 [&] {
                   if (robot_) clearance_m = robot_->ClearanceTo(ground_ids_, outcome_.min_clearance_m);
                 });
  if (latency_) Deliver();
  if (robot_) UpdateRobot(clearance_m);
  return frame_;
}

bool Simulation::IsSensorSample(std::size_t sensor, std::int64_t sample) const {
  const double rate_hz = scenario_.sensors[sensor].rate_hz;
  if (!(rate_hz > 0) || sample == 0) return true;
  // the first run sample in each of the sensor's periods (1e-9: t_k·rate on an exact multiple)
  const auto period = [&](std::int64_t k) {
    return std::floor(static_cast<double>(k) * rate_hz / scenario_.rate_hz + 1e-9);
  };
  return period(sample) > period(sample - 1);
}

void Simulation::Deliver() {
  delivered_.sample = frame_.sample;
  delivered_.t_s = frame_.t_s;
  delivered_.robot = frame_.robot;
  for (std::size_t i = 0; i < frame_.sensors.size(); ++i) {
    Pending& pending = pending_[i];
    const SensorSample& taken = frame_.sensors[i];
    if (taken.reading.status != ReadingStatus::kNotSampled) {
      // the ring holds every reading still in flight (sized for the latency)
      pending.ring[(pending.head + pending.count) % pending.ring.size()] = taken;
      ++pending.count;
    }
    SensorSample& out = delivered_.sensors[i];
    const SensorSample& oldest = pending.ring[pending.head];
    if (pending.count > 0 && oldest.t_reported_s <= frame_.t_s + 1e-9) {
      out = oldest;
      pending.head = (pending.head + 1) % pending.ring.size();
      --pending.count;
    } else {
      out = SensorSample{};
      out.reading.status = ReadingStatus::kNotSampled;
      out.ray = -1;
    }
  }
}

void Simulation::PlaceSensor(std::size_t i) {
  const Pose& X_LS = scenario_.sensors[i].X_LS;
  const Pose X_WS = sensor_link_[i] < 0 ? X_LS : robot_->X_WL(sensor_link_[i]) * X_LS;
  SensorSample& out = frame_.sensors[i];
  out.p_WS = X_WS.translation();
  out.dir_W = X_WS.linear().col(0);  // the beam's axis is the sensor's +x
  for (std::size_t r = ray_begin_[i]; r < ray_begin_[i + 1]; ++r) {
    rays_[r].origin_W = out.p_WS.cast<float>();
    // the axis ray is exactly the sensor's +x, as in the paper's single-ray model
    const BeamRay& beam_ray = beam_rays_[r];
    ray_dir_W_[r] = beam_ray.off_axis_deg == 0.0 ? out.dir_W : Vec3(X_WS.linear() * beam_ray.dir_S);
    rays_[r].direction_W = ray_dir_W_[r].cast<float>();
  }
}

void Simulation::ReadSensors() {
  // sensors are independent (each owns its rays, hits, echoes and output
  // slot), so a sample with many rays is shared out by sensor, in one fork:
  // each thread places a sensor's rays, casts them and reads them while they
  // are in its cache. A sensor's rays are always cast on their own, in the same packets,
  // and the noise is keyed, so the readings are the same whatever the thread count.
  const std::size_t sensor_count = scenario_.sensors.size();
  const auto read = [this](std::size_t begin_sensor, std::size_t end_sensor) {
    for (std::size_t sensor = begin_sensor; sensor < end_sensor; ++sensor) {
      const std::size_t begin = ray_begin_[sensor], count = ray_begin_[sensor + 1] - begin;
      PlaceSensor(sensor);
      caster_.Cast(std::span(rays_).subspan(begin, count), std::span(hits_).subspan(begin, count));
      MeasureSensor(sensor);
    }
  };
  if (rays_.size() >= kParallelReadRays) {
    runner_.For(sensor_count, kSensorsPerTask, read);
  } else {
    read(0, sensor_count);
  }
}

void Simulation::MeasureSensor(std::size_t i) {
  const SensorConfig& sensor = scenario_.sensors[i];
  const SensorSpec& spec = sensor.spec;
  SensorSample& out = frame_.sensors[i];
  out.t_reported_s = frame_.t_s + sensor.latency_s;
  const Vec3 p_WS_previous = p_WS_previous_[i];
  p_WS_previous_[i] = out.p_WS;

  // between the sensor's own samples: no reading
  if (!IsSensorSample(i, frame_.sample)) {
    out.reading = Reading{};
    out.reading.status = ReadingStatus::kNotSampled;
    out.reading.d_m = spec.max_range_m;
    out.echo = Echo{};
    out.object_id = -1;
    out.ray = -1;
    out.truth_ray = 0;
    out.p_WH.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }

  // the sensor's velocity over the last sample, for the echo's flight
  Vec3 v_W = Vec3::Zero();
  if (sensor.flight_time && frame_.sample > 0 && p_WS_previous.allFinite()) {
    v_W = (out.p_WS - p_WS_previous) * scenario_.rate_hz;
  }
  const double c_m_s = sensor.wave_speed_m_s > 0 ? sensor.wave_speed_m_s
                       : spec.type == SensorType::kUltrasonic ? 343.0
                                                               : 299792458.0;

  // every ray's echo, with its material
  const std::size_t begin = ray_begin_[i];
  const std::size_t end = ray_begin_[i + 1];
  for (std::size_t r = begin; r < end; ++r) {
    const Hit& hit = hits_[r];
    Echo& echo = echoes_[r];
    echo = Echo{};
    if (hit.is_hit()) {
      echo.distance_m = hit.distance_m;
      // the robot's links come after the scene's objects (and have the default material)
      echo.from_robot = hit.object_id >= first_robot_object_id_;
      if (!echo.from_robot) {
        const Material& material = scenario_.scene.objects[hit.object_id].material;
        echo.ir_albedo = material.ir_albedo.value_or(material.albedo);
        echo.acoustic_reflectivity = material.acoustic_reflectivity.value_or(1.0);
        echo.specular = material.specular;
      }
      const Vec3& dir_W = ray_dir_W_[r];
      const Vec3 normal_W = hit.normal_W.cast<double>();
      echo.incidence_deg = IncidenceDeg(dir_W.x(), dir_W.y(), dir_W.z(), normal_W.x(), normal_W.y(), normal_W.z());
      if (sensor.flight_time) {
        echo.flight_shift_m = FlightTimeShift(out.p_WS, v_W, out.p_WS + echo.distance_m * dir_W, echo.distance_m, c_m_s);
      }
    }
  }

  // keyed draws per (seed, sensor, sample, ray): thread- and order-independent,
  // made only for the ray the reading needs; the dropout's uniform has its
  // own key (the ray's top bit set)
  const DrawOfRay draw = [&](int ray) {
    const NoiseKey key{scenario_.seed, static_cast<std::uint32_t>(i), static_cast<std::uint64_t>(frame_.sample),
                       static_cast<std::uint32_t>(ray)};
    NoiseDraw d;
    d.gaussian_g = KeyedGaussian(key);
    if (spec.noise.dropout > 0) {
      NoiseKey dropout_key = key;
      dropout_key.ray |= 0x80000000u;
      d.uniform = KeyedUniforms(dropout_key).u1;
    }
    return d;
  };

  // the reading: the paper's single ray, or the beam's combination
  if (end - begin == 1) {
    out.reading = Measure(spec, echoes_[begin], draw);
    out.truth_ray = 0;
    out.ray = (out.reading.status == ReadingStatus::kOk || out.reading.status == ReadingStatus::kSelf) ? 0 : -1;
  } else {
    const BeamReading beam = MeasureBeam(spec, std::span(echoes_).subspan(begin, end - begin),
                                         std::span(beam_rays_).subspan(begin, end - begin),
                                         draw);
    out.reading = beam.reading;
    out.truth_ray = beam.truth_ray;
    out.ray = beam.ray;
  }

  // the truth beside it: the echo, object and hit point of the ray it came from
  const std::size_t truth = begin + static_cast<std::size_t>(out.truth_ray);
  out.echo = echoes_[truth];
  out.object_id = hits_[truth].object_id;
  if (hits_[truth].is_hit()) {
    out.p_WH = out.p_WS + out.echo.distance_m * ray_dir_W_[truth];
  } else {
    out.p_WH.setConstant(std::numeric_limits<double>::quiet_NaN());
  }
}

void Simulation::UpdateRobot(double clearance_m) {
  const RobotState& state = robot_->state();
  frame_.robot = {.present = true,
                  .gait_phase = state.gait_phase,
                  .support = state.support,
                  .stopped = state.stopped,
                  .distance_walked_m = state.distance_walked_m};

  // the built-in strategy sees readings and the robot's own kinematics only
  if (stop_rule_ && !outcome_.stop_requested) {
    const int trigger = FindStopTrigger(delivered(), robot_->SelfKnowledge(), *stop_rule_);
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
  if (clearance_m < outcome_.min_clearance_m) {
    outcome_.min_clearance_m = clearance_m;
    outcome_.min_clearance_t_s = frame_.t_s;
  }
}

}  // namespace proxsim
