#include "sim/sensor_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sensors/echo.h"
#include "sensors/crosstalk.h"
#include "sensors/measured_point.h"
#include "sensors/multizone.h"
#include "sensors/noise.h"
#include "sensors/wave_speed.h"

namespace proxsim {

SensorReader::SensorReader(const Scenario& scenario, World& world, const SensorRig& rig)
    : scenario_(scenario), world_(world), rig_(rig) {
  const std::size_t ray_count = rig.ray_count();
  rays_.resize(ray_count);
  ray_dir_W_.resize(ray_count);
  hits_.resize(ray_count);
  echoes_.resize(ray_count);
  for (std::size_t i = 0; i < scenario.sensors.size(); ++i) {
    for (std::size_t r = rig.ray_begin(i); r < rig.ray_begin(i + 1); ++r) {
      rays_[r].max_range_m = static_cast<float>(scenario.sensors[i].spec.max_range_m);
      rays_[r].see_robot = scenario.sensors[i].see_robot;
    }
    if (scenario.sensors[i].spec.type == SensorType::kUltrasonic && scenario.sensors[i].spec.beam) sonars_.push_back(i);
  }
  // crosstalk: the longest listening window, and the sonars others may hear (cast at every sample)
  heard_by_others_.assign(scenario.sensors.size(), false);
  for (const std::size_t sonar : sonars_) {
    longest_window_s_ = std::max(longest_window_s_, ListeningWindow_s(sonar));
    heard_by_others_[sonar] = sonars_.size() > 1;
  }
  zone_axes_S_.resize(scenario.sensors.size());
  zone_axes_W_.resize(scenario.sensors.size());
  measured_.resize(scenario.sensors.size());
  mount_X_WM_.resize(scenario.sensors.size());
  for (std::size_t i = 0; i < scenario.sensors.size(); ++i) {
    if (const auto& zones = scenario.sensors[i].spec.zones) {
      for (int zone = 0; zone < ZoneCount(*zones); ++zone) zone_axes_S_[i].push_back(ZoneAxis_S(*zones, zone));
    }
  }
  Reset();
}

void SensorReader::Reset() {
  p_WS_previous_.assign(scenario_.sensors.size(), Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  last_ping_t_s_.assign(scenario_.sensors.size(), std::numeric_limits<double>::quiet_NaN());
}

void SensorReader::Read(SampleFrame& frame, ParallelRunner& runner) {
  // sensors are independent (each owns its rays, hits, echoes and output
  // slot), so a sample with many rays is shared out by sensor, in one fork:
  // each thread places a sensor's rays, casts them and reads them while they
  // are in its cache. A sensor's rays are always cast on their own, in the same packets,
  // and the noise is keyed, so the readings are the same whatever the thread count.
  const std::size_t sensor_count = scenario_.sensors.size();
  frame.sensors.resize(sensor_count);
  const bool crosstalk = sonars_.size() > 1;
  if (crosstalk) PrepareCrosstalk(frame.sample);
  const auto read = [this, &frame, crosstalk](std::size_t begin_sensor, std::size_t end_sensor) {
    for (std::size_t sensor = begin_sensor; sensor < end_sensor; ++sensor) {
      const std::size_t begin = rig_.ray_begin(sensor), count = rig_.ray_begin(sensor + 1) - begin;
      // between its own samples a sensor reads nothing: its rays are not cast
      const bool cast = CastsAt(sensor, frame.sample);
      PlaceSensor(sensor, frame, cast);
      if (cast) world_.caster().Cast(std::span(rays_).subspan(begin, count), std::span(hits_).subspan(begin, count));
      MeasureSensor(sensor, frame);
      if (crosstalk) FindEchoSources(sensor, frame);
    }
  };
  if (rays_.size() >= kParallelReadRays) {
    runner.For(sensor_count, kSensorsPerTask, read);
  } else {
    read(0, sensor_count);
  }
  // after every sensor is read: a listener needs the others' pings
  if (crosstalk) ApplyCrosstalk(frame, runner);
}

double SensorReader::ListeningWindow_s(std::size_t sensor) const {
  const SensorConfig& config = scenario_.sensors[sensor];
  if (config.spec.echo_timeout_s > 0) return config.spec.echo_timeout_s;
  return config.rate_hz > 0 ? 1.0 / config.rate_hz : 1.0 / scenario_.rate_hz;  // until its next ping
}

void SensorReader::FindNextPings(std::int64_t sample) {
  next_ping_offset_s_.assign(scenario_.sensors.size(), std::numeric_limits<double>::infinity());
  for (const std::size_t emitter : sonars_) {
    for (std::int64_t k = sample + 1; static_cast<double>(k - sample) / scenario_.rate_hz <= longest_window_s_; ++k) {
      if (IsSensorSample(emitter, k)) {
        next_ping_offset_s_[emitter] = static_cast<double>(k - sample) / scenario_.rate_hz;
        break;
      }
    }
  }
}

void SensorReader::PrepareCrosstalk(std::int64_t sample) {
  FindNextPings(sample);
  echo_sources_.resize(scenario_.sensors.size());
  nearest_source_m_.resize(scenario_.sensors.size());
  cross_paths_.resize(scenario_.sensors.size());
  sonar_listens_now_ = std::any_of(sonars_.begin(), sonars_.end(), [&](std::size_t sonar) {
    return scenario_.sensors[sonar].crosstalk && IsSensorSample(sonar, sample);
  });
}

void SensorReader::FindEchoSources(std::size_t sensor, const SampleFrame& frame) {
  // a listener asks for an emitter's sources when a ping of it lies within
  // its window (PingOffsets_s): the last one (this sample's included: set by
  // MeasureSensor) or the next one, within the longest window of any
  if (!sonar_listens_now_ || !heard_by_others_[sensor]) return;
  const double t_s = static_cast<double>(frame.sample) / scenario_.rate_hz;
  const double last_s = last_ping_t_s_[sensor];
  const bool may_be_heard = (std::isfinite(last_s) && t_s - last_s < longest_window_s_) ||
                            next_ping_offset_s_[sensor] <= longest_window_s_;
  if (!may_be_heard) return;
  const std::size_t begin = rig_.ray_begin(sensor), count = rig_.ray_begin(sensor + 1) - begin;
  const PingRays ping{frame.sensors[sensor].p_WS, std::span(ray_dir_W_).subspan(begin, count),
                      std::span(hits_).subspan(begin, count), std::span(rig_.beam_rays()).subspan(begin, count)};
  EchoSourcesInto(scenario_.sensors[sensor].spec, ping, echo_sources_[sensor]);
  nearest_source_m_[sensor] = NearestEchoSource_m(echo_sources_[sensor]);
}

void SensorReader::ApplyCrosstalk(SampleFrame& frame, ParallelRunner& runner) {
  const double t_s = static_cast<double>(frame.sample) / scenario_.rate_hz;
  // each emitter's last ping, s from this sample (−inf before its first), for PingOffsets_s
  last_ping_offset_s_.resize(scenario_.sensors.size());
  for (const std::size_t sonar : sonars_) {
    const double last_s = last_ping_t_s_[sonar];
    last_ping_offset_s_[sonar] = std::isfinite(last_s) ? last_s - t_s : -std::numeric_limits<double>::infinity();
  }
  // each listener reads the emitters' sources and writes only its own reading
  runner.For(sonars_.size(), kListenersPerTask, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) ListenForCrosstalk(sonars_[k], frame);
  });
}

void SensorReader::ListenForCrosstalk(std::size_t listener, SampleFrame& frame) {
  const SensorConfig& config = scenario_.sensors[listener];
  SensorSample& out = frame.sensors[listener];
  if (!config.crosstalk || out.reading.status == ReadingStatus::kNotSampled) return;
  const double c_m_s = WaveSpeed_m_s(config.spec.type, config.wave_speed_m_s);
  const double window_s = ListeningWindow_s(listener);
  // its own first echo, when one came back (the dead zone's and its body's too)
  const ReadingStatus own = out.reading.status;
  const bool own_heard = own == ReadingStatus::kOk || own == ReadingStatus::kTooClose || own == ReadingStatus::kSelf;
  double first_s = own_heard ? 2.0 * (out.echo.distance_m + out.echo.flight_shift_m) / c_m_s
                             : std::numeric_limits<double>::infinity();
  bool heard_another = false;
  const ListeningSensor ear{out.p_WS, out.dir_W};
  const MirrorWindow mirror_window(config.spec);
  std::vector<CrossEchoPath>& paths = cross_paths_[listener];
  for (const std::size_t emitter : sonars_) {
    if (emitter == listener) continue;
    const PingOffsets offsets_s = PingOffsets_s(emitter, window_s);
    if (offsets_s.count == 0) continue;
    // (FindEchoSources found this emitter's sources at this sample: this
    // listener listens now, and the ping lies within its window, so within the longest)
    // no path of this ping can arrive in the window before the first echo
    // heard so far: its paths need not be found (an exact cut: each path is
    // at least the shortest bound, and arrives no sooner)
    const double shortest_m = ShortestCrossEchoPath_m(nearest_source_m_[emitter], frame.sensors[emitter].p_WS, out.p_WS);
    const bool too_late = std::all_of(offsets_s.begin(), offsets_s.end(), [&](double offset_s) {
      const double earliest_s = offset_s + shortest_m / c_m_s;
      return earliest_s > window_s || earliest_s >= first_s;
    });
    if (too_late) continue;
    // and no path longer than this could: it would arrive after the window or
    // the first echo for every ping (widened for rounding: the cut must never
    // drop a path the test below would take)
    double longest_m = 0.0;
    for (const double offset_s : offsets_s) longest_m = std::max(longest_m, (std::min(window_s, first_s) - offset_s) * c_m_s);
    CrossEchoPathsInto(echo_sources_[emitter], config.spec, mirror_window, ear, paths, frame.sensors[emitter].p_WS,
                       longest_m * (1 + 1e-9) + 1e-9);
    for (const CrossEchoPath& path : paths) {
      double arrival_s = std::numeric_limits<double>::infinity();
      for (const double offset_s : offsets_s) {
        const double a_s = offset_s + path.path_m / c_m_s;
        if (a_s >= 0.0 && a_s <= window_s) arrival_s = std::min(arrival_s, a_s);
      }
      if (!(arrival_s < first_s)) continue;
      // the listener must see the reflecting point
      const Vec3 to_H = path.p_WH - out.p_WS;
      const double d_m = to_H.norm();
      Ray ray{.origin_W = out.p_WS.cast<float>(), .direction_W = (to_H / d_m).cast<float>(),
              .max_range_m = static_cast<float>(d_m), .see_robot = config.see_robot};
      Hit hit;
      world_.caster().Cast(std::span(&ray, 1), std::span(&hit, 1));
      if (hit.is_hit() && hit.distance_m < d_m - 1e-3) continue;
      first_s = arrival_s;
      heard_another = true;
    }
  }
  if (!heard_another) return;
  // the device reads the other ping's echo as its own: range limits and noise
  // as for any echo, from a draw keyed past its rays (no ray of its own)
  Echo echo;
  echo.distance_m = 0.5 * c_m_s * first_s;
  const NoiseKey key{scenario_.seed, static_cast<std::uint32_t>(listener), static_cast<std::uint64_t>(frame.sample),
                     static_cast<std::uint32_t>(rig_.ray_begin(listener + 1) - rig_.ray_begin(listener))};
  Reading reading = Measure(config.spec, echo, [&](int) { return KeyedNoiseDraw(config.spec.noise, key); });
  if (reading.status != ReadingStatus::kOk) return;
  reading.status = ReadingStatus::kCrosstalk;
  out.reading = reading;
  out.ray = -1;
}

void SensorReader::SetMountPose_W(std::size_t sensor, const Pose& X_WM) { mount_X_WM_.at(sensor) = X_WM; }

bool SensorReader::IsSensorSample(std::size_t sensor, std::int64_t sample) const {
  const double rate_hz = scenario_.sensors[sensor].rate_hz;
  if (!(rate_hz > 0)) return true;
  // the first run sample in each of the sensor's periods, which start at its
  // fire offset (1e-9: t_k·rate on an exact multiple); sample −1 lies before
  // every period, so a sensor without an offset reads at sample 0
  const double offset_s = scenario_.sensors[sensor].fire_offset_s;
  const auto period = [&](std::int64_t k) {
    return std::floor(static_cast<double>(k) * rate_hz / scenario_.rate_hz - offset_s * rate_hz + 1e-9);
  };
  if (offset_s == 0.0 && sample == 0) return true;
  return period(sample) > period(sample - 1);
}

bool SensorReader::CastsAt(std::size_t sensor, std::int64_t sample) const {
  return heard_by_others_[sensor] || IsSensorSample(sensor, sample);
}

void SensorReader::PlaceSensor(std::size_t i, SampleFrame& frame, bool rays) {
  const Pose& X_LS = scenario_.sensors[i].X_LS;
  const int link = rig_.sensor_link(i);
  const Pose X_WS = mount_X_WM_[i] ? *mount_X_WM_[i] * X_LS : link < 0 ? X_LS : world_.robot()->X_WL(link) * X_LS;
  SensorSample& out = frame.sensors[i];
  out.p_WS = X_WS.translation();
  out.dir_W = X_WS.linear().col(0);  // the beam's axis is the sensor's +x
  if (!rays) return;
  const std::vector<Vec3>& zone_axes_S = zone_axes_S_[i];
  zone_axes_W_[i].resize(zone_axes_S.size());
  for (std::size_t zone = 0; zone < zone_axes_S.size(); ++zone) zone_axes_W_[i][zone] = X_WS.linear() * zone_axes_S[zone];
  for (std::size_t r = rig_.ray_begin(i); r < rig_.ray_begin(i + 1); ++r) {
    rays_[r].origin_W = out.p_WS.cast<float>();
    ray_dir_W_[r] = BeamRayDir_W(X_WS, rig_.beam_rays()[r]);
    rays_[r].direction_W = ray_dir_W_[r].cast<float>();
  }
}

void SensorReader::MeasureSensor(std::size_t i, SampleFrame& frame) {
  const SensorConfig& sensor = scenario_.sensors[i];
  const SensorSpec& spec = sensor.spec;
  SensorSample& out = frame.sensors[i];
  out.t_reported_s = frame.t_s + sensor.latency_s;
  const Vec3 p_WS_previous = p_WS_previous_[i];
  p_WS_previous_[i] = out.p_WS;

  // between the sensor's own samples: no reading
  const bool pings = IsSensorSample(i, frame.sample);
  if (pings) last_ping_t_s_[i] = frame.t_s;
  if (!pings) {
    out.reading = Reading{};
    out.reading.status = ReadingStatus::kNotSampled;
    out.reading.d_m = spec.max_range_m;
    out.echo = Echo{};
    out.object_id = -1;
    out.ray = -1;
    out.truth_ray = 0;
    out.p_WH.setConstant(std::numeric_limits<double>::quiet_NaN());
    out.measurements.clear();
    out.measurements_truth.clear();
    return;
  }

  // the sensor's velocity over the last sample, for the echo's flight
  Vec3 v_W = Vec3::Zero();
  if (sensor.flight_time && frame.sample > 0 && p_WS_previous.allFinite()) {
    v_W = (out.p_WS - p_WS_previous) * scenario_.rate_hz;
  }
  const double c_m_s = WaveSpeed_m_s(spec.type, sensor.wave_speed_m_s);

  // every ray's echo, with its material
  const std::size_t begin = rig_.ray_begin(i);
  const std::size_t end = rig_.ray_begin(i + 1);
  for (std::size_t r = begin; r < end; ++r) {
    const Hit& hit = hits_[r];
    Echo& echo = echoes_[r];
    echo = Echo{};
    if (hit.is_hit()) {
      const Vec3& dir_W = ray_dir_W_[r];
      echo = EchoOfHit(hit.distance_m, dir_W, hit.normal_W.cast<double>());
      // the robot's links come after the scene's objects (and have the default material)
      echo.from_robot = hit.object_id >= world_.first_robot_object_id();
      if (!echo.from_robot) {
        const Material& material = scenario_.scene.objects[hit.object_id].material;
        echo.ir_albedo = material.ir_albedo.value_or(material.albedo);
        echo.acoustic_reflectivity = material.acoustic_reflectivity.value_or(1.0);
        echo.specular = material.specular;
      }
      if (sensor.flight_time) {
        // a moving object is met where it is when the wave reaches it
        const Vec3 p_WH = MeasuredPoint_W(out.p_WS, dir_W, echo.distance_m);
        const Motion* motion = echo.from_robot || !scenario_.scene.objects[hit.object_id].motion
                                   ? nullptr
                                   : &*scenario_.scene.objects[hit.object_id].motion;
        const double out_m =
            motion ? MovingSurfaceMeeting_m(echo.distance_m, dir_W, hit.normal_W.cast<double>(),
                                            MotionPointVelocity_W(*motion, frame.t_s, p_WH), c_m_s)
                   : echo.distance_m;
        echo.flight_shift_m = (out_m - echo.distance_m) +
                              FlightTimeShift(out.p_WS, v_W, MeasuredPoint_W(out.p_WS, dir_W, out_m), out_m, c_m_s);
      }
    }
  }

  // keyed draws per (seed, sensor, sample, ray): thread- and order-independent,
  // made only for the ray the reading needs
  const DrawOfRay draw = [&](int ray) {
    return KeyedNoiseDraw(spec.noise, {scenario_.seed, static_cast<std::uint32_t>(i),
                                       static_cast<std::uint64_t>(frame.sample), static_cast<std::uint32_t>(ray)});
  };

  // the reading and what the part reports beside it (sensors/sensor_measure.h)
  SensorMeasurement& measured = measured_[i];
  MeasureSensorSample(spec, SensorPlacement{out.p_WS, out.dir_W, zone_axes_W_[i]},
                      std::span(echoes_).subspan(begin, end - begin),
                      std::span(rig_.beam_rays()).subspan(begin, end - begin), draw, measured);
  out.reading = measured.headline.reading;
  out.ray = measured.headline.ray;
  out.truth_ray = measured.headline.truth_ray;
  out.dir_W = measured.headline_dir_W;
  out.cos_to_axis = measured.headline_cos_to_axis;
  out.measurements.swap(measured.measured);
  out.measurements_truth.swap(measured.truth);

  // the truth beside it: the echo, object and hit point of the ray it came from
  const std::size_t truth = begin + static_cast<std::size_t>(out.truth_ray);
  out.echo = echoes_[truth];
  out.object_id = hits_[truth].object_id;
  if (hits_[truth].is_hit()) {
    out.p_WH = MeasuredPoint_W(out.p_WS, ray_dir_W_[truth], out.echo.distance_m);
  } else {
    out.p_WH.setConstant(std::numeric_limits<double>::quiet_NaN());
  }
}

}  // namespace proxsim
