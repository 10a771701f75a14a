// Tests of the scenario loader (io/scenario.h): a full file parses to the
// values written in it (presets, overrides, degrees to radians, defaults),
// and each class of mistake is reported with the file, the line, the key path
// and what was expected — all mistakes of a file at once. Small scenarios are
// written inline so that the line numbers asserted are visible here; the
// files under tests/data/scenarios/ cover file handling and relative paths.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "core/nearest_key.h"
#include "scenario/scenario.h"

namespace proxsim {
namespace {

const std::string kDataDir = std::string(PROXSIM_TEST_DATA_DIR) + "/scenarios";

// The problems LoadScenarioText reports for `text`; fails the test if it loads.
std::vector<std::string> ProblemsOf(const std::string& text, const std::string& source = "scenario.yaml") {
  try {
    LoadScenarioText(text, source);
  } catch (const InputError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return {};
}

// The same for a file.
std::vector<std::string> FileProblemsOf(const std::string& path) {
  try {
    LoadScenarioFile(path);
  } catch (const InputError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "expected an InputError for " << path;
  return {};
}

// Success when one problem contains every fragment (file:line, key path, expectation …).
::testing::AssertionResult HasProblem(const std::vector<std::string>& problems,
                                      std::initializer_list<std::string> fragments) {
  for (const auto& problem : problems) {
    const bool all = std::all_of(fragments.begin(), fragments.end(),
                                 [&](const std::string& fragment) { return problem.find(fragment) != std::string::npos; });
    if (all) return ::testing::AssertionSuccess();
  }
  auto failure = ::testing::AssertionFailure() << "no problem contains all of:";
  for (const auto& fragment : fragments) failure << " [" << fragment << "]";
  failure << "\nproblems:";
  for (const auto& problem : problems) failure << "\n  " << problem;
  return failure;
}

// A valid scenario header followed by `rest`; line 1 is "proxsim: 1".
std::string WithHeader(const std::string& rest) { return "proxsim: 1\n" + rest; }

// ---------------------------------------------------------------------------
// Valid scenarios

TEST(ScenarioTest, FullFileParsesToTheValuesWrittenInIt) {
  const Scenario scenario = LoadScenarioFile(kDataDir + "/full_valid.yaml");

  // top level
  EXPECT_EQ(scenario.source, kDataDir + "/full_valid.yaml");
  EXPECT_EQ(scenario.schema, 1);
  EXPECT_EQ(scenario.seed, 7u);
  EXPECT_DOUBLE_EQ(scenario.duration_s, 12.5);
  EXPECT_DOUBLE_EQ(scenario.rate_hz, 40.0);
  EXPECT_EQ(scenario.builtin_scene, "empty");

  // objects: the file's five, in order, after the (empty) built-in scene's
  const auto& objects = scenario.scene.objects;
  ASSERT_EQ(objects.size(), MakeBuiltinScene("empty").objects.size() + 5);
  const std::size_t first = objects.size() - 5;
  const SceneObject& obstacle = objects[first];
  EXPECT_EQ(obstacle.name, "obstacle");
  ASSERT_TRUE(std::holds_alternative<Box>(obstacle.shape));
  EXPECT_TRUE(std::get<Box>(obstacle.shape).size_m.isApprox(Vec3(0.2, 0.3, 0.1)));
  EXPECT_TRUE(obstacle.X_WO.translation().isApprox(Vec3(2.0, 0, 0.05)));
  // yaw 90°: the object's x axis is the world's y axis
  EXPECT_TRUE((obstacle.X_WO.linear() * Vec3::UnitX()).isApprox(Vec3::UnitY(), 1e-12));
  EXPECT_DOUBLE_EQ(obstacle.material.albedo, 0.8);
  EXPECT_DOUBLE_EQ(obstacle.material.specular, 0.25);

  const SceneObject& ball = objects[first + 1];
  ASSERT_TRUE(std::holds_alternative<Sphere>(ball.shape));
  EXPECT_DOUBLE_EQ(std::get<Sphere>(ball.shape).radius_m, 0.15);
  EXPECT_TRUE(ball.X_WO.isApprox(Pose::Identity()));  // pose defaults to zeros
  EXPECT_DOUBLE_EQ(ball.material.albedo, 1.0);        // material defaults
  EXPECT_DOUBLE_EQ(ball.material.specular, 0.0);

  const SceneObject& post = objects[first + 2];
  ASSERT_TRUE(std::holds_alternative<Cylinder>(post.shape));
  EXPECT_DOUBLE_EQ(std::get<Cylinder>(post.shape).radius_m, 0.05);
  EXPECT_DOUBLE_EQ(std::get<Cylinder>(post.shape).length_m, 1.2);
  EXPECT_TRUE(post.X_WO.translation().isApprox(Vec3(1, 1, 0.6)));
  EXPECT_TRUE(post.X_WO.linear().isApprox(Rotation::Identity()));  // rpy_deg defaults to zeros

  EXPECT_TRUE(std::holds_alternative<Plane>(objects[first + 3].shape));
  ASSERT_TRUE(std::holds_alternative<Mesh>(objects[first + 4].shape));
  EXPECT_EQ(std::get<Mesh>(objects[first + 4].shape).file, "meshes/tetra.obj");  // as written
  EXPECT_TRUE(std::get<Mesh>(objects[first + 4].shape).scale.isApprox(Vec3(1, 2, 3)));

  // robot
  ASSERT_TRUE(scenario.robot.has_value());
  const RobotConfig& robot = *scenario.robot;
  EXPECT_EQ(robot.model, "builtin:biped");
  EXPECT_TRUE(robot.start_xyz_m.isApprox(Vec3(0.5, -0.5, 0)));
  EXPECT_DOUBLE_EQ(robot.start_yaw_rad, kPi / 2);
  EXPECT_DOUBLE_EQ(robot.gait.stride_m, 0.5);
  EXPECT_DOUBLE_EQ(robot.gait.period_s, 1.0);
  ASSERT_EQ(robot.waypoints_m.size(), 3u);
  EXPECT_TRUE(robot.waypoints_m[2].isApprox(Vec2(4, 2)));
  // stop_distance_m is the shorthand for the stop strategy
  ASSERT_TRUE(robot.strategy.has_value());
  ASSERT_TRUE(std::holds_alternative<StopConfig>(*robot.strategy));
  EXPECT_DOUBLE_EQ(std::get<StopConfig>(*robot.strategy).stop_distance_m, 0.25);
  EXPECT_TRUE(robot.trajectory_file.empty());

  // sensors: the ultrasonic preset untouched, mounted with a 20° pitch
  ASSERT_EQ(scenario.sensors.size(), 4u);
  const SensorConfig& us = scenario.sensors[0];
  EXPECT_EQ(us.name, "us");
  EXPECT_EQ(us.spec.type, SensorType::kUltrasonic);
  EXPECT_DOUBLE_EQ(us.spec.min_range_m, 0.1);
  EXPECT_DOUBLE_EQ(us.spec.max_range_m, 1.0);
  EXPECT_DOUBLE_EQ(us.spec.max_incidence_deg, 15.0);
  EXPECT_DOUBLE_EQ(us.spec.noise.sigma, 0.01);
  EXPECT_EQ(us.link, "left_tibia");
  EXPECT_TRUE(us.see_robot);
  EXPECT_TRUE(us.X_LS.translation().isApprox(Vec3(0.06, 0, -0.15)));
  // pitch 20° about y tips the beam (+x) down: x' = (cos 20°, 0, −sin 20°)
  const double pitch_rad = 20.0 * kPi / 180.0;
  EXPECT_TRUE((us.X_LS.linear() * Vec3::UnitX()).isApprox(Vec3(std::cos(pitch_rad), 0, -std::sin(pitch_rad)), 1e-12));

  // a laser with every preset value overridden
  const SensorConfig& laser = scenario.sensors[1];
  EXPECT_EQ(laser.spec.type, SensorType::kLaser);
  EXPECT_DOUBLE_EQ(laser.spec.min_range_m, 0.05);
  EXPECT_DOUBLE_EQ(laser.spec.max_range_m, 1.5);
  EXPECT_DOUBLE_EQ(laser.spec.max_incidence_deg, 60.0);
  EXPECT_DOUBLE_EQ(laser.spec.noise.sigma, 0.02);
  EXPECT_DOUBLE_EQ(laser.spec.noise.mean, 0.001);
  EXPECT_FALSE(laser.see_robot);

  // defaults: link world, zero pose, the preset of the type
  const SensorConfig& ir = scenario.sensors[2];
  EXPECT_EQ(ir.link, "world");
  EXPECT_TRUE(ir.X_LS.isApprox(Pose::Identity()));
  EXPECT_EQ(ir.spec.type, SensorType::kReflectance);
  EXPECT_DOUBLE_EQ(ir.spec.max_range_m, 1.0);
  EXPECT_DOUBLE_EQ(ir.spec.max_incidence_deg, 90.0);
  EXPECT_EQ(scenario.sensors[3].spec.type, SensorType::kIdeal);
  EXPECT_DOUBLE_EQ(scenario.sensors[3].spec.noise.sigma, 0.0);
}

TEST(ScenarioTest, MinimalFileTakesEveryDefault) {
  const Scenario scenario = LoadScenarioFile(kDataDir + "/minimal.yaml");
  EXPECT_EQ(scenario.seed, 1u);
  EXPECT_DOUBLE_EQ(scenario.duration_s, 10.0);
  EXPECT_DOUBLE_EQ(scenario.rate_hz, 50.0);
  EXPECT_EQ(scenario.builtin_scene, "empty");
  EXPECT_FALSE(scenario.robot.has_value());
  EXPECT_TRUE(scenario.sensors.empty());
  EXPECT_EQ(scenario.SampleCount(), 500);
}

TEST(ScenarioTest, RobotSectionDefaultsWhenEmpty) {
  const Scenario scenario = LoadScenarioText(WithHeader("robot: {}\n"), "scenario.yaml");
  ASSERT_TRUE(scenario.robot.has_value());
  EXPECT_EQ(scenario.robot->model, "builtin:biped");
  EXPECT_DOUBLE_EQ(scenario.robot->gait.stride_m, 0.6);
  EXPECT_DOUBLE_EQ(scenario.robot->gait.period_s, 1.2);
  EXPECT_FALSE(scenario.robot->strategy.has_value());
  EXPECT_TRUE(scenario.robot->waypoints_m.empty());
}

TEST(ScenarioTest, SampleCountCoversTheDurationAtTheRate) {
  Scenario scenario;
  scenario.duration_s = 12.5;
  scenario.rate_hz = 40;
  EXPECT_EQ(scenario.SampleCount(), 500);  // t = 0, 0.025, …, 12.475
  scenario.duration_s = 0.3;                // 0.3 × 10 is 3.0000000000000004 in doubles
  scenario.rate_hz = 10;
  EXPECT_EQ(scenario.SampleCount(), 3);
  scenario.duration_s = 0.01;  // shorter than one period: the sample at t = 0
  scenario.rate_hz = 50;
  EXPECT_EQ(scenario.SampleCount(), 1);
  scenario.duration_s = 0.05;  // 2.5 periods: t = 0, 0.02, 0.04
  EXPECT_EQ(scenario.SampleCount(), 3);
}

TEST(ScenarioTest, MeshPathIsRelativeToTheScenarioFile) {
  // load through a path with a detour, from a different current directory
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  Scenario scenario;
  EXPECT_NO_THROW(scenario = LoadScenarioFile(kDataDir + "/meshes/../full_valid.yaml"));
  std::filesystem::current_path(previous);

  const SceneObject& tetra = scenario.scene.objects.back();
  ASSERT_TRUE(std::holds_alternative<Mesh>(tetra.shape));
  const Mesh& mesh = std::get<Mesh>(tetra.shape);
  ASSERT_NE(mesh.data, nullptr);
  EXPECT_EQ(mesh.data->triangles.size(), 4u);
  // the unit tetrahedron scaled by [1, 2, 3] spans exactly that box
  Vec3 max_O = Vec3::Constant(-1e9);
  Vec3 min_O = Vec3::Constant(1e9);
  for (const Vec3f& vertex : mesh.data->vertices_O) {
    max_O = max_O.cwiseMax(vertex.cast<double>());
    min_O = min_O.cwiseMin(vertex.cast<double>());
  }
  EXPECT_TRUE(max_O.isApprox(Vec3(1, 2, 3), 1e-6));
  EXPECT_TRUE(min_O.isZero(1e-6));
}

TEST(ScenarioTest, TextSourceFolderResolvesRelativePaths) {
  const std::string text = WithHeader(
      "scene:\n"
      "  objects:\n"
      "    - {name: t, mesh: {file: meshes/tetra.obj, scale: 2}}\n"
      "robot: {model: meshes/tetra.obj}\n");
  const Scenario scenario = LoadScenarioText(text, kDataDir + "/inline.yaml");
  const Mesh& mesh = std::get<Mesh>(scenario.scene.objects.back().shape);
  EXPECT_TRUE(mesh.scale.isApprox(Vec3(2, 2, 2)));  // a single number scales every axis
  ASSERT_NE(mesh.data, nullptr);
  // a robot model path is stored resolved against the scenario's folder
  EXPECT_TRUE(std::filesystem::equivalent(scenario.robot->model, kDataDir + "/meshes/tetra.obj"));
}

TEST(ScenarioTest, BuiltinScenariosLoad) {
  const auto names = BuiltinScenarioNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "paper"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "world_demo"), names.end());
  for (const auto& name : names) {
    Scenario scenario;
    ASSERT_NO_THROW(scenario = LoadBuiltinScenario(name)) << name;
    EXPECT_EQ(scenario.source, "builtin:" + name);
    EXPECT_FALSE(scenario.sensors.empty()) << name;
  }
}

TEST(ScenarioTest, UnknownBuiltinScenarioListsTheValidOnes) {
  try {
    LoadBuiltinScenario("papr");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_TRUE(HasProblem(error.problems(), {"builtin:papr", "paper", "world_demo"}));
  }
}

// ---------------------------------------------------------------------------
// Files that are not scenarios

TEST(ScenarioErrorTest, NotYamlNamesTheLineOfTheSyntaxError) {
  const auto problems = FileProblemsOf(kDataDir + "/not_yaml.yaml");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(HasProblem(problems, {"not_yaml.yaml:5:", "not valid YAML"}));
}

TEST(ScenarioErrorTest, EmptyFile) {
  EXPECT_TRUE(HasProblem(FileProblemsOf(kDataDir + "/empty.yaml"), {"empty.yaml", "empty", "proxsim: 1"}));
  EXPECT_TRUE(HasProblem(ProblemsOf(""), {"scenario.yaml", "empty"}));
}

TEST(ScenarioErrorTest, MissingFile) {
  EXPECT_TRUE(HasProblem(FileProblemsOf(kDataDir + "/no_such_file.yaml"), {"no_such_file.yaml", "no such file"}));
  EXPECT_TRUE(HasProblem(FileProblemsOf(kDataDir), {"scenarios", "not a regular file"}));
}

TEST(ScenarioErrorTest, TopLevelMustBeAMap) {
  EXPECT_TRUE(HasProblem(ProblemsOf("- proxsim\n- 1\n"), {"scenario.yaml:1:", "expected a map of scenario keys", "got"}));
  EXPECT_TRUE(HasProblem(ProblemsOf("just words\n"), {"scenario.yaml:1:", "expected a map", "got just words"}));
}

TEST(ScenarioErrorTest, MissingSchemaVersion) {
  EXPECT_TRUE(HasProblem(ProblemsOf("seed: 3\n"), {"scenario.yaml:1:", "proxsim: missing", "proxsim: 1"}));
}

TEST(ScenarioErrorTest, WrongSchemaVersion) {
  const auto problems = ProblemsOf("seed: 3\nproxsim: 2\n");
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:2:", "proxsim:", "expected schema version 1, got 2"}));
  EXPECT_TRUE(HasProblem(ProblemsOf("proxsim: one\n"), {"scenario.yaml:1:", "proxsim:", "whole number", "got one"}));
}

// ---------------------------------------------------------------------------
// Unknown keys, at every level, with the nearest valid key suggested

TEST(ScenarioErrorTest, UnknownTopLevelKeySuggestsTheNearest) {
  EXPECT_TRUE(HasProblem(ProblemsOf(WithHeader("sed: 3\n")),
                         {"scenario.yaml:2:", "sed: unknown key 'sed' (did you mean 'seed'?)"}));
}

TEST(ScenarioErrorTest, UnknownSensorKeySuggestsTheNearest) {
  const auto problems = ProblemsOf(WithHeader(
      "sensors:\n"
      "  - name: a\n"
      "    type: laser\n"
      "    rang_m: [0, 1]\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "sensors[0].rang_m", "unknown key 'rang_m' (did you mean 'range_m'?)"}));
}

TEST(ScenarioErrorTest, UnknownKeysDeepInsideAreFound) {
  const auto problems = ProblemsOf(WithHeader(
      "scene:\n"
      "  objects:\n"
      "    - name: a\n"
      "      box: {sise_m: [1, 1, 1]}\n"
      "      material: {albedo: 0.5, colour: red}\n"
      "robot:\n"
      "  gait: {stride_m: 0.5, perid_s: 1}\n"
      "  start: {xyz_m: [0, 0, 0], yaw_rad: 0}\n"
      "sensors:\n"
      "  - name: s\n"
      "    type: laser\n"
      "    noise: {sigma: 0.1, mu: 0}\n"
      "    pose: {xyz_m: [0, 0, 0], rpy: [0, 0, 0]}\n"
      "    zzzzzzzzzz: 1\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "scene.objects[0].box.sise_m", "did you mean 'size_m'?"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:6:", "scene.objects[0].material.colour", "expected one of albedo, specular"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:8:", "robot.gait.perid_s", "did you mean 'period_s'?"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:9:", "robot.start.yaw_rad", "did you mean 'yaw_deg'?"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:13:", "sensors[0].noise.mu", "unknown key 'mu'"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:14:", "sensors[0].pose.rpy", "did you mean 'rpy_deg'?"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:15:", "sensors[0].zzzzzzzzzz", "expected one of name, type"}));
  // the box, now without size_m, is also reported as missing it
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "scene.objects[0].box.size_m: missing"}));
}

TEST(ScenarioErrorTest, PlaneTakesNoKeys) {
  EXPECT_TRUE(HasProblem(ProblemsOf(WithHeader("scene: {objects: [{name: p, plane: {size_m: 1}}]}\n")),
                         {"scenario.yaml:2:", "scene.objects[0].plane.size_m", "unknown key", "takes no keys"}));
}

TEST(ScenarioErrorTest, DuplicateYamlKey) {
  EXPECT_TRUE(HasProblem(ProblemsOf(WithHeader("seed: 1\nseed: 2\n")), {"scenario.yaml:3:", "seed", "duplicate key 'seed'"}));
}

// ---------------------------------------------------------------------------
// Wrong types and non-finite numbers

TEST(ScenarioErrorTest, StringWhereANumberGoes) {
  const auto problems = ProblemsOf(WithHeader("duration_s: ten\nrate_hz: \"50\"\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:2:", "duration_s:", "expected a finite number > 0 s, got ten"}));
  // a quoted number is text, not a number
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:3:", "rate_hz:", "expected a finite number > 0 Hz, got \"50\""}));
}

TEST(ScenarioErrorTest, MapWhereAListGoes) {
  const auto problems = ProblemsOf(WithHeader(
      "sensors:\n"
      "  name: a\n"
      "  type: laser\n"
      "scene: {objects: {name: b}}\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:3:", "sensors:", "expected a list of sensors, got a map"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "scene.objects:", "expected a list of objects, got a map"}));
}

TEST(ScenarioErrorTest, WrongShapesOfValues) {
  const auto problems = ProblemsOf(WithHeader(
      "seed: 1.5\n"
      "robot: fast\n"
      "sensors:\n"
      "  - name: [a, b]\n"
      "    type: laser\n"
      "    see_robot: maybe\n"
      "    pose: {xyz_m: [1, 2]}\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:2:", "seed:", "expected a whole number >= 0, got 1.5"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:3:", "robot:", "expected a map with keys model, model_scene, geom_group", "got fast"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "sensors[0].name:", "expected a non-empty text, got [a, b]"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:7:", "sensors[0].see_robot:", "expected true or false, got maybe"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:8:", "sensors[0].pose.xyz_m:", "expected [x, y, z] in metres, got [1, 2]"}));
}

TEST(ScenarioErrorTest, NegativeSeed) {
  EXPECT_TRUE(HasProblem(ProblemsOf(WithHeader("seed: -1\n")), {"scenario.yaml:2:", "seed:", "whole number >= 0, got -1"}));
}

TEST(ScenarioErrorTest, NonFiniteNumbersAnywhere) {
  const auto problems = ProblemsOf(WithHeader(
      "duration_s: .inf\n"
      "scene:\n"
      "  objects:\n"
      "    - name: a\n"
      "      sphere: {radius_m: .nan}\n"
      "      pose: {rpy_deg: [0, -.inf, 0]}\n"
      "sensors:\n"
      "  - name: s\n"
      "    type: laser\n"
      "    noise: {mean: .NaN}\n"
      "    max_incidence_deg: .inf\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:2:", "duration_s:", "finite", "got .inf"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:6:", "scene.objects[0].sphere.radius_m:", "finite", "got .nan"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:7:", "scene.objects[0].pose.rpy_deg[1]:", "finite", "got -.inf"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:11:", "sensors[0].noise.mean:", "finite", "got .NaN"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:12:", "sensors[0].max_incidence_deg:", "finite", "got .inf"}));
}

// ---------------------------------------------------------------------------
// Out-of-range values

TEST(ScenarioErrorTest, NonPositiveDurationRateSizesAndGait) {
  const auto problems = ProblemsOf(WithHeader(
      "duration_s: 0\n"
      "rate_hz: -50\n"
      "scene:\n"
      "  objects:\n"
      "    - {name: a, box: {size_m: [1, 0, 1]}}\n"
      "    - {name: b, sphere: {radius_m: 0}}\n"
      "    - {name: c, cylinder: {radius_m: -0.1, length_m: 0}}\n"
      "    - {name: d, mesh: {file: x.obj, scale: 0}}\n"
      "robot:\n"
      "  gait: {stride_m: 0, period_s: -1}\n"
      "  stop_distance_m: -0.1\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:2:", "duration_s:", "expected a finite number > 0 s, got 0"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:3:", "rate_hz:", "expected a finite number > 0 Hz, got -50"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:6:", "scene.objects[0].box.size_m[1]:", "> 0 m, got 0"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:7:", "scene.objects[1].sphere.radius_m:", "> 0 m, got 0"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:8:", "scene.objects[2].cylinder.radius_m:", "> 0 m, got -0.1"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:8:", "scene.objects[2].cylinder.length_m:", "> 0 m, got 0"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:9:", "scene.objects[3].mesh.scale:", "a number > 0", "got 0"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:9:", "scene.objects[3].mesh.file:", "x.obj"}));  // still loaded
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:11:", "robot.gait.stride_m:", "in [0.01, 3] m (a stride a walking robot can take), got 0"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:11:", "robot.gait.period_s:", "in [0.1, 30] s (a gait cycle a walking robot can take), got -1"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:12:", "robot.stop_distance_m:", "> 0 m, got -0.1"}));
}

TEST(ScenarioErrorTest, InvertedRange) {
  const auto problems = ProblemsOf(WithHeader(
      "sensors:\n"
      "  - name: a\n"
      "    type: laser\n"
      "  - name: b\n"
      "    type: ultrasonic\n"
      "    range_m: [1.0, 0.1]\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:7: sensors[1].range_m: expected [min, max] with 0 <= min < max, got [1.0, 0.1]"}));
  EXPECT_EQ(problems.size(), 1u);  // SensorSpec::Validate's own range message is not repeated
}

TEST(ScenarioErrorTest, NegativeOrMalformedRange) {
  const auto problems = ProblemsOf(WithHeader(
      "sensors:\n"
      "  - {name: a, type: laser, range_m: [-0.1, 1]}\n"
      "  - {name: b, type: laser, range_m: [0.5]}\n"
      "  - {name: c, type: laser, range_m: 2}\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:3:", "sensors[0].range_m:", "0 <= min < max, got [-0.1, 1]"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:4:", "sensors[1].range_m:", "expected [min, max] in metres, got [0.5]"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "sensors[2].range_m:", "expected [min, max] in metres, got 2"}));
}

TEST(ScenarioErrorTest, MaxIncidenceOutsideZeroToNinety) {
  const auto problems = ProblemsOf(WithHeader(
      "sensors:\n"
      "  - name: a\n"
      "    type: laser\n"
      "    max_incidence_deg: 95\n"
      "  - {name: b, type: laser, max_incidence_deg: -1}\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "sensors[0].max_incidence_deg:", "[0, 90] degrees, got 95"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:6:", "sensors[1].max_incidence_deg:", "[0, 90] degrees, got -1"}));
}

TEST(ScenarioErrorTest, NegativeSigma) {
  const auto problems = ProblemsOf(WithHeader(
      "sensors:\n"
      "  - name: a\n"
      "    type: laser\n"
      "    noise:\n"
      "      sigma: -0.01\n"
      "    max_incidence_deg: 91\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:6:", "sensors[0].noise.sigma:", "expected", ">= 0, got -0.01"}));
  // locating the sigma problem leaves the document intact for the next one
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:7:", "sensors[0].max_incidence_deg:", "got 91"}));
}

TEST(ScenarioErrorTest, UnknownSensorTypeListsTheValidOnes) {
  const auto problems = ProblemsOf(WithHeader(
      "sensors:\n"
      "  - name: a\n"
      "    type: sonar\n"
      "  - name: b\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:4:", "sensors[0].type:", "unknown sensor type 'sonar'",
                                    "ideal, laser, ultrasonic, reflectance"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "sensors[1].type: missing", "ideal, laser"}));
}

TEST(ScenarioErrorTest, UnknownBuiltinSceneListsTheValidOnes) {
  const auto problems = ProblemsOf(WithHeader("scene:\n  builtin: kitchen\n"));
  std::string fragment = "expected one of ";
  for (const auto& name : BuiltinSceneNames()) fragment += (fragment.back() == ' ' ? "" : ", ") + name;
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:3:", "scene.builtin:", "unknown built-in scene 'kitchen'", fragment}));
}

TEST(ScenarioErrorTest, ObjectNeedsExactlyOneShape) {
  const auto problems = ProblemsOf(WithHeader(
      "scene:\n"
      "  objects:\n"
      "    - name: nothing\n"
      "    - name: both\n"
      "      box: {size_m: [1, 1, 1]}\n"
      "      sphere: {radius_m: 1}\n"
      "    - box: {size_m: [1, 1, 1]}\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:4:", "scene.objects[0]:", "exactly one shape key", "got none"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "scene.objects[1]:", "exactly one shape key", "got box, sphere"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:8:", "scene.objects[2].name: missing"}));
}

TEST(ScenarioErrorTest, MaterialOutsideZeroToOne) {
  const auto problems = ProblemsOf(WithHeader(
      "scene:\n"
      "  objects:\n"
      "    - name: a\n"
      "      plane: {}\n"
      "      material: {albedo: 1.5, specular: -0.2}\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:6:", "scene.objects[0].material.albedo:", "[0, 1], got 1.5"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:6:", "scene.objects[0].material.specular:", "[0, 1], got -0.2"}));
}

// ---------------------------------------------------------------------------
// Names and links

TEST(ScenarioErrorTest, DuplicateObjectAndSensorNames) {
  const auto problems = ProblemsOf(WithHeader(
      "scene:\n"
      "  objects:\n"
      "    - {name: a, plane: {}}\n"
      "    - {name: a, sphere: {radius_m: 1}}\n"
      "sensors:\n"
      "  - {name: s, type: laser}\n"
      "  - {name: s, type: ideal}\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "scene.objects[1].name:", "duplicate object name 'a'", "scene.objects[0]"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:8:", "sensors[1].name:", "duplicate sensor name 's'", "sensors[0]"}));
}

TEST(ScenarioErrorTest, ObjectNameClashingWithTheBuiltinScene) {
  const Scene dining_room = MakeBuiltinScene("dining_room");
  ASSERT_FALSE(dining_room.objects.empty());
  const std::string taken = dining_room.objects.front().name;
  const auto problems = ProblemsOf(WithHeader(
      "scene:\n"
      "  builtin: dining_room\n"
      "  objects:\n"
      "    - {name: " + taken + ", plane: {}}\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:5:", "scene.objects[0].name:", "duplicate object name '" + taken + "'",
                                    "built-in scene 'dining_room'"}));
}

TEST(ScenarioErrorTest, LinkOtherThanWorldNeedsARobot) {
  const auto problems = ProblemsOf(WithHeader(
      "sensors:\n"
      "  - {name: a, type: laser, link: left_tibia}\n"
      "  - {name: b, type: laser, link: \"\"}\n"));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:3:", "sensors[0].link:", "expected 'world' (the scenario has no robot section), got 'left_tibia'"}));
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:4:", "sensors[1].link:", "non-empty"}));
  // with a robot, any link name passes here (the robot loader checks it)
  EXPECT_NO_THROW(LoadScenarioText(WithHeader("robot: {}\nsensors: [{name: a, type: laser, link: left_tibia}]\n"),
                                   "scenario.yaml"));
}

// ---------------------------------------------------------------------------
// Files the scenario points to

TEST(ScenarioErrorTest, MissingMeshFileIsReportedAtItsKey) {
  const auto problems = FileProblemsOf(kDataDir + "/bad_mesh_path.yaml");
  EXPECT_TRUE(HasProblem(problems, {"bad_mesh_path.yaml:6:", "scene.objects[0].mesh.file:", "missing.obj"}));
}

TEST(ScenarioErrorTest, MissingRobotModelAndTrajectory) {
  const auto problems = ProblemsOf(WithHeader(
      "robot:\n"
      "  model: robots/nowhere.urdf\n"
      "  trajectory: walk.csv\n"),
                                   kDataDir + "/inline.yaml");
  EXPECT_TRUE(HasProblem(problems, {"inline.yaml:3:", "robot.model:", "URDF", "nowhere.urdf' is not a file"}));
  EXPECT_TRUE(HasProblem(problems, {"inline.yaml:4:", "robot.trajectory:", "trajectory CSV", "walk.csv' is not a file"}));
}

// ---------------------------------------------------------------------------
// The run as a whole, and many mistakes at once

TEST(ScenarioErrorTest, AbsurdRunSizeIsRefusedWithTheEstimate) {
  const auto problems = ProblemsOf(WithHeader(
      "duration_s: 1000000\n"
      "rate_hz: 1000\n"
      "sensors: [{name: a, type: laser}, {name: b, type: laser}]\n"));
  // 1e9 samples × 2 sensors × 300 B per sensor sample
  EXPECT_TRUE(HasProblem(problems, {"scenario.yaml:2:", "duration_s:", "too large", "1e+09 samples of 2 sensor(s)",
                                    "about 600 GB", "at most 50 GB"}));
  // just under the limit (8e7 samples × 2 × 300 B = 48 GB) passes
  EXPECT_NO_THROW(LoadScenarioText(WithHeader("duration_s: 80000\nrate_hz: 1000\nsensors: [{name: a, type: laser}, "
                                              "{name: b, type: laser}]\n"),
                                   "scenario.yaml"));
}

TEST(ScenarioErrorTest, EveryProblemOfAFileIsReportedAtOnce) {
  const auto problems = FileProblemsOf(kDataDir + "/several_errors.yaml");
  EXPECT_EQ(problems.size(), 5u);
  EXPECT_TRUE(HasProblem(problems, {"several_errors.yaml:3:", "seed:"}));
  EXPECT_TRUE(HasProblem(problems, {"several_errors.yaml:4:", "duration_s:"}));
  EXPECT_TRUE(HasProblem(problems, {"several_errors.yaml:5:", "rate_hz:"}));
  EXPECT_TRUE(HasProblem(problems, {"several_errors.yaml:7:", "scene.builtin:"}));
  EXPECT_TRUE(HasProblem(problems, {"several_errors.yaml:11:", "sensors[0].rang_m:", "did you mean 'range_m'?"}));
}

// ---------------------------------------------------------------------------
// The suggestion itself

TEST(ScenarioNearestKeyTest, EditDistanceCountsSingleCharacterEdits) {
  EXPECT_EQ(EditDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(EditDistance("", "abc"), 3u);
  EXPECT_EQ(EditDistance("range_m", "range_m"), 0u);
  EXPECT_EQ(EditDistance("rang_m", "range_m"), 1u);
}

TEST(ScenarioNearestKeyTest, SuggestsOnlyPlausibleTypos) {
  const std::vector<std::string> keys = {"name", "type", "range_m", "max_incidence_deg"};
  EXPECT_EQ(NearestKey("rang_m", keys), "range_m");
  EXPECT_EQ(NearestKey("max_incidence", keys), "max_incidence_deg");
  EXPECT_EQ(NearestKey("nmae", keys), "name");
  EXPECT_FALSE(NearestKey("colour", keys).has_value());
}

}  // namespace
}  // namespace proxsim

namespace proxsim {
namespace {

// ---------------------------------------------------------------------------
// robot.strategy

TEST(ScenarioStrategyTest, ReadsEachBuiltInStrategyWithItsParameters) {
  const Scenario stop = LoadScenarioText(
      WithHeader("robot:\n  strategy: {name: stop, stop_distance_m: 0.4, corridor_half_width_m: 0.2, max_drop_m: 0.25}\n"),
      "s.yaml");
  ASSERT_TRUE(stop.robot && stop.robot->strategy);
  const auto& s = std::get<StopConfig>(*stop.robot->strategy);
  EXPECT_DOUBLE_EQ(s.stop_distance_m, 0.4);
  EXPECT_DOUBLE_EQ(s.corridor_half_width_m, 0.2);
  EXPECT_DOUBLE_EQ(s.max_drop_m, 0.25);
  EXPECT_DOUBLE_EQ(s.min_height_m, StopConfig{}.min_height_m);
  // without max_drop_m, the legs' gait.max_step_m (0: from the legs)
  EXPECT_EQ(StopConfig{}.max_drop_m, 0.0);
  EXPECT_TRUE(HasProblem(ProblemsOf(WithHeader("robot:\n  strategy: {name: stop, max_drop_m: -1}\n")),
                         {"max_drop_m"}));

  const Scenario circumvent =
      LoadScenarioText(WithHeader("robot:\n  strategy: {name: circumvent, margin_m: 0.2, max_detour_m: 1}\n"), "c.yaml");
  const auto& c = std::get<CircumventConfig>(*circumvent.robot->strategy);
  EXPECT_DOUBLE_EQ(c.margin_m, 0.2);
  EXPECT_DOUBLE_EQ(c.max_detour_m, 1.0);
  EXPECT_DOUBLE_EQ(c.rejoin_m, CircumventConfig{}.rejoin_m);
}

TEST(ScenarioStrategyTest, BadStrategiesAreReportedAllAtOnce) {
  const auto unknown = ProblemsOf(WithHeader("robot:\n  strategy: {name: circumvnet}\n"));
  EXPECT_TRUE(HasProblem(unknown, {"robot.strategy:", "unknown strategy 'circumvnet'", "did you mean 'circumvent'"}));

  const auto both = ProblemsOf(WithHeader("robot:\n  stop_distance_m: 0.5\n  strategy: {name: stop}\n"));
  EXPECT_TRUE(HasProblem(both, {"robot.stop_distance_m:", "not both"}));

  // a key of another strategy, and a bad value, in one message list
  const auto keys = ProblemsOf(WithHeader("robot:\n  strategy: {name: stop, margin_m: 0.1, stop_distance_m: 0}\n"));
  EXPECT_TRUE(HasProblem(keys, {"robot.strategy", "margin_m"}));
  EXPECT_TRUE(HasProblem(keys, {"robot.strategy.stop_distance_m:", "> 0 m, got 0"}));

  const auto nameless = ProblemsOf(WithHeader("robot:\n  strategy: {margin_m: 0.1}\n"));
  EXPECT_TRUE(HasProblem(nameless, {"robot.strategy:", "name: stop or name: circumvent"}));
}

}  // namespace
}  // namespace proxsim
