#include "sim/run.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <cstdio>
#include <filesystem>

#include <assimp/version.h>
#include <embree3/rtcore_config.h>

#include "io/atomic_file.h"
#include "io/npy_writer.h"
#include "io/poses_csv.h"
#include "io/profile_ply.h"
#include "io/readings_csv.h"
#include "io/scene_json.h"
#include "sim/run_statistics.h"
#include "sim/simulation.h"

namespace proxsim {

namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

nlohmann::json Versions() {
  return {{"proxsim", PROXSIM_VERSION},
          {"embree", RTC_VERSION_STRING},
          {"assimp", std::to_string(aiGetVersionMajor()) + "." + std::to_string(aiGetVersionMinor()) + "." +
                         std::to_string(aiGetVersionPatch())},
          {"eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                        std::to_string(EIGEN_MINOR_VERSION)}};
}

// the inputs as they were understood, after defaults and presets
nlohmann::json EchoInputs(const Scenario& scenario) {
  nlohmann::json sensors = nlohmann::json::array();
  for (const SensorConfig& sensor : scenario.sensors) {
    const Vec3 rpy_deg = RpyFromRotation(sensor.X_LS.linear()) * (180.0 / kPi);
    const Vec3& xyz = sensor.X_LS.translation();
    sensors.push_back({{"name", sensor.name},
                       {"type", SensorTypeName(sensor.spec.type)},
                       {"link", sensor.link},
                       {"pose", {{"xyz_m", {xyz.x(), xyz.y(), xyz.z()}}, {"rpy_deg", {rpy_deg.x(), rpy_deg.y(), rpy_deg.z()}}}},
                       {"range_m", {sensor.spec.min_range_m, sensor.spec.max_range_m}},
                       {"max_incidence_deg", sensor.spec.max_incidence_deg},
                       {"noise", {{"sigma", sensor.spec.noise.sigma}, {"mean", sensor.spec.noise.mean}}},
                       {"see_robot", sensor.see_robot}});
  }
  nlohmann::json objects = nlohmann::json::array();
  for (const SceneObject& object : scenario.scene.objects) objects.push_back(object.name);
  nlohmann::json robot = nullptr;
  if (scenario.robot) {
    const RobotConfig& r = *scenario.robot;
    nlohmann::json waypoints = nlohmann::json::array();
    for (const Vec2& p : r.waypoints_m) waypoints.push_back({p.x(), p.y()});
    robot = {{"model", r.model},
             {"start", {{"xyz_m", {r.start_xyz_m.x(), r.start_xyz_m.y(), r.start_xyz_m.z()}},
                        {"yaw_deg", RadToDeg(r.start_yaw_rad)}}},
             {"gait", {{"stride_m", r.gait.stride_m}, {"period_s", r.gait.period_s}}},
             {"path", {{"waypoints_m", waypoints}}},
             {"stop_distance_m", r.stop_distance_m ? nlohmann::json(*r.stop_distance_m) : nlohmann::json(nullptr)},
             {"trajectory", r.trajectory_file.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.trajectory_file)}};
  }
  return {{"source", scenario.source},
          {"seed", scenario.seed},
          {"robot", robot},
          {"duration_s", scenario.duration_s},
          {"rate_hz", scenario.rate_hz},
          {"scene", {{"builtin", scenario.builtin_scene}, {"objects", objects}}},
          {"sensors", sensors}};
}

nlohmann::json RobotSummary(const Simulation& sim) {
  const Simulation::RobotOutcome& outcome = sim.robot_outcome();
  const RobotState& state = sim.robot()->state();
  nlohmann::json robot = {{"model", sim.robot()->model().source()},
                          {"stopped", outcome.stopped},
                          {"stop_t_s", outcome.stopped ? nlohmann::json(outcome.stop_t_s) : nlohmann::json(nullptr)},
                          {"stop_requested_t_s", outcome.stop_requested ? nlohmann::json(outcome.stop_request_t_s)
                                                                        : nlohmann::json(nullptr)},
                          {"stop_trigger_sensor", outcome.stop_trigger_sensor >= 0
                                                      ? nlohmann::json(sim.scenario().sensors[outcome.stop_trigger_sensor].name)
                                                      : nlohmann::json(nullptr)},
                          {"min_clearance_m", std::isfinite(outcome.min_clearance_m) ? nlohmann::json(outcome.min_clearance_m)
                                                                                    : nlohmann::json(nullptr)},
                          {"min_clearance_t_s", outcome.min_clearance_t_s},
                          {"distance_walked_m", state.distance_walked_m},
                          {"standing_at_end", state.stopped}};
  return robot;
}

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled) : enabled_(enabled) {}
  void Update(std::int64_t done, std::int64_t total, double t_s) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (done < total && now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    std::fprintf(stderr, "\rproxsim: sample %lld/%lld  t = %.2f s  (%3.0f%%)", static_cast<long long>(done),
                 static_cast<long long>(total), t_s, total > 0 ? 100.0 * done / total : 100.0);
    if (done == total) std::fputc('\n', stderr);
  }

 private:
  bool enabled_;
  Clock::time_point last_{};
};

// How far p_O lies inside the solid shape (negative: outside); planes count
// their z = 0 surface only, meshes have no inside here (nullopt).
std::optional<double> DepthInside(const Shape& shape, const Vec3& p_O) {
  if (const auto* box = std::get_if<Box>(&shape)) return ((box->size_m / 2) - p_O.cwiseAbs()).minCoeff();
  if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere->radius_m - p_O.norm();
  if (const auto* cylinder = std::get_if<Cylinder>(&shape)) {
    return std::min(cylinder->radius_m - p_O.head<2>().norm(), cylinder->length_m / 2 - std::abs(p_O.z()));
  }
  if (std::holds_alternative<Plane>(shape)) return -std::abs(p_O.z());
  return std::nullopt;
}

// Suspicious but legal: a sensor whose ray starts inside a scene object, or
// exactly on its surface (its rays may then hit that surface at d = 0).
std::vector<std::string> SensorsInsideObjects(const Scenario& scenario, const SampleFrame& frame) {
  constexpr double kOnSurface_m = 1e-9;
  std::vector<std::string> warnings;
  for (std::size_t s = 0; s < scenario.sensors.size() && s < frame.sensors.size(); ++s) {
    const Vec3& p_WS = frame.sensors[s].p_WS;
    for (const SceneObject& object : scenario.scene.objects) {
      const auto depth_m = DepthInside(object.shape, object.X_WO.inverse() * p_WS);
      if (!depth_m || *depth_m < -kOnSurface_m) continue;
      char where[160];
      std::snprintf(where, sizeof where, "at t = %g s its origin (%g, %g, %g) m", frame.t_s, p_WS.x(), p_WS.y(),
                    p_WS.z());
      const std::string sensor = scenario.source + ": sensor '" + scenario.sensors[s].name + "'";
      if (*depth_m > kOnSurface_m) {
        warnings.push_back(sensor + " is inside object '" + object.name + "' (" + where +
                           "); it sees that object from within");
      } else {
        warnings.push_back(sensor + " starts on the surface of object '" + object.name + "' (" + where +
                           "); its rays may hit that surface at d = 0");
      }
    }
  }
  return warnings;
}

}  // namespace

RunResult RunScenario(const Scenario& scenario, const RunOptions& options) {
  const auto start = Clock::now();
  // everything that can fail on bad input happens before the folder is made
  Simulation sim(scenario, options.threads);
  std::filesystem::create_directories(options.out_dir);
  const std::filesystem::path out(options.out_dir);

  std::vector<std::string> object_names, sensor_names;
  for (std::size_t id = 0; id < sim.object_count(); ++id) object_names.push_back(sim.object_name(id));
  for (const SensorConfig& sensor : scenario.sensors) sensor_names.push_back(sensor.name);

  const bool npy = options.format == ReadingsFormat::kNpy;
  std::optional<ReadingsCsvWriter> readings;
  std::optional<NpyReadingsWriter> readings_npy;
  if (npy) {
    readings_npy.emplace((out / "readings").string(), scenario, object_names);
  } else {
    readings.emplace((out / "readings.csv").string(), scenario, object_names);
  }
  ProfilePlyWriter profile((out / "profile.ply").string());
  std::unique_ptr<PosesCsvWriter> poses;
  if (sim.robot()) poses = std::make_unique<PosesCsvWriter>((out / "poses.csv").string(), sim.robot()->model());
  RunStatistics statistics(scenario.sensors.size());
  ProgressLine progress(options.progress);

  // the loop: one sample per step, streamed out as it is taken
  const auto loop_start = Clock::now();
  std::vector<std::string> warnings;
  bool interrupted = false;
  std::int64_t samples_done = 0;
  double last_t_s = 0.0;
  while (!sim.done()) {
    // a stop request (SIGINT, SIGTERM) ends the run between two samples
    if (options.stop_signal != nullptr && options.stop_signal->load() != 0) {
      interrupted = true;
      break;
    }
    const SampleFrame& frame = sim.Step();
    ++samples_done;
    last_t_s = frame.t_s;
    if (frame.sample == 0) {
      warnings = SensorsInsideObjects(scenario, frame);
      if (options.warn)
        for (const std::string& warning : warnings) options.warn(warning);
    }
    if (npy) readings_npy->Append(frame); else readings->Append(frame);
    profile.Append(frame);
    statistics.Add(frame);
    if (poses) poses->Append(frame.t_s, sim.robot()->X_WL());
    progress.Update(frame.sample + 1, sim.sample_count(), frame.t_s);
  }
  const double loop_wall_s = SecondsSince(loop_start);

  if (npy) readings_npy->Commit(); else readings->Commit();
  profile.Commit();
  if (poses) poses->Commit();

  RunResult result;
  result.summary = {{"proxsim", 1},
                    {"versions", Versions()},
                    {"inputs", EchoInputs(scenario)},
                    {"samples", samples_done},
                    {"interrupted", interrupted},
                    {"profile_points", profile.point_count()},
                    {"sensors", statistics.ToJson(sensor_names, object_names)},
                    {"outputs", {npy ? "readings/" : "readings.csv", "profile.ply", "scene.json", "summary.json", "timings.json"}}};
  result.summary["warnings"] = warnings;
  if (interrupted) {
    // the files hold every sample up to and including this one
    result.summary["samples_planned"] = sim.sample_count();
    result.summary["last_sample_t_s"] = samples_done > 0 ? nlohmann::json(last_t_s) : nlohmann::json(nullptr);
  }
  result.interrupted = interrupted;
  if (sim.robot()) {
    result.summary["robot"] = RobotSummary(sim);
    result.summary["outputs"].push_back("poses.csv");
  }
  const auto links = sim.robot() ? sim.robot()->LinkGeometry() : std::vector<LinkGeometryJson>{};
  WriteFileAtomically((out / "scene.json").string(), SceneToJson(scenario, links).dump(1) + "\n");
  WriteFileAtomically((out / "summary.json").string(), result.summary.dump(2) + "\n");

  // timings live apart from the summary so that reruns give byte-identical summaries
  result.wall_s = SecondsSince(start);
  const double simulated_s = static_cast<double>(samples_done) / scenario.rate_hz;
  const nlohmann::json timings = {{"wall_s", result.wall_s},
                                  {"loop_wall_s", loop_wall_s},
                                  {"threads", options.threads},
                                  {"simulated_s_per_wall_s", loop_wall_s > 0 ? simulated_s / loop_wall_s : 0.0}};
  WriteFileAtomically((out / "timings.json").string(), timings.dump(2) + "\n");
  return result;
}

}  // namespace proxsim
