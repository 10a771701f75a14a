// Moving objects (docs/worlds.md): the motions' closed forms (waypoints in
// each mode, a velocity, a trajectory), an ideal sensor fixed in the world
// reading a box that comes at it at constant speed (the analytic distance at
// every sample), a person's leg crossing a beam at shin height (the echo at
// the leg's true place, computed here from the documented proportions), the
// first-order time-of-flight formula for a moving surface, a robot struck by
// a moving box (a collision like any other), and bad input (a moving ground,
// times that do not increase) refused naming the fault.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "core/input_error.h"
#include "scenario/scenario.h"
#include "scene/motion.h"
#include "sensors/sensor_model.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

std::string ErrorText(const std::string& text) {
  try {
    LoadScenarioText(text, "moving.yaml");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

// --- the motions -----------------------------------------------------------

TEST(Motion, WaypointsLoopFacingTheirDirectionOfTravel) {
  Motion motion;
  motion.waypoints_m = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1)};
  motion.speed_m_s = 0.5;
  motion.start_s = 1.0;
  // waits at the first waypoint facing the first segment
  EXPECT_TRUE(MotionPoseAt(motion, 0.5).translation().isApprox(Vec3(0, 0, 0)));
  // 1 m along the first segment at t = 3 s, facing +x
  const Pose at3 = MotionPoseAt(motion, 3.0);
  EXPECT_NEAR((at3.translation() - Vec3(1, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((at3.linear() * Vec3::UnitX() - Vec3::UnitX()).norm(), 0, 1e-12);
  // 2.5 m: on the second segment, facing +y
  const Pose at6 = MotionPoseAt(motion, 6.0);
  EXPECT_NEAR((at6.translation() - Vec3(2, 0.5, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((at6.linear() * Vec3::UnitX() - Vec3::UnitY()).norm(), 0, 1e-12);
  // the loop closes back to the first waypoint: perimeter 3 + √5
  const double perimeter = 3 + std::sqrt(5.0);
  const double t_lap = 1.0 + perimeter / 0.5;
  EXPECT_NEAR((MotionPoseAt(motion, t_lap + 2.0).translation() - Vec3(1, 0, 0)).norm(), 0, 1e-9);
  const Vec3 back = MotionPoseAt(motion, t_lap - 0.2).linear() * Vec3::UnitX();
  EXPECT_NEAR((back - Vec3(-2, -1, 0).normalized()).norm(), 0, 1e-12);
}

TEST(Motion, BackAndForthTurnsAroundOnceStops) {
  Motion motion;
  motion.waypoints_m = {Vec2(0, 0), Vec2(4, 0)};
  motion.speed_m_s = 1.0;
  motion.mode = MotionMode::kBackAndForth;
  const Pose at5 = MotionPoseAt(motion, 5.0);
  EXPECT_NEAR((at5.translation() - Vec3(3, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((at5.linear() * Vec3::UnitX() + Vec3::UnitX()).norm(), 0, 1e-12);
  EXPECT_NEAR((MotionPoseAt(motion, 9.0).translation() - Vec3(1, 0, 0)).norm(), 0, 1e-12);
  motion.mode = MotionMode::kOnce;
  EXPECT_NEAR((MotionPoseAt(motion, 50.0).translation() - Vec3(4, 0, 0)).norm(), 0, 1e-12);
  EXPECT_DOUBLE_EQ(MotionFrameAt(motion, 50.0).travelled_m, 4.0);
}

TEST(Motion, VelocityAndTrajectoryAndTheObjectsPoseInTheirFrame) {
  Motion velocity;
  velocity.kind = Motion::Kind::kVelocity;
  velocity.velocity_m_s = Vec3(0.3, -0.4, 0.1);
  velocity.X_MO.translation() = Vec3(1, 2, 0.5);
  EXPECT_NEAR((MotionPoseAt(velocity, 2.0).translation() - Vec3(1.6, 1.2, 0.7)).norm(), 0, 1e-12);
  EXPECT_NEAR((MotionPointVelocity_W(velocity, 2.0, Vec3(5, 5, 5)) - velocity.velocity_m_s).norm(), 0, 1e-9);

  Motion trajectory;
  trajectory.kind = Motion::Kind::kTrajectory;
  trajectory.trajectory = {{0.0, Vec3(0, 0, 0), 0.0}, {2.0, Vec3(2, 0, 0.4), DegToRad(90)}};
  const Pose at1 = MotionPoseAt(trajectory, 1.0);
  EXPECT_NEAR((at1.translation() - Vec3(1, 0, 0.2)).norm(), 0, 1e-12);
  EXPECT_NEAR((at1.linear() * Vec3::UnitX() - Vec3(std::cos(kPi / 4), std::sin(kPi / 4), 0)).norm(), 0, 1e-12);
  // before the first row and after the last it holds still
  EXPECT_NEAR((MotionPoseAt(trajectory, -1.0).translation()).norm(), 0, 1e-12);
  EXPECT_NEAR((MotionPoseAt(trajectory, 9.0).translation() - Vec3(2, 0, 0.4)).norm(), 0, 1e-12);
}

// --- every sensor sees objects where they are ------------------------------

// An ideal sensor fixed at (0, 0, 0.5) facing +x; `objects` listed under scene.objects.
std::string FixedSensorScenario(const std::string& objects, const std::string& sensor_extra = "") {
  return "proxsim: 1\n"
         "duration_s: 4\n"
         "rate_hz: 50\n"
         "scene:\n"
         "  objects:\n" +
         objects +
         "sensors:\n"
         "  - {name: s, type: ideal, link: world, range_m: [0, 5], pose: {xyz_m: [0, 0, 0.5]}" +
         sensor_extra + "}\n";
}

TEST(MovingObjects, AFixedIdealSensorReadsABoxComingAtItAtTheAnalyticDistance) {
  // the box's near face starts at x = 3.9 and comes at 0.5 m/s: d(t) = 3.9 − 0.5·t
  const Scenario scenario = LoadScenarioText(
      FixedSensorScenario("    - {name: cart, box: {size_m: [0.2, 1, 1]}, pose: {xyz_m: [4, 0, 0.5]},\n"
                          "       motion: {velocity_m_s: [-0.5, 0, 0]}}\n"),
      "moving.yaml");
  Simulation sim(scenario, 1);
  int samples = 0;
  while (!sim.done()) {
    const SampleFrame& frame = sim.Step();
    const SensorSample& sample = frame.sensors[0];
    ASSERT_TRUE(sample.reading.detected()) << frame.t_s;
    EXPECT_NEAR(sample.reading.d_m, 3.9 - 0.5 * frame.t_s, 1e-5) << frame.t_s;
    EXPECT_EQ(sim.object_name(sample.object_id), "cart");
    ++samples;
  }
  EXPECT_EQ(samples, 200);
}

TEST(MovingObjects, AWalkingPersonsLegCrossesABeamAtShinHeightWhereTheLegIs) {
  // a 1.75 m person walks along +y at x = 1.5 across a beam at z = 0.25 m
  const double H = 1.75, x_walk = 1.5, speed = 1.0, z_beam = 0.25;
  const Scenario scenario = LoadScenarioText(
      "proxsim: 1\nduration_s: 4\nrate_hz: 100\nscene:\n  objects:\n"
      "    - {name: walker, person: {height_m: 1.75}, motion: {waypoints_m: [[1.5, -2], [1.5, 2]], speed_m_s: 1, mode: once}}\n"
      "sensors:\n"
      "  - {name: s, type: ideal, link: world, range_m: [0, 5], pose: {xyz_m: [0, 0, 0.25]}}\n",
      "moving.yaml");
  // the documented proportions: hip at 0.53·H, legs 0.05·H either side of the
  // middle, radius 0.04·H, a full swing cycle per 0.8·H walked, the feet a
  // step (0.4·H) apart at full swing; the left leg's angle is A·sin(2π·s/cycle)
  const double hip_z = 0.53 * H, hip_y = 0.05 * H, r = 0.04 * H, cycle = 0.8 * H;
  const double A = std::asin(0.2 * H / hip_z);
  // where a beam along +x at y = 0 meets a leg: the person faces +y, so its
  // left (+y of the person) is world −x and the legs swing in the y–z plane
  const auto leg_distance = [&](double t, double side, double phase) {
    const double s = speed * t;  // travelled
    const double theta = A * std::sin(2 * kPi * s / cycle + phase);
    const double y_hip = -2 + s, x_axis = x_walk - side * hip_y;
    // the axis goes down from the hip, leaning forward (+y) by theta
    const double along = (hip_z - z_beam) / std::cos(theta);
    const double y_axis = y_hip - along * std::sin(theta);
    // the tilted cylinder's section at z_beam: an ellipse with semi-axes r (x) and r/cos(theta) (y)
    const double u = (0 - y_axis) * std::cos(theta) / r;
    if (std::abs(u) >= 1) return std::numeric_limits<double>::infinity();
    return x_axis - r * std::sqrt(1 - u * u);
  };
  Simulation sim(scenario, 1);
  int leg_hits = 0;
  while (!sim.done()) {
    const SampleFrame& frame = sim.Step();
    const SensorSample& sample = frame.sensors[0];
    const double expected = std::min(leg_distance(frame.t_s, +1, 0), leg_distance(frame.t_s, -1, kPi));
    if (!sample.reading.detected()) {
      EXPECT_TRUE(std::isinf(expected)) << frame.t_s;
      continue;
    }
    const std::string object = sim.object_name(sample.object_id);
    ASSERT_TRUE(object == "walker/left_leg" || object == "walker/right_leg") << object << " at " << frame.t_s;
    EXPECT_NEAR(sample.reading.d_m, expected, 1e-4) << frame.t_s;
    ++leg_hits;
  }
  EXPECT_GT(leg_hits, 5);
}

TEST(MovingObjects, ATimeOfFlightReadingMeetsTheMovingSurfaceToFirstOrder) {
  // the box comes at 20 m/s at a sensor whose wave travels at 343 m/s: the
  // wave meets the face at d·c/(c + v), and comes back as far (the sensor stands)
  const double c = 343.0, v = 20.0;
  const Scenario scenario = LoadScenarioText(
      FixedSensorScenario("    - {name: cart, box: {size_m: [0.2, 1, 1]}, pose: {xyz_m: [4.1, 0, 0.5]},\n"
                          "       motion: {velocity_m_s: [-20, 0, 0]}}\n",
                          ", flight_time: true, wave_speed_m_s: 343"),
      "moving.yaml");
  Simulation sim(scenario, 1);
  int samples = 0;
  while (!sim.done()) {
    const SampleFrame& frame = sim.Step();
    const SensorSample& sample = frame.sensors[0];
    const double d = 4.0 - v * frame.t_s;
    if (d < 0.5) break;
    ASSERT_TRUE(sample.reading.detected()) << frame.t_s;
    EXPECT_NEAR(sample.reading.d_m, d * c / (c + v), 1e-6) << frame.t_s;
    EXPECT_NEAR(sample.echo.distance_m, d, 1e-5) << "the truth is the distance at the emission";
    ++samples;
  }
  EXPECT_GT(samples, 5);
  // a surface seen obliquely: the meeting follows the normal's share of the velocity
  const Vec3 dir = Vec3(1, 1, 0).normalized(), n = -Vec3::UnitX(), vel(-3, 7, 0);
  EXPECT_NEAR(MovingSurfaceMeeting_m(2.0, dir, n, vel, c), 2.0 / (1 - 3 / (c * -dir.x())), 1e-12);
}

TEST(MovingObjects, ARobotStruckByAMovingBoxCollidesWithIt) {
  const Scenario scenario = LoadScenarioText(
      "proxsim: 1\nduration_s: 6\nrate_hz: 50\n"
      "scene:\n  builtin: empty\n  objects:\n"
      "    - {name: floor, plane: {}}\n"
      "    - {name: cart, box: {size_m: [0.4, 0.8, 0.6]}, pose: {xyz_m: [4, 0, 0.3]}, motion: {velocity_m_s: [-1, 0, 0]}}\n"
      "robot:\n  path: {waypoints_m: [[0, 0], [3, 0]]}\n"
      "sensors:\n  - {name: s, type: ideal, link: left_tibia}\n",
      "moving.yaml");
  Simulation sim(scenario, 1);
  while (!sim.done()) sim.Step();
  ASSERT_FALSE(sim.robot_outcome().collisions.empty());
  EXPECT_EQ(sim.robot_outcome().collisions.front().object, "cart");
  EXPECT_EQ(sim.outcome().name(), "collided");
  // about when the cart (front at 3.8 − t) meets a robot a few tens of cm ahead of x = 0.3·t
  EXPECT_GT(sim.robot_outcome().collisions.front().t_s, 1.5);
  EXPECT_LT(sim.robot_outcome().collisions.front().t_s, 4.0);
}

// People as pedestrians: one whose way crosses the place where the robot
// stands waits for it (kPedestrianPassStanding_m) and never walks into it — at
// several crossings, starting before and after the robot stops — while a
// robot that walks into a person has collided (the baseline that must fail).
std::string PersonScenario(double cross_x_m, double start_s, const std::string& goal, double speed_m_s,
                           const std::string& waypoints) {
  return "proxsim: 1\nduration_s: 12\nrate_hz: 50\n"
         "scene:\n  builtin: empty\n  objects:\n"
         "    - {name: floor, plane: {}}\n"
         "    - name: walker\n      person: {height_m: 1.7}\n"
         "      motion: {waypoints_m: " + (waypoints.empty() ? "[[" + std::to_string(cross_x_m) + ", -3], [" +
                                                                  std::to_string(cross_x_m) + ", 3]]"
                                                            : waypoints) +
         ", mode: back_and_forth, speed_m_s: " + std::to_string(speed_m_s) + ", start_s: " + std::to_string(start_s) +
         "}\nrobot:\n  model: builtin:biped\n  path: {waypoints_m: [[0, 0], " + goal + "]}\n"
         "sensors:\n  - {name: s, type: ideal, link: left_tibia}\n";
}

TEST(MovingObjects, APersonCrossingWhereTheRobotStandsWaitsAndNeverCollides) {
  for (const double cross_x_m : {0.45, 0.6, 0.75, 0.9}) {
    for (const double start_s : {0.0, 1.5}) {
      Simulation sim(LoadScenarioText(PersonScenario(cross_x_m, start_s, "[0.6, 0]", 1.0, ""), "person.yaml"), 1);
      while (!sim.done()) sim.Step();
      const std::string what = "crossing x = " + std::to_string(cross_x_m) + " from t = " + std::to_string(start_s);
      EXPECT_TRUE(sim.robot_outcome().collisions.empty()) << what << ": " << sim.robot_outcome().collisions.front().object;
      EXPECT_EQ(sim.outcome().name(), "reached_goal") << what;
      // the person came up to the robot and waited: it is still on the crossing's first half
      EXPECT_LT(sim.robot_outcome().min_clearance_m, 1.0) << what;
    }
  }
}

// A strategy that stops the robot at a given time, whatever it sees.
class StopsAtTime : public Strategy {
 public:
  explicit StopsAtTime(double t_s) : t_s_(t_s) {}
  std::string name() const override { return "stops_at_time"; }
  void Reset(const StrategySetup&) override { stopped_ = false; }
  void Decide(const Observation& observation, RobotCommands& robot, EventLog&) override {
    if (!stopped_ && observation.t_s >= t_s_) {
      robot.Stop();
      stopped_ = true;
    }
  }

 private:
  double t_s_;
  bool stopped_ = false;
};

TEST(MovingObjects, APersonComingAtARobotThatIsStoppingWaitsAndNeverCollides) {
  // a person walks down the path at the robot; the robot is stopped while
  // the person is still 1.0-1.6 m ahead of its pelvis, its last step then
  // under way: the person waits as for a robot standing still (the person
  // is 4 m out at t = 0 and closes at its speed plus the robot's 0.5 m/s)
  int reached_before_standing = 0;
  for (const double speed_m_s : {1.0, 1.4}) {
    for (const double gap_m : {1.0, 1.3, 1.6}) {
      const double stop_t_s = (4.0 - gap_m) / (speed_m_s + 0.5);
      Simulation sim(LoadScenarioText(PersonScenario(0, 0, "[6, 0]", speed_m_s, "[[4, 0], [-4, 0]]"), "person.yaml"), 1,
                     nullptr, std::make_unique<StopsAtTime>(stop_t_s));
      double standing_t_s = -1;
      while (!sim.done()) {
        sim.Step();
        if (standing_t_s < 0 && sim.robot_outcome().stopped) standing_t_s = sim.observation().t_s;
      }
      const std::string what = "at " + std::to_string(speed_m_s) + " m/s, stopped " + std::to_string(gap_m) + " m apart";
      EXPECT_TRUE(sim.robot_outcome().collisions.empty()) << what << ": " << sim.robot_outcome().collisions.front().object;
      EXPECT_EQ(sim.outcome().name(), "stopped") << what;
      // the robot was still stepping 0.2 s after its stop: a rule for robots standing still would not have held the person then
      reached_before_standing += standing_t_s > stop_t_s + 0.2;
    }
  }
  EXPECT_GT(reached_before_standing, 0);
}

TEST(MovingObjects, ARobotWalkingIntoAPersonCollides) {
  // a person lingering across the path 1.5 m ahead; the robot walks on blind
  Simulation sim(LoadScenarioText(PersonScenario(0, 0, "[3, 0]", 0.1, "[[1.5, -0.2], [1.5, 0.2]]"), "person.yaml"),
                 1);
  while (!sim.done()) sim.Step();
  ASSERT_FALSE(sim.robot_outcome().collisions.empty());
  EXPECT_EQ(sim.robot_outcome().collisions.front().object.rfind("walker", 0), 0u)
      << sim.robot_outcome().collisions.front().object;
  EXPECT_EQ(sim.outcome().name(), "collided");
}

// --- bad input -------------------------------------------------------------

TEST(MovingObjects, BadInputNamesTheFault) {
  EXPECT_NE(ErrorText(FixedSensorScenario("    - {name: f, plane: {}, ground: true, motion: {velocity_m_s: [1, 0, 0]}}\n"))
                .find("objects[0].ground: a moving object cannot be ground"),
            std::string::npos);
  EXPECT_NE(ErrorText(FixedSensorScenario("    - {name: p, person: {}, ground: true}\n")).find("a person cannot be ground"),
            std::string::npos);
  EXPECT_NE(ErrorText(FixedSensorScenario("    - {name: p, person: {height_m: 4}}\n")).find("height_m"),
            std::string::npos);
  EXPECT_NE(ErrorText(FixedSensorScenario("    - {name: b, sphere: {radius_m: 1}, motion: {waypoints_m: [[0, 0], [0, 0]]}}\n"))
                .find("waypoints 0 and 1 are the same point"),
            std::string::npos);
  EXPECT_NE(ErrorText(FixedSensorScenario("    - {name: b, sphere: {radius_m: 1}, motion: {waypoints_m: [[0, 0], [1, 0]], mode: lop}}\n"))
                .find("unknown mode 'lop' (did you mean 'loop'?"),
            std::string::npos);
  EXPECT_NE(ErrorText(FixedSensorScenario("    - {name: b, sphere: {radius_m: 1}, motion: {velocity_m_s: [1, 0, 0], speed_m_s: 2}}\n"))
                .find("speed_m_s is for waypoints_m only"),
            std::string::npos);
  // a trajectory whose times do not increase
  const auto dir = std::filesystem::temp_directory_path() / "proxsim_moving_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "back.csv") << "t_s,x_m,y_m,z_m,yaw_deg\n0,0,0,0,0\n1,1,0,0,0\n1,2,0,0,0\n";
  const std::string back = (dir / "back.csv").string();
  EXPECT_NE(ErrorText(FixedSensorScenario("    - {name: b, sphere: {radius_m: 1}, motion: {trajectory: " + back + "}}\n"))
                .find("back.csv:4: t_s 1 is not after the previous row's; times must strictly increase"),
            std::string::npos);
  std::ofstream(dir / "cols.csv") << "t_s,x_m,y_m,z_m\n0,0,0,0\n";
  EXPECT_NE(ErrorText(FixedSensorScenario("    - {name: b, sphere: {radius_m: 1}, motion: {trajectory: " +
                                          (dir / "cols.csv").string() + "}}\n"))
                .find("missing column 'yaw_deg'"),
            std::string::npos);
}

}  // namespace
}  // namespace proxsim
