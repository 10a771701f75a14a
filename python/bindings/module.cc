// The Python package's core, `proxsim._core` (pybind11): the same Simulation
// as `proxsim run`, stepped from a script. A step returns what the robot
// knows (the devices' outputs and its own kinematics) as NumPy arrays; the
// truth is apart, in truth(); commands go through sim.robot; terrain_map()
// gives the map the robot has built from its readings. With out=DIR
// the run's files are written exactly as `proxsim run` writes them. A robot
// driven from outside (robot.locomotion: external) takes its state in
// step(q=..., X_WP=...) (robot_state.h); VecWalkCore is VecWalkEnv's core
// (vec_walk_env.h).
//
// Errors: a bad scenario raises proxsim.InputError (a ValueError) whose
// `problems` lists the CLI's messages; a wrong value (threads < 1, a stride
// <= 0, a malformed path) raises ValueError; a step after the last sample or
// after close() raises RuntimeError. Nothing here aborts the interpreter.
//
// Threads: every method of a Simulation (and of its Robot) holds the object's
// own mutex, so one Simulation shared by several threads is safe: a second
// call made while another thread is inside step() waits for that step to end
// (with the GIL released while it waits, so the stepping thread can finish).
// Calls are serialised, not interleaved; one Simulation per thread is faster.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "object_lock.h"
#include "robot_state.h"
#include "vec_walk_env.h"
#include "scenario/config_sections.h"
#include "scenario/scenario.h"
#include "run/run.h"
#include "run/run_recorder.h"
#include "sim/simulation.h"
#include "knowledge/terrain_map.h"
#include "sensors/multizone.h"

namespace py = pybind11;

namespace proxsim {
namespace {

// Simulation(..., locomotion="gait" | "external"): the scenario's robot.locomotion, overridden
void OverrideLocomotion(Scenario& scenario, const std::string& locomotion) {
  if (!scenario.robot) throw py::value_error("locomotion: the scenario has no robot section");
  if (locomotion == "gait") {
    scenario.robot->locomotion = LocomotionSource::kGait;
  } else if (locomotion == "external") {
    if (!scenario.robot->trajectory_file.empty())
      throw py::value_error("locomotion='external': the scenario's robot replays a trajectory");
    scenario.robot->locomotion = LocomotionSource::kExternal;
  } else {
    throw py::value_error("locomotion: expected 'gait', 'external' or None, got '" + locomotion + "'");
  }
}

using Clock = std::chrono::steady_clock;

// proxsim.InputError, created at import and raised for every InputError
PyObject* g_input_error = nullptr;

// An integer argument read by hand: pybind11's own conversion answers an
// out-of-range int with a TypeError that names neither the argument nor the range.
std::optional<std::uint64_t> SeedArgument(const py::object& value, const std::string& name) {
  if (value.is_none()) return std::nullopt;
  if (!PyLong_Check(value.ptr()) || PyBool_Check(value.ptr())) {
    throw py::type_error(name + ": expected an int in [0, 2**64 - 1] or None, got " +
                         py::repr(value).cast<std::string>());
  }
  const unsigned long long seed = PyLong_AsUnsignedLongLong(value.ptr());
  if (PyErr_Occurred() != nullptr) {
    PyErr_Clear();
    throw py::value_error(name + ": expected an int in [0, 2**64 - 1], got " + py::repr(value).cast<std::string>());
  }
  return seed;
}

// out=None writes nothing; out='' once did the same, silently, where the CLI refuses `--out ''`
void CheckOutArgument(const std::optional<std::string>& out) {
  if (out && out->empty()) throw py::value_error("out: an empty path; give the folder for the outputs, or None for none");
}

int ThreadsArgument(const py::object& value) {
  constexpr long kMaxThreads = 256;  // as the CLI's --threads
  if (!PyLong_Check(value.ptr()) || PyBool_Check(value.ptr())) {
    throw py::type_error("threads: expected an int in [1, 256], got " + py::repr(value).cast<std::string>());
  }
  int overflow = 0;
  const long threads = PyLong_AsLongAndOverflow(value.ptr(), &overflow);
  if (overflow != 0 || threads < 1 || threads > kMaxThreads) {
    throw py::value_error("threads: expected an int in [1, 256], got " + py::repr(value).cast<std::string>());
  }
  return static_cast<int>(threads);
}

py::array_t<double> Vector(const Vec3& v) {
  py::array_t<double> a(3);
  auto out = a.mutable_unchecked<1>();
  for (int k = 0; k < 3; ++k) out(k) = v[k];
  return a;
}

// The observation's keys as Python strings made once per simulation: a step
// builds two dicts of a dozen entries each, and a key made anew each time
// (and hashed anew) was most of the binding's cost per step.
struct ObservationKeys {
  py::str t_s{"t_s"}, readings{"readings"}, robot{"robot"};
  py::str d_m{"d_m"}, detected{"detected"}, fresh{"fresh"}, signal{"signal"}, output{"output"},
      t_reported_s{"t_reported_s"}, origin_W{"origin_W"}, dir_W{"dir_W"}, zones{"zones"}, status{"status"},
      target_count{"target_count"}, echoes{"echoes"}, count{"count"}, measurements{"measurements"}, code{"code"},
      group{"group"}, rank{"rank"};
  py::str left{"left"}, right{"right"}, pelvis_W{"pelvis_W"}, yaw_deg{"yaw_deg"}, joints_rad{"joints_rad"},
      gait_phase{"gait_phase"}, support_leg{"support_leg"}, has_feet{"has_feet"}, soles_W{"soles_W"},
      toes_W{"toes_W"}, heading_W{"heading_W"}, stopped{"stopped"}, distance_walked_m{"distance_walked_m"},
      half_width_m{"half_width_m"};
  std::vector<std::pair<int, py::str>> joints;  // the moving joints: index and name
};

py::object JsonToPython(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

// Commands for scripts: the simulation's own RobotCommands
class PyRobot {
 public:
  PyRobot(RobotCommands* commands, std::mutex* mutex) : commands_(commands), mutex_(mutex) {}
  void Stop() {
    ObjectLock lock(*mutex_);
    commands_->Stop();
  }
  void Resume() {
    ObjectLock lock(*mutex_);
    commands_->Resume();
  }
  void SetStride(double stride_m) {
    ObjectLock lock(*mutex_);
    commands_->SetStride(stride_m);
  }
  void SetPath(const py::object& waypoints) {
    // any sequence of [x, y] pairs, or an (n, 2) array
    const py::array_t<double, py::array::c_style | py::array::forcecast> array(waypoints);
    if (array.ndim() != 2 || array.shape(1) != 2) {
      throw std::invalid_argument("set_path: expected a list of [x, y] waypoints in metres (shape (n, 2))");
    }
    std::vector<Vec2> path;
    const auto a = array.unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i) path.emplace_back(a(i, 0), a(i, 1));
    ObjectLock lock(*mutex_);
    commands_->SetPath(std::move(path));
  }

 private:
  RobotCommands* commands_;
  std::mutex* mutex_;  ///< the owning Simulation's: commands change what a step does
};

class PySimulation {
 public:
  PySimulation(Scenario scenario, std::optional<std::uint64_t> seed, int threads, std::optional<std::string> out,
               bool scenario_strategy, const std::optional<std::string>& locomotion)
      : out_dir_(out.value_or("")), threads_(threads) {
    if (seed) scenario.seed = *seed;
    if (locomotion) OverrideLocomotion(scenario, *locomotion);
    // a script that drives the robot itself drops the scenario's strategy
    if (!scenario_strategy && scenario.robot) scenario.robot->strategy.reset();
    initial_seed_ = scenario.seed;
    sim_ = std::make_unique<Simulation>(std::move(scenario), threads);
    if (sim_->commands() != nullptr) robot_ = std::make_unique<PyRobot>(sim_->commands(), &mutex_);
    if (sim_->robot() != nullptr) {
      const RobotModel& model = sim_->robot()->model();
      for (const int j : model.MovingJoints()) keys_.joints.emplace_back(j, py::str(model.joint_name(j)));
    }
    StartRecording();
  }

  static std::unique_ptr<PySimulation> FromFile(const std::string& path, const py::object& seed,
                                                const py::object& threads, std::optional<std::string> out,
                                                bool scenario_strategy, std::optional<std::string> locomotion) {
    // the integers first: a bad one is named before a long load
    const auto seed_value = SeedArgument(seed, "seed");
    const int thread_count = ThreadsArgument(threads);
    CheckOutArgument(out);
    return std::make_unique<PySimulation>(LoadScenarioFile(path), seed_value, thread_count, std::move(out),
                                          scenario_strategy, locomotion);
  }

  static std::unique_ptr<PySimulation> Builtin(const std::string& name, const py::object& seed,
                                               const py::object& threads, std::optional<std::string> out,
                                               bool scenario_strategy, std::optional<std::string> locomotion) {
    const auto seed_value = SeedArgument(seed, "seed");
    const int thread_count = ThreadsArgument(threads);
    CheckOutArgument(out);
    return std::make_unique<PySimulation>(LoadBuiltinScenario(name), seed_value, thread_count, std::move(out),
                                          scenario_strategy, locomotion);
  }

  // step(): the robot's own motion; step(q=..., X_WP=...): co-simulation (robot.locomotion: external)
  py::dict Step(const py::object& q, const py::object& X_WP, const py::object& gait_phase,
                const py::object& support_leg) {
    ObjectLock lock(mutex_);
    if (closed_) throw std::runtime_error("step: the simulation is closed");
    if (sim_->done()) {
      throw std::runtime_error("step: every sample of the episode has been taken (sim.done); call reset() for another");
    }
    const bool state_given = !q.is_none() || !X_WP.is_none() || !gait_phase.is_none() || !support_leg.is_none();
    if (state_given && sim_->external() == nullptr) {
      throw py::value_error("step: a robot state was given but the robot moves by itself; drive it from outside with "
                            "robot.locomotion: external (or Simulation(..., locomotion='external'))");
    }
    std::optional<ExternalState> state;
    if (sim_->external() != nullptr) state = ExternalStateFromPython(*sim_->external(), q, X_WP, gait_phase, support_leg);
    if (samples_ == 0) loop_start_ = Clock::now();
    {
      py::gil_scoped_release release;
      recorder_->Add(state ? sim_->Step(*state) : sim_->Step());
    }
    ++samples_;
    return ObservationDict();
  }

  // the robot's true state at the last sample (what a co-simulation sends, the other way)
  py::object RobotStateNow() const {
    ObjectLock lock(mutex_);
    if (sim_->robot_state() == nullptr) return py::none();
    // no state before the episode's first sample (it once read an empty joint vector: SIGSEGV)
    if (samples_ == 0) {
      throw std::runtime_error("robot_state: no sample taken yet in this episode (after Simulation() or reset()); "
                               "call step() first");
    }
    py::dict state = RobotStateDict(sim_->robot()->model(), *sim_->robot_state());
    // a co-simulated robot cannot obey a stop: its caller reads it here
    if (sim_->external() != nullptr) state["stop_requested"] = sim_->external()->stop_requested();
    return state;
  }

  std::vector<std::string> joint_names() const {
    std::vector<std::string> names;
    if (sim_->robot() == nullptr) return names;
    const RobotModel& model = sim_->robot()->model();
    for (const int j : model.MovingJoints()) names.push_back(model.joint_name(j));
    return names;
  }

  bool external() const { return sim_->external() != nullptr; }

  py::dict Truth() const {
    ObjectLock lock(mutex_);
    const SampleFrame& frame = sim_->frame();
    const std::size_t n = frame.sensors.size();
    py::list status, object;
    py::array_t<double> d_true(n), incidence(n), hit({static_cast<py::ssize_t>(n), py::ssize_t{3}});
    auto d = d_true.mutable_unchecked<1>();
    auto a = incidence.mutable_unchecked<1>();
    auto h = hit.mutable_unchecked<2>();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < n; ++i) {
      const SensorSample& s = frame.sensors[i];
      const bool hit_something = s.object_id >= 0;
      status.append(ReadingStatusName(s.reading.status));
      object.append(hit_something ? py::object(py::str(sim_->object_name(s.object_id))) : py::object(py::none()));
      d(i) = hit_something ? s.echo.distance_m : nan;
      a(i) = hit_something ? s.echo.incidence_deg : nan;
      for (int k = 0; k < 3; ++k) h(i, k) = s.p_WH[k];
    }
    py::dict truth;
    truth["t_s"] = frame.t_s;
    truth["status"] = status;
    truth["d_true_m"] = d_true;
    truth["incidence_deg"] = incidence;
    truth["hit_W"] = hit;
    truth["object"] = object;
    if (sim_->robot() != nullptr) {
      const auto& outcome = sim_->robot_outcome();
      truth["min_clearance_m"] = outcome.min_clearance_m;
      truth["reached_goal"] = outcome.reached_goal;
      // how the episode stands: reached_goal, stopped, collided, fell, refused or time_up (summary.json's)
      const Simulation::Outcome episode = sim_->outcome();
      truth["outcome"] = std::string(episode.name());
      truth["outcome_t_s"] = episode.t_s;
      truth["collisions"] = outcome.collisions.size();
    }
    return truth;
  }

  void Reset(const py::object& seed_argument) {
    const std::optional<std::uint64_t> seed = SeedArgument(seed_argument, "reset: seed");
    ObjectLock lock(mutex_);
    if (closed_) throw std::runtime_error("reset: the simulation is closed");
    recorder_.reset();  // an unfinished episode's files are dropped (their temporary names removed)
    sim_->Reset(seed.value_or(initial_seed_));
    StartRecording();
  }

  py::object Summary() const {
    ObjectLock lock(mutex_);
    return JsonToPython(recorder_->Summary(!sim_->done()));
  }

  // The terrain map as the robot has built it so far (what a strategy reads):
  // dense float32 arrays over its tiles, NaN where unknown, and its hazards.
  py::object TerrainMapDict() const {
    ObjectLock lock(mutex_);
    const TerrainMap* map = sim_->terrain_map();
    if (map == nullptr) return py::none();
    const ElevationGrid& grid = map->grid();
    const CellBox box = grid.Bounds();
    const py::ssize_t ny = box.ny(), nx = box.nx();
    py::array_t<float> elevation({ny, nx}), variance({ny, nx}), upper_bound({ny, nx});
    py::array_t<std::uint32_t> hits({ny, nx});
    auto e = elevation.mutable_unchecked<2>();
    auto v = variance.mutable_unchecked<2>();
    auto u = upper_bound.mutable_unchecked<2>();
    auto h = hits.mutable_unchecked<2>();
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    for (py::ssize_t i = 0; i < ny; ++i) {
      for (py::ssize_t j = 0; j < nx; ++j) {
        const TerrainCell* cell = grid.Find({box.ix_min + static_cast<std::int32_t>(j), box.iy_min + static_cast<std::int32_t>(i)});
        const bool measured = cell != nullptr && cell->has_elevation();
        e(i, j) = measured ? cell->elevation_m : kNaN;
        v(i, j) = measured ? cell->variance_m2 : kNaN;
        u(i, j) = cell != nullptr && std::isfinite(cell->upper_bound_m) ? cell->upper_bound_m : kNaN;
        h(i, j) = cell != nullptr ? cell->hits : 0;
      }
    }
    py::list hazards;
    for (const Hazard& hazard : map->hazards()) {
      py::dict d;
      d["class"] = HazardClassName(hazard.hazard_class);
      d["x_m"] = hazard.centroid_W.x();
      d["y_m"] = hazard.centroid_W.y();
      d["size_x_m"] = hazard.max_W.x() - hazard.min_W.x();
      d["size_y_m"] = hazard.max_W.y() - hazard.min_W.y();
      d["height_m"] = hazard.height_m;
      d["first_detection_t_s"] = hazard.first_detection_t_s;
      d["distance_at_detection_m"] = hazard.distance_at_detection_m;
      hazards.append(d);
    }
    py::dict result;
    const double r = grid.resolution_m();
    result["resolution_m"] = r;
    result["origin_xy_m"] = py::make_tuple(box.ix_min * r, box.iy_min * r);
    result["elevation"] = elevation;
    result["variance"] = variance;
    result["upper_bound"] = upper_bound;
    result["hits"] = hits;
    result["hazards"] = hazards;
    return result;
  }

  void Close() {
    ObjectLock lock(mutex_);
    if (closed_) return;
    closed_ = true;
    if (out_dir_.empty()) return;
    const double loop_wall_s = samples_ > 0 ? std::chrono::duration<double>(Clock::now() - loop_start_).count() : 0.0;
    recorder_->Finish(!sim_->done());
    WriteTimings(recorder_->out_dir(), std::chrono::duration<double>(Clock::now() - start_).count(), loop_wall_s, threads_,
                 recorder_->samples(), sim_->scenario().rate_hz);
    recorder_->ReleaseFolder();  // written: another run may take the folder
  }

  bool done() const {
    ObjectLock lock(mutex_);
    return sim_->done();
  }
  double t_s() const {
    ObjectLock lock(mutex_);
    return sim_->frame().t_s;
  }
  std::int64_t sample_count() const {
    ObjectLock lock(mutex_);
    return sim_->sample_count();
  }
  double rate_hz() const { return sim_->scenario().rate_hz; }
  std::uint64_t seed() const {
    ObjectLock lock(mutex_);
    return sim_->scenario().seed;
  }
  py::object robot(py::object self) const {
    // the commands object lives as long as the simulation that owns it
    return robot_ ? py::cast(robot_.get(), py::return_value_policy::reference_internal, self) : py::none();
  }
  std::vector<std::string> sensor_names() const {
    std::vector<std::string> names;
    for (const SensorConfig& sensor : sim_->scenario().sensors) names.push_back(sensor.name);
    return names;
  }

 private:
  void StartRecording() {
    recorder_ = std::make_unique<RunRecorder>(*sim_, out_dir_, ReadingsFormat::kCsv);
    samples_ = 0;
    start_ = Clock::now();
  }

  // a sensor's measurements as arrays of one length: distances, whether
  // each is a detection, the part's codes, signals, groups, ranks, origins and directions
  py::dict MeasurementsDict(const Measurements& list) const {
    const ObservationKeys& k = keys_;
    const auto count = static_cast<py::ssize_t>(list.size());
    py::array_t<double> d_m(count), signal(count), origin({count, py::ssize_t{3}}), dir({count, py::ssize_t{3}});
    py::array_t<bool> detected(count);
    py::array_t<std::uint8_t> code(count);
    py::array_t<std::int32_t> group(count), rank(count);
    for (py::ssize_t m = 0; m < count; ++m) {
      const Measurement& measurement = list[static_cast<std::size_t>(m)];
      d_m.mutable_at(m) = measurement.d_m;
      signal.mutable_at(m) = measurement.signal;
      detected.mutable_at(m) = measurement.detected();
      code.mutable_at(m) = measurement.code;
      group.mutable_at(m) = measurement.group;
      rank.mutable_at(m) = measurement.rank;
      for (int c = 0; c < 3; ++c) {
        origin.mutable_at(m, c) = measurement.p_WS[c];
        dir.mutable_at(m, c) = measurement.dir_W[c];
      }
    }
    py::dict out;
    out[k.d_m] = d_m;
    out[k.detected] = detected;
    out[k.code] = code;
    out[k.signal] = signal;
    out[k.group] = group;
    out[k.rank] = rank;
    out[k.origin_W] = origin;
    out[k.dir_W] = dir;
    return out;
  }

  // a multi-zone part's grid: (zones, targets) distances (0 without a target)
  // and ST's status codes, (zones,) target counts and (zones, 3) zone axes
  py::dict ZonesDict(const Measurements& list, int zone_count, int targets) const {
    const ObservationKeys& k = keys_;
    py::array_t<double> zone_d({py::ssize_t{zone_count}, py::ssize_t{targets}});
    py::array_t<std::uint8_t> zone_status({py::ssize_t{zone_count}, py::ssize_t{targets}});
    py::array_t<std::uint8_t> zone_counts(zone_count);
    py::array_t<double> zone_dir({py::ssize_t{zone_count}, py::ssize_t{3}});
    std::fill_n(zone_d.mutable_data(), zone_count * targets, 0.0);
    std::fill_n(zone_status.mutable_data(), zone_count * targets, kZoneNoTarget);
    std::fill_n(zone_counts.mutable_data(), zone_count, std::uint8_t{0});
    for (const Measurement& measurement : list) {
      zone_status.mutable_at(measurement.group, measurement.rank) = measurement.code;
      if (measurement.rank == 0) {
        for (int c = 0; c < 3; ++c) zone_dir.mutable_at(measurement.group, c) = measurement.dir_W[c];
      }
      if (!measurement.detected()) continue;
      zone_d.mutable_at(measurement.group, measurement.rank) = measurement.d_m;
      ++zone_counts.mutable_at(measurement.group);
    }
    py::dict out;
    out[k.d_m] = zone_d;
    out[k.status] = zone_status;
    out[k.target_count] = zone_counts;
    out[k.dir_W] = zone_dir;
    return out;
  }

  // a beam's echoes: (4,) distances and signals, nearest first, NaN past the echoes heard, and their count
  py::dict EchoesDict(const Measurements& list) const {
    const ObservationKeys& k = keys_;
    py::array_t<double> echo_d(kMaxEchoes), echo_signal(kMaxEchoes);
    std::fill_n(echo_d.mutable_data(), kMaxEchoes, std::numeric_limits<double>::quiet_NaN());
    std::fill_n(echo_signal.mutable_data(), kMaxEchoes, std::numeric_limits<double>::quiet_NaN());
    const std::size_t heard = std::min(list.size(), static_cast<std::size_t>(kMaxEchoes));
    for (std::size_t e = 0; e < heard; ++e) {
      echo_d.mutable_at(static_cast<py::ssize_t>(e)) = list[e].d_m;
      echo_signal.mutable_at(static_cast<py::ssize_t>(e)) = list[e].signal;
    }
    py::dict out;
    out[k.d_m] = echo_d;
    out[k.signal] = echo_signal;
    out[k.count] = static_cast<int>(heard);
    return out;
  }

  py::dict ObservationDict() const {
    const Observation& obs = sim_->observation();
    const std::size_t n = obs.sensors.size();
    py::array_t<double> d_m(n), signal(n), output(n), t_reported(n);
    py::array_t<bool> detected(n), fresh(n);
    py::array_t<double> origin({static_cast<py::ssize_t>(n), py::ssize_t{3}}),
        dir({static_cast<py::ssize_t>(n), py::ssize_t{3}});
    auto d = d_m.mutable_unchecked<1>();
    auto sg = signal.mutable_unchecked<1>();
    auto op = output.mutable_unchecked<1>();
    auto tr = t_reported.mutable_unchecked<1>();
    auto de = detected.mutable_unchecked<1>();
    auto fr = fresh.mutable_unchecked<1>();
    auto o = origin.mutable_unchecked<2>();
    auto u = dir.mutable_unchecked<2>();
    for (std::size_t i = 0; i < n; ++i) {
      const SensorOutput& s = obs.sensors[i];
      d(i) = s.d_m;
      sg(i) = s.signal;
      op(i) = s.output;
      tr(i) = s.t_reported_s;
      de(i) = s.detected;
      fr(i) = s.fresh;
      for (int k = 0; k < 3; ++k) {
        o(i, k) = s.p_WS[k];
        u(i, k) = s.dir_W[k];
      }
    }
    const ObservationKeys& k = keys_;
    py::dict readings;
    readings[k.d_m] = d_m;
    readings[k.detected] = detected;
    readings[k.fresh] = fresh;
    readings[k.signal] = signal;
    readings[k.output] = output;
    readings[k.t_reported_s] = t_reported;
    readings[k.origin_W] = origin;
    readings[k.dir_W] = dir;

    // what each sensor reports beside its reading, by its name, one shape for
    // every part (sensors/measurement.h), and the same as a multi-zone part's
    // (zones, targets) grid and a beam's (4,) echoes
    // (a beam with several echoes has its entry even before it heard one)
    py::dict measurements, zones, echoes;
    for (std::size_t i = 0; i < n; ++i) {
      const SensorOutput& s = obs.sensors[i];
      const SensorSpec& spec = sim_->scenario().sensors[i].spec;
      const py::str name(sim_->scenario().sensors[i].name);
      if (spec.echoes != EchoSelection::kFirst) echoes[name] = EchoesDict(s.measurements);
      if (s.measurements.empty()) continue;
      measurements[name] = MeasurementsDict(s.measurements);
      if (spec.zones) zones[name] = ZonesDict(s.measurements, ZoneCount(*spec.zones), spec.zones->targets);
    }
    readings[k.measurements] = measurements;
    readings[k.zones] = zones;
    readings[k.echoes] = echoes;

    py::dict result;
    result[k.t_s] = obs.t_s;
    result[k.readings] = readings;
    result[k.robot] = obs.robot != nullptr ? py::object(RobotDict(*obs.robot)) : py::object(py::none());
    return result;
  }

  py::dict RobotDict(const RobotKnowledge& self) const {
    const ObservationKeys& k = keys_;
    py::dict joints;
    for (const auto& [j, name] : k.joints) joints[name] = self.q[j];
    py::dict soles, toes;
    soles[k.left] = Vector(self.feet[0].p_W_sole);
    soles[k.right] = Vector(self.feet[1].p_W_sole);
    toes[k.left] = Vector(self.feet[0].p_W_toe);
    toes[k.right] = Vector(self.feet[1].p_W_toe);
    py::dict robot;
    robot[k.pelvis_W] = Vector(self.X_WP.translation());
    robot[k.yaw_deg] = RadToDeg(self.yaw_rad);
    robot[k.joints_rad] = joints;
    robot[k.gait_phase] = self.gait_phase;
    robot[k.support_leg] = SupportLegName(self.support);
    robot[k.has_feet] = self.has_feet;
    robot[k.soles_W] = soles;
    robot[k.toes_W] = toes;
    robot[k.heading_W] = Vector(self.heading_W);
    robot[k.stopped] = self.stopped;
    robot[k.distance_walked_m] = self.distance_walked_m;
    robot[k.half_width_m] = self.half_width_m;
    return robot;
  }

  mutable std::mutex mutex_;  ///< one call at a time (see the file comment)
  std::unique_ptr<Simulation> sim_;
  ObservationKeys keys_;
  std::unique_ptr<PyRobot> robot_;
  std::unique_ptr<RunRecorder> recorder_;
  std::string out_dir_;
  int threads_ = 1;
  std::uint64_t initial_seed_ = 0;
  std::int64_t samples_ = 0;
  bool closed_ = false;
  Clock::time_point start_{}, loop_start_{};
};

}  // namespace
}  // namespace proxsim

PYBIND11_MODULE(_core, m) {
  using proxsim::PyRobot;
  using proxsim::PySimulation;
  m.doc() = "proxsim's simulation core; import the package `proxsim`, not this module";

  // proxsim.InputError(ValueError): str() gives every problem, .problems lists them
  proxsim::g_input_error = PyErr_NewExceptionWithDoc(
      "proxsim.InputError", "A bad scenario, robot or argument: .problems lists every problem, as the CLI prints them.",
      PyExc_ValueError, nullptr);
  m.attr("InputError") = py::handle(proxsim::g_input_error);

  // the scenario sections' declared keys (core/config_schema.h), as the docs' tables give them
  m.def(
      "config_keys",
      [](const std::string& section) {
        const auto params = proxsim::ConfigSectionParams(section);
        if (!params) {
          std::string names;
          for (const std::string& name : proxsim::ConfigSectionNames()) names += (names.empty() ? "" : ", ") + name;
          throw py::value_error("no declared section '" + section + "'; expected one of " + names);
        }
        py::list keys;
        for (const proxsim::ParamDescription& p : *params) {
          py::dict key;
          key["key"] = p.key;
          key["type"] = proxsim::ParamTypeText(p);
          key["unit"] = p.unit;
          const bool number = p.type == proxsim::ParamType::kNumber;
          key["min"] = number && std::isfinite(p.bounds.min) ? py::cast(p.bounds.min) : py::none();
          key["max"] = number && std::isfinite(p.bounds.max) ? py::cast(p.bounds.max) : py::none();
          key["min_open"] = p.bounds.min_open;
          key["max_open"] = p.bounds.max_open;
          key["choices"] = p.choices;
          key["default"] = p.default_text;
          key["meaning"] = p.meaning;
          keys.append(key);
        }
        return keys;
      },
      py::arg("section"),
      "The keys of a scenario section ('material', 'map', 'robot', 'robot.gait', 'strategy.stop', 'strategy.circumvent'): "
      "a list of dicts {key, type, unit, min, max, min_open, max_open, choices, default, meaning}.");
  m.def("config_sections", &proxsim::ConfigSectionNames, "The sections config_keys() describes.");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const proxsim::InputError& error) {
      std::string message;
      py::list problems;
      for (const std::string& problem : error.problems()) {
        message += (message.empty() ? "" : "\n") + problem;
        problems.append(problem);
      }
      py::object exception = py::reinterpret_steal<py::object>(
          PyObject_CallFunction(proxsim::g_input_error, "s", message.c_str()));
      exception.attr("problems") = problems;
      PyErr_SetObject(proxsim::g_input_error, exception.ptr());
    }
  });

  proxsim::BindVecWalkEnv(m);

  py::class_<PyRobot>(m, "Robot", "Commands to the simulated robot; they take effect from the next step on.")
      .def("stop", &PyRobot::Stop, "Stop at the next double support and stand there.")
      .def("resume", &PyRobot::Resume, "Walk again after a stop.")
      .def("set_stride", &PyRobot::SetStride, py::arg("stride_m"), "Stride in metres (> 0) from the next step on.")
      .def("set_path", &PyRobot::SetPath, py::arg("waypoints"),
           "Replace the rest of the path with [[x, y], ...] in metres (world frame).");

  py::class_<PySimulation>(m, "Simulation",
                           "A scenario's simulation, stepped sample by sample (see the package documentation).")
      .def(py::init(&PySimulation::FromFile), py::arg("scenario"), py::arg("seed") = py::none(),
           py::arg("threads") = 1, py::arg("out") = py::none(), py::kw_only(), py::arg("scenario_strategy") = true,
           py::arg("locomotion") = py::none(),
           "scenario: a YAML file; seed: the noise's (default: the scenario's); out: a folder for the run's files; "
           "scenario_strategy=False: drop the scenario's built-in strategy (the script drives the robot); "
           "locomotion='external' or 'gait': overrides robot.locomotion (docs/cosimulation.md).")
      .def_static("builtin", &PySimulation::Builtin, py::arg("name") = "paper", py::arg("seed") = py::none(),
                  py::arg("threads") = 1, py::arg("out") = py::none(), py::kw_only(),
                  py::arg("scenario_strategy") = true, py::arg("locomotion") = py::none(),
                  "A built-in scenario: 'paper' (the default `proxsim run`) or 'world_demo'.")
      .def("step", &PySimulation::Step, py::kw_only(), py::arg("q") = py::none(), py::arg("X_WP") = py::none(),
           py::arg("gait_phase") = py::none(), py::arg("support_leg") = py::none(),
           "Take the next sample; returns what the robot knows (obs). With robot.locomotion: external, the robot's "
           "state at it: q ({joint: rad or m} or an array in joint_names order), X_WP ((xyz, quat_wxyz) or (xyz, R)), "
           "and optionally gait_phase and support_leg ('left', 'right', 'double').")
      .def("robot_state", &PySimulation::RobotStateNow,
           "The robot's true state at the last sample: xyz, quat_wxyz, R, q (joint_names order), gait_phase, "
           "support_leg, stopped, distance_walked_m (and stop_requested when driven from outside); None without a robot.")
      .def("truth", &PySimulation::Truth, "The last sample's truth, for analysis and scoring only.")
      .def("reset", &PySimulation::Reset, py::arg("seed") = py::none(),
           "Start a new episode on the same world (seed: the noise's; default the first one).")
      .def("summary", &PySimulation::Summary, "summary.json's content for the episode so far, as a dict.")
      .def("terrain_map", &PySimulation::TerrainMapDict,
           "The terrain map built so far from the delivered readings (what a strategy sees): resolution_m, "
           "origin_xy_m, elevation, variance, upper_bound (float32 (ny, nx), NaN unknown), hits, hazards; None without one.")
      .def("close", &PySimulation::Close, "With out=DIR: write the run's files. Further steps raise.")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](PySimulation& self, py::object, py::object, py::object) { self.Close(); })
      .def_property_readonly("done", &PySimulation::done)
      .def_property_readonly("t_s", &PySimulation::t_s)
      .def_property_readonly("sample_count", &PySimulation::sample_count)
      .def_property_readonly("rate_hz", &PySimulation::rate_hz, "Samples per second: sample k is at t = k / rate_hz.")
      .def_property_readonly("seed", &PySimulation::seed)
      .def_property_readonly("sensor_names", &PySimulation::sensor_names)
      .def_property_readonly("joint_names", &PySimulation::joint_names,
                             "The robot's moving joints in its joint order: the order of q as an array.")
      .def_property_readonly("external", &PySimulation::external,
                             "True when the robot is driven from outside (robot.locomotion: external).")
      .def_property_readonly("robot", [](py::object self) { return self.cast<const PySimulation&>().robot(self); },
                             "The robot's commands (None without a robot).");
}
