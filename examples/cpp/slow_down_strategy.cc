// A strategy written in C++ and run in the closed loop: the robot shortens
// its stride while something stands ahead within 1.2 m and stops within 0.4 m,
// from its sensors' outputs alone. Built with the project
// (build/release/example_slow_down_strategy); run:
//
//   build/release/example_slow_down_strategy [SCENARIO.yaml]
//
// (default: data/scenarios/circumvent_obstacle.yaml, whose lasers look far ahead). A strategy is a class with three methods
// (strategy/strategy.h): name(), Reset(setup) at the start of an episode, and
// Decide(observation, robot, events) at every sample. It is handed to the
// Simulation, which calls it after the readings are delivered.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "core/input_error.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"
#include "strategy/strategy.h"

namespace {

class SlowDownStrategy : public proxsim::Strategy {
 public:
  std::string name() const override { return "slow_down"; }

  void Reset(const proxsim::StrategySetup&) override { mode_ = Mode::kCruise; }

  void Decide(const proxsim::Observation& obs, proxsim::RobotCommands& robot, proxsim::EventLog& events) override {
    if (obs.robot == nullptr || mode_ == Mode::kStopped) return;
    const proxsim::RobotKnowledge& self = *obs.robot;
    // the nearest point a sensor reports ahead, above the ground the robot stands on
    double nearest_m = INFINITY;
    for (const proxsim::SensorOutput& sensor : obs.sensors) {
      if (!sensor.fresh || !sensor.detected) continue;
      const proxsim::Vec3 p_W = sensor.p_W_measured();
      if (p_W.z() - self.ground_z_m < 0.03) continue;  // the floor
      const double ahead_m = (p_W - self.p_W_front).dot(self.heading_W);
      if (ahead_m > 0) nearest_m = std::min(nearest_m, ahead_m);
    }
    if (nearest_m < 0.4) {
      robot.Stop();
      mode_ = Mode::kStopped;
      events.Log("stopped_short", "a point " + std::to_string(nearest_m) + " m ahead");
    } else if (nearest_m < 1.2 && mode_ == Mode::kCruise) {
      robot.SetStride(0.35);
      mode_ = Mode::kCautious;
      events.Log("slowing_down", "a point " + std::to_string(nearest_m) + " m ahead: stride 0.35 m");
    }
  }

 private:
  enum class Mode { kCruise, kCautious, kStopped };
  Mode mode_ = Mode::kCruise;
};

}  // namespace

int main(int argc, char** argv) {
  try {
    proxsim::Scenario scenario = proxsim::LoadScenarioFile(
        argc > 1 ? argv[1] : PROXSIM_SOURCE_DIR "/data/scenarios/circumvent_obstacle.yaml");
    // the scenario's locomotion (nullptr), our strategy instead of the scenario's
    proxsim::Simulation sim(std::move(scenario), 1, nullptr, std::make_unique<SlowDownStrategy>());
    while (!sim.done()) sim.Step();
    for (const proxsim::StrategyEvent& event : sim.events()) {
      std::printf("t = %5.2f s  %-14s %s\n", event.t_s, event.event.c_str(), event.detail.c_str());
    }
    const auto& outcome = sim.robot_outcome();
    std::printf("walked %.2f m; true minimum clearance %.3f m\n", sim.robot_state()->distance_walked_m,
                outcome.min_clearance_m);
    return 0;
  } catch (const proxsim::InputError& error) {
    for (const std::string& problem : error.problems()) std::fprintf(stderr, "%s\n", problem.c_str());
    return 2;
  }
}
