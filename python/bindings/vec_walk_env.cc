#include "vec_walk_env.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/parallel.h"
#include "object_lock.h"
#include "scenario/scenario.h"
#include "sim/make_locomotion.h"
#include "sim/simulation.h"

namespace py = pybind11;

namespace proxsim {

namespace {

using Clock = std::chrono::steady_clock;

// what the robot itself adds to the sensors' triples (walk_env.py's `own`)
constexpr int kOwnValues = 6;

// The task's parameters, as WalkEnv takes them.
struct WalkTask {
  double min_stride_m = 0;
  double max_stride_m = 0;
  double collision_penalty = 0;
  double fall_penalty = 0;
};

// One environment: its simulation and where its episode stands.
struct EnvSlot {
  std::unique_ptr<Simulation> sim;
  bool walking = true;
  std::size_t collisions = 0;
  double last_distance_m = 0;
  std::uint64_t seed = 0;       // this episode's
  std::uint64_t next_seed = 0;  // the next episode's
  bool autoreset = false;       // the episode ended: the next step starts the next one
  OutcomeKind outcome = OutcomeKind::kTimeUp;  // after the last step
};

// Row i of every output array, written by the thread that steps env i.
struct Outputs {
  float* obs = nullptr;
  double* reward = nullptr;
  bool* terminated = nullptr;
  bool* truncated = nullptr;
  double* t_s = nullptr;
  bool* collided = nullptr;
  bool* fell = nullptr;
  bool* reached_goal = nullptr;
  std::uint64_t* seed = nullptr;
};

class VecWalkCore {
 public:
  VecWalkCore(Scenario scenario, int num_envs, int threads, const WalkTask& task)
      : task_(task), runner_(threads) {
    if (!scenario.robot) throw py::value_error("VecWalkEnv needs a scenario with a robot section (its sensors ride the robot)");
    if (scenario.robot->locomotion == LocomotionSource::kExternal)
      throw py::value_error("VecWalkEnv walks the robot by its gait: the scenario's robot.locomotion is external");
    scenario.robot->strategy.reset();  // the agent drives the robot
    if (!scenario.robot->waypoints_m.empty()) goal_m_ = scenario.robot->waypoints_m.back();
    sensor_count_ = static_cast<int>(scenario.sensors.size());
    envs_.resize(static_cast<std::size_t>(num_envs));
    const std::uint64_t first_seed = scenario.seed;
    // the first alone (a bad scenario fails once, with its message), the
    // others at once, each walking a copy of the first's robot: the model
    // (its URDF or MJCF and its meshes) is loaded once, not once per environment
    envs_[0].sim = std::make_unique<Simulation>(scenario, 1);
    const RobotModel& model = envs_[0].sim->robot()->model();
    {
      py::gil_scoped_release release;
      runner_.For(envs_.size() - 1, 1, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin + 1; i < end + 1; ++i) {
          envs_[i].sim = std::make_unique<Simulation>(
              scenario, 1, MakeLocomotion(*scenario.robot, scenario.rate_hz, RobotModel(model)), nullptr);
        }
      });
    }
    for (std::size_t i = 0; i < envs_.size(); ++i) envs_[i].next_seed = first_seed + i;
  }

  int num_envs() const { return static_cast<int>(envs_.size()); }
  int observation_size() const { return 3 * sensor_count_ + kOwnValues; }
  double last_cpp_s() const {
    ObjectLock lock(mutex_);
    return last_cpp_s_;
  }

  // reset(seeds): every environment's next episode, seeded seeds[i] (None: each one's next seed)
  py::tuple Reset(const std::optional<std::vector<std::uint64_t>>& seeds) {
    ObjectLock lock(mutex_);
    if (seeds && seeds->size() != envs_.size()) {
      throw py::value_error("reset: expected " + std::to_string(envs_.size()) + " seeds (one per environment), got " +
                            std::to_string(seeds->size()));
    }
    Arrays arrays(envs_.size(), observation_size());
    const Outputs out = arrays.Pointers();
    Timed([&] {
      runner_.For(envs_.size(), 1, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) ResetEnv(i, seeds ? (*seeds)[i] : envs_[i].next_seed, out);
      });
    });
    started_ = true;
    return py::make_tuple(arrays.obs, Infos(arrays));
  }

  // step(actions): one step of every environment; (obs, rewards, terminations, truncations, infos)
  py::tuple Step(const py::object& actions_argument) {
    ObjectLock lock(mutex_);
    if (!started_) throw std::runtime_error("step: call reset() first (Gymnasium's order)");
    const py::array_t<double, py::array::c_style | py::array::forcecast> actions(actions_argument);
    const auto n = static_cast<py::ssize_t>(envs_.size());
    if (actions.ndim() != 2 || actions.shape(0) != n || actions.shape(1) != 2) {
      throw py::value_error("step: expected actions [walk, stride_m] of shape (" + std::to_string(n) + ", 2), got shape " +
                            py::repr(py::tuple(py::cast(std::vector<py::ssize_t>(actions.shape(), actions.shape() + actions.ndim())))).cast<std::string>());
    }
    const double* a = actions.data();
    for (py::ssize_t i = 0; i < 2 * n; ++i) {
      if (!std::isfinite(a[i])) {
        throw py::value_error("step: actions[" + std::to_string(i / 2) + "][" + std::to_string(i % 2) + "] (" +
                              (i % 2 == 0 ? "walk" : "stride_m") + ") is " + py::repr(py::float_(a[i])).cast<std::string>() +
                              ": expected a finite number");
      }
    }
    Arrays arrays(envs_.size(), observation_size());
    const Outputs out = arrays.Pointers();
    Timed([&] {
      runner_.For(envs_.size(), 1, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
          if (envs_[i].autoreset) {
            ResetEnv(i, envs_[i].next_seed, out);
          } else {
            StepEnv(i, a[2 * i], a[2 * i + 1], out);
          }
        }
      });
    });
    for (std::size_t i = 0; i < envs_.size(); ++i) envs_[i].autoreset = out.terminated[i] || out.truncated[i];
    return py::make_tuple(arrays.obs, arrays.reward, arrays.terminated, arrays.truncated, Infos(arrays));
  }

  std::vector<std::string> sensor_names() const {
    std::vector<std::string> names;
    for (const SensorConfig& sensor : envs_[0].sim->scenario().sensors) names.push_back(sensor.name);
    return names;
  }

 private:
  // the step's output arrays, made with the GIL held
  struct Arrays {
    Arrays(std::size_t n, int d)
        : obs({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(d)}), reward(n), terminated(n), truncated(n),
          t_s(n), collided(n), fell(n), reached_goal(n), seed(n) {}
    Outputs Pointers() {
      return {obs.mutable_data(), reward.mutable_data(), terminated.mutable_data(), truncated.mutable_data(),
              t_s.mutable_data(), collided.mutable_data(), fell.mutable_data(), reached_goal.mutable_data(),
              seed.mutable_data()};
    }
    py::array_t<float> obs;
    py::array_t<double> reward;
    py::array_t<bool> terminated, truncated;
    py::array_t<double> t_s;
    py::array_t<bool> collided, fell, reached_goal;
    py::array_t<std::uint64_t> seed;
  };

  template <typename Work>
  void Timed(Work&& work) {
    py::gil_scoped_release release;
    const auto start = Clock::now();
    work();
    last_cpp_s_ = std::chrono::duration<double>(Clock::now() - start).count();
  }

  // Gymnasium's vector infos: an array per key, and "_key" saying which environments have it (all)
  py::dict Infos(Arrays& arrays) {
    py::array_t<bool> all(static_cast<py::ssize_t>(envs_.size()));
    std::fill_n(all.mutable_data(), envs_.size(), true);
    // an object array of None from NumPy itself, its items then replaced by the outcomes' names
    py::array outcome = numpy_empty_(static_cast<py::ssize_t>(envs_.size()), "O");
    auto** items = static_cast<PyObject**>(outcome.mutable_data());
    for (std::size_t i = 0; i < envs_.size(); ++i) {
      py::str& name = outcome_names_[static_cast<std::size_t>(envs_[i].outcome)];
      Py_XDECREF(items[i]);
      items[i] = name.inc_ref().ptr();
    }
    py::dict infos;
    const std::pair<const char*, py::object> entries[] = {
        {"t_s", arrays.t_s},           {"outcome", outcome}, {"collided", arrays.collided}, {"fell", arrays.fell},
        {"reached_goal", arrays.reached_goal}, {"episode_seed", arrays.seed}};
    for (const auto& [key, value] : entries) {
      infos[key] = value;
      infos[(std::string("_") + key).c_str()] = all;
    }
    return infos;
  }

  // WalkEnv._distance_to_goal
  double DistanceToGoal(const RobotKnowledge& robot) const {
    if (!goal_m_) return 0.0;
    return std::hypot(robot.X_WP.translation().x() - goal_m_->x(), robot.X_WP.translation().y() - goal_m_->y());
  }

  // WalkEnv._vector, row i
  void FillObservation(std::size_t i, const Outputs& out) const {
    const Observation& obs = envs_[i].sim->observation();
    float* row = out.obs + i * static_cast<std::size_t>(observation_size());
    for (const SensorOutput& s : obs.sensors) {
      *row++ = static_cast<float>(s.d_m);
      *row++ = s.detected ? 1.0f : 0.0f;
      *row++ = s.fresh ? 1.0f : 0.0f;
    }
    const RobotKnowledge& robot = *obs.robot;
    // the yaw as WalkEnv has it: degrees in the observation dict, back to radians by NumPy (x · (π/180))
    const double yaw_deg = RadToDeg(robot.yaw_rad);
    *row++ = static_cast<float>(robot.X_WP.translation().x());
    *row++ = static_cast<float>(robot.X_WP.translation().y());
    *row++ = static_cast<float>(yaw_deg * (kPi / 180.0));
    *row++ = static_cast<float>(robot.gait_phase);
    *row++ = robot.stopped ? 1.0f : 0.0f;
    *row++ = static_cast<float>(robot.distance_walked_m);
    out.t_s[i] = obs.t_s;
  }

  // WalkEnv.reset(seed=seed), environment i
  void ResetEnv(std::size_t i, std::uint64_t seed, const Outputs& out) {
    EnvSlot& env = envs_[i];
    env.sim->Reset(seed);
    env.seed = seed;
    env.next_seed = seed + envs_.size();
    env.walking = true;
    env.collisions = 0;
    env.autoreset = false;
    env.sim->Step();
    env.last_distance_m = DistanceToGoal(*env.sim->observation().robot);
    env.outcome = env.sim->outcome().kind;
    FillObservation(i, out);
    out.reward[i] = 0.0;
    out.terminated[i] = out.truncated[i] = false;
    out.collided[i] = out.fell[i] = false;
    out.reached_goal[i] = env.sim->robot_outcome().reached_goal;
    out.seed[i] = seed;
  }

  // WalkEnv.step([walk, stride_m]), environment i
  void StepEnv(std::size_t i, double walk_value, double stride_m, const Outputs& out) {
    EnvSlot& env = envs_[i];
    RobotCommands& robot = *env.sim->commands();
    const bool walk = walk_value >= 0.5;
    if (walk != env.walking) {
      if (walk) robot.Resume();
      else robot.Stop();
      env.walking = walk;
    }
    robot.SetStride(std::clamp(stride_m, task_.min_stride_m, task_.max_stride_m));
    env.sim->Step();
    const double distance_m = DistanceToGoal(*env.sim->observation().robot);
    double reward = env.last_distance_m - distance_m;
    env.last_distance_m = distance_m;
    env.outcome = env.sim->outcome().kind;
    const bool collided = env.outcome == OutcomeKind::kCollided, fell = env.outcome == OutcomeKind::kFell;
    const std::size_t collisions = env.sim->robot_outcome().collisions.size();
    if (collisions > env.collisions) reward -= task_.collision_penalty;  // a new collision this step
    env.collisions = collisions;
    if (fell) reward -= task_.fall_penalty;
    const bool terminated = collided || fell || env.outcome == OutcomeKind::kReachedGoal;
    FillObservation(i, out);
    out.reward[i] = reward;
    out.terminated[i] = terminated;
    out.truncated[i] = env.sim->done() && !terminated;
    out.collided[i] = collided;
    out.fell[i] = fell;
    out.reached_goal[i] = env.sim->robot_outcome().reached_goal;
    out.seed[i] = env.seed;
  }

  // one reset or step at a time: both release the GIL while the simulations
  // step, and a second thread's reset under a step freed what it read (SIGSEGV)
  mutable std::mutex mutex_;
  WalkTask task_;
  ParallelRunner runner_;
  std::vector<EnvSlot> envs_;
  std::optional<Vec2> goal_m_;
  int sensor_count_ = 0;
  double last_cpp_s_ = 0;
  bool started_ = false;  // reset() was called
  // each outcome's name as a Python string, made once (OutcomeKind's order)
  std::vector<py::str> outcome_names_ = [] {
    std::vector<py::str> names;
    for (const std::string_view name : kOutcomeNames) names.emplace_back(std::string(name));
    return names;
  }();
  py::object numpy_empty_ = py::module_::import("numpy").attr("empty");
};

Scenario ScenarioArgument(const std::string& scenario) {
  constexpr const char* kBuiltin = "builtin:";
  if (scenario.starts_with(kBuiltin)) return LoadBuiltinScenario(scenario.substr(std::string(kBuiltin).size()));
  return LoadScenarioFile(scenario);
}

}  // namespace

void BindVecWalkEnv(py::module_& m) {
  py::class_<VecWalkCore>(m, "VecWalkCore", "The C++ core of proxsim.VecWalkEnv; use that class.")
      .def(py::init([](const std::string& scenario, int num_envs, int threads, double min_stride_m, double max_stride_m,
                       double collision_penalty, double fall_penalty) {
             if (num_envs < 1 || num_envs > 4096) throw py::value_error("num_envs: expected an int in [1, 4096], got " + std::to_string(num_envs));
             if (threads < 1 || threads > 256) throw py::value_error("threads: expected an int in [1, 256], got " + std::to_string(threads));
             return std::make_unique<VecWalkCore>(ScenarioArgument(scenario), num_envs, threads,
                                                  WalkTask{min_stride_m, max_stride_m, collision_penalty, fall_penalty});
           }),
           py::arg("scenario"), py::arg("num_envs"), py::arg("threads"), py::arg("min_stride_m"),
           py::arg("max_stride_m"), py::arg("collision_penalty"), py::arg("fall_penalty"))
      .def("reset", &VecWalkCore::Reset, py::arg("seeds") = py::none())
      .def("step", &VecWalkCore::Step, py::arg("actions"))
      .def_property_readonly("num_envs", &VecWalkCore::num_envs)
      .def_property_readonly("observation_size", &VecWalkCore::observation_size)
      .def_property_readonly("sensor_names", &VecWalkCore::sensor_names)
      .def_property_readonly("last_cpp_s", &VecWalkCore::last_cpp_s,
                             "Wall time of the last reset/step's C++ work (the GIL released), s.");
}

}  // namespace proxsim
