#include "sim/simulation.h"

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
  PlaceSensors(frame_.t_s);
  caster_.Cast(rays_, hits_);
  MeasureAll();
  return frame_;
}

void Simulation::PlaceSensors(double /*t_s*/) {
  for (std::size_t i = 0; i < scenario_.sensors.size(); ++i) {
    const Pose& X_WS = scenario_.sensors[i].X_LS;  // link "world": L is W
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

}  // namespace proxsim
