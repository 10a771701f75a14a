// Co-simulation through the C++ library (robot.locomotion: external): a
// simulation driven by a gait simulation's states measures what it measured,
// a bad state is refused with every fault named and changes nothing, and the
// two Step() overloads refuse the wrong kind of robot.
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/input_error.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

Scenario PaperWith(LocomotionSource locomotion) {
  Scenario scenario = LoadBuiltinScenario("paper");
  scenario.robot->locomotion = locomotion;
  return scenario;
}

// The state the gait took at its last sample, as a caller would give it
ExternalState StateOf(const Simulation& gait) {
  const RobotState& s = *gait.robot_state();
  ExternalState state;
  state.p_WP = s.X_WP.translation();
  state.R_WP = s.X_WP.linear();
  for (const int j : gait.robot()->model().MovingJoints()) state.q.push_back(s.q[j]);
  state.gait_phase = s.gait_phase;
  state.support = s.support;
  return state;
}

TEST(Cosimulation, DrivenByTheGaitsStatesMeasuresWhatTheGaitMeasured) {
  Simulation gait(PaperWith(LocomotionSource::kGait), 1);
  Simulation external(PaperWith(LocomotionSource::kExternal), 1);
  ASSERT_EQ(gait.external(), nullptr);
  ASSERT_NE(external.external(), nullptr);
  int compared = 0;
  while (!gait.done()) {
    const SampleFrame& a = gait.Step();
    const SampleFrame& b = external.Step(StateOf(gait));
    ASSERT_EQ(a.t_s, b.t_s);
    ASSERT_EQ(a.sensors.size(), b.sensors.size());
    for (std::size_t i = 0; i < a.sensors.size(); ++i) {
      EXPECT_EQ(a.sensors[i].reading.status, b.sensors[i].reading.status) << a.t_s;
      EXPECT_NEAR(a.sensors[i].reading.d_m, b.sensors[i].reading.d_m, 1e-9) << a.t_s;
      EXPECT_EQ(a.sensors[i].object_id, b.sensors[i].object_id) << a.t_s;
      ++compared;
    }
    EXPECT_EQ(a.robot.support, b.robot.support);
  }
  EXPECT_GT(compared, 1000);
  EXPECT_TRUE(external.done());
  // the stop rule decided the same: its stop is recorded for the caller, and the outcome is the gait's
  EXPECT_TRUE(external.robot_outcome().stop_requested);
  EXPECT_EQ(external.robot_outcome().stop_request_t_s, gait.robot_outcome().stop_request_t_s);
  EXPECT_TRUE(external.external()->stop_requested());
  EXPECT_EQ(external.outcome().name(), gait.outcome().name());
  EXPECT_EQ(external.robot_outcome().min_clearance_m, gait.robot_outcome().min_clearance_m);
}

TEST(Cosimulation, ABadStateIsRefusedWithEveryFaultAndChangesNothing) {
  Simulation sim(PaperWith(LocomotionSource::kExternal), 1);
  const ExternalDrive& drive = *sim.external();
  ExternalState state;
  state.p_WP = Vec3(0, 0, 0.95);
  state.quat_wxyz = Eigen::Vector4d(1, 0, 0, 0);
  state.q.assign(drive.joint_names().size(), 0.0);
  sim.Step(state);

  ExternalState bad = state;
  bad.quat_wxyz = Eigen::Vector4d(0.9, 0, 0, 0);
  bad.p_WP.x() = 1.0;  // not checked: the pose is not valid
  bad.q[0] = 7.0;      // outside the limits and a jump
  try {
    sim.Step(bad);
    FAIL() << "a bad state was taken";
  } catch (const InputError& error) {
    ASSERT_EQ(error.problems().size(), 3u) << error.what();
    EXPECT_NE(error.problems()[0].find("expected a unit quaternion"), std::string::npos);
    EXPECT_NE(error.problems()[1].find("outside its URDF limits"), std::string::npos);
    EXPECT_NE(error.problems()[2].find("jumped 7 rad"), std::string::npos);
  }
  EXPECT_EQ(sim.samples_taken(), 1);
  EXPECT_EQ(sim.robot_state()->X_WP.translation().x(), 0.0);
  sim.Step(state);
  EXPECT_EQ(sim.samples_taken(), 2);
  EXPECT_TRUE(sim.robot_state()->stopped);  // the same state as the last sample's: standing
}

TEST(Cosimulation, JointsByNameNameTheMissingAndTheUnknown) {
  Simulation sim(PaperWith(LocomotionSource::kExternal), 1);
  const ExternalDrive& drive = *sim.external();
  std::vector<std::pair<std::string, double>> named;
  for (const std::string& name : drive.joint_names()) named.emplace_back(name, 0.1);
  EXPECT_EQ(drive.JointVector(named), std::vector<double>(drive.joint_names().size(), 0.1));
  named.erase(named.begin());
  named.emplace_back("tail", 0.0);
  try {
    drive.JointVector(named);
    FAIL();
  } catch (const InputError& error) {
    ASSERT_EQ(error.problems().size(), 2u);
    EXPECT_NE(error.problems()[0].find("'tail' is not a moving joint"), std::string::npos);
    EXPECT_NE(error.problems()[1].find("joint '" + drive.joint_names()[0] + "' is missing"), std::string::npos);
  }
}

TEST(Cosimulation, EachStepRefusesTheOtherKindOfRobot) {
  Simulation external(PaperWith(LocomotionSource::kExternal), 1);
  EXPECT_THROW(external.Step(), std::logic_error);
  Simulation gait(PaperWith(LocomotionSource::kGait), 1);
  EXPECT_THROW(gait.Step(ExternalState{}), std::logic_error);
}

}  // namespace
}  // namespace proxsim
