// Every class of bad input through the real `proxsim` binary: exit
// code 2, one message per problem naming the file (and line), the key and what
// was expected, and no output folder created. The inputs are small files in
// tests/data/bad_input/; the table "Bad input and the message it gets" in
// docs/trust.md quotes the messages these tests check.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_helpers.h"

namespace proxsim {
namespace {

using testing::CommandResult;
using testing::FreshDir;
using testing::RunProxsim;

const std::string kBadDir = std::string(PROXSIM_TEST_DATA_DIR) + "/bad_input";

// Runs `proxsim run FILE --out DIR --no-report` and checks the common
// contract: exit 2, every fragment in the output, the folder not created.
CommandResult ExpectRefused(const std::string& name, const std::string& run_args,
                            const std::vector<std::string>& fragments) {
  const auto out = FreshDir("bad_input_" + name);
  const CommandResult result = RunProxsim("run " + run_args + " --out " + out.string() + " --no-report");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  for (const std::string& fragment : fragments) {
    EXPECT_NE(result.output.find(fragment), std::string::npos) << "missing '" << fragment << "' in:\n"
                                                               << result.output;
  }
  EXPECT_FALSE(std::filesystem::exists(out)) << "the output folder was created for a refused run";
  return result;
}

CommandResult ExpectRefusedFile(const std::string& file, const std::vector<std::string>& fragments) {
  return ExpectRefused(std::filesystem::path(file).stem().string(), kBadDir + "/" + file, fragments);
}

TEST(BadInputTest, NotYaml) { ExpectRefusedFile("not_yaml.yaml", {"not_yaml.yaml:", "not valid YAML"}); }

TEST(BadInputTest, EmptyFile) { ExpectRefusedFile("empty.yaml", {"empty.yaml", "the file is empty", "proxsim: 1"}); }

TEST(BadInputTest, MissingFile) {
  ExpectRefused("missing", kBadDir + "/no_such_scenario.yaml", {"no_such_scenario.yaml", "does not exist"});
}

TEST(BadInputTest, UnknownKeySuggestsTheNearest) {
  ExpectRefusedFile("unknown_key.yaml", {"unknown_key.yaml:2:", "duraton_s", "duration_s"});
}

TEST(BadInputTest, WrongType) { ExpectRefusedFile("wrong_type.yaml", {"wrong_type.yaml:2:", "rate_hz", "fast"}); }

TEST(BadInputTest, NanAndInfinityAnywhere) {
  const auto result = ExpectRefusedFile("non_finite.yaml", {"non_finite.yaml:2:", "duration_s", "non_finite.yaml:6:",
                                                             "size_m"});
  EXPECT_NE(result.output.find("2 problems"), std::string::npos) << result.output;
}

TEST(BadInputTest, ZeroAndNegativeRatesDurationsSizesRadii) {
  const auto result = ExpectRefusedFile(
      "non_positive.yaml", {"non_positive.yaml:2:", "duration_s", "non_positive.yaml:3:", "rate_hz",
                            "non_positive.yaml:7:", "size_m", "non_positive.yaml:9:", "radius_m"});
  EXPECT_NE(result.output.find("4 problems"), std::string::npos) << result.output;
}

TEST(BadInputTest, SensorValuesAllAtOnce) {
  // inverted and negative range_m, max_incidence_deg beyond 90, negative sigma, unknown type
  const auto result = ExpectRefusedFile(
      "sensor_values.yaml", {"sensor_values.yaml:5:", "range_m", "sensor_values.yaml:8:", "sensor_values.yaml:11:",
                             "max_incidence_deg", "sensor_values.yaml:14:", "sigma", "sensor_values.yaml:16:",
                             "sonar", "ultrasonic"});
  EXPECT_NE(result.output.find("5 problems"), std::string::npos) << result.output;
}

TEST(BadInputTest, UnknownLink) {
  ExpectRefusedFile("unknown_link.yaml", {"unknown_link.yaml:7:", "sensors.us.link", "unknown link 'left_tibiaa'",
                                          "did you mean 'left_tibia'?", "expected world or one of"});
  // validate finds it too, without running
  const CommandResult result = RunProxsim("validate " + kBadDir + "/unknown_link.yaml");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("unknown link 'left_tibiaa'"), std::string::npos) << result.output;
}

TEST(BadInputTest, GroundThatIsNotTrueOrFalse) {
  ExpectRefusedFile("bad_ground.yaml", {"bad_ground.yaml:6:", "scene.objects[0].ground", "expected true or false",
                                        "got yes please"});
}

TEST(BadInputTest, MissingMesh) { ExpectRefusedFile("missing_mesh.yaml", {"missing_mesh.yaml:5:", "no_such_mesh.obj"}); }

TEST(BadInputTest, MeshWithoutTriangles) {
  ExpectRefusedFile("mesh_no_triangles.yaml", {"lines_only.obj", "no triangles"});
}

TEST(BadInputTest, MeshWithNonFiniteVertices) {
  ExpectRefusedFile("mesh_non_finite.yaml", {"non_finite.obj", "not finite"});
}

TEST(BadInputTest, BrokenUrdf) { ExpectRefusedFile("broken_urdf.yaml", {"broken.urdf", "could not parse the URDF"}); }

TEST(BadInputTest, UrdfWhoseJointsFormACycle) {
  ExpectRefusedFile("cycle_urdf.yaml", {"planar_cycle.urdf", "cycle"});
}

TEST(BadInputTest, UrdfWithAMissingLink) {
  ExpectRefusedFile("missing_link_urdf.yaml", {"missing_link.urdf", "thigh"});
}

TEST(BadInputTest, RobotMeshNotFound) {
  ExpectRefusedFile("missing_robot_mesh.yaml",
                    {"missing_robot_mesh.urdf: link 'pelvis' (visual): mesh 'package://no_such_package/meshes/pelvis.stl' "
                     "not found: package 'no_such_package' not found; searched robot.package_paths: ",
                     "ROS_PACKAGE_PATH: ", "the URDF's folder and its ancestors: "});
}

TEST(BadInputTest, MissingPackagesOneLineEach) {
  // four meshes of two packages that are nowhere: one line per package, not per mesh
  const auto result = ExpectRefusedFile(
      "missing_packages.yaml",
      {"missing_packages.urdf: link 'pelvis' (visual): mesh 'package://gone_robot/meshes/pelvis.stl' not found: "
       "package 'gone_robot' not found; searched robot.package_paths: ",
       "(and 2 other meshes of package 'gone_robot')",
       "mesh 'package://gone_hands/meshes/hand.stl' not found: package 'gone_hands' not found; searched",
       "the URDF's folder and its ancestors: "});
  EXPECT_NE(result.output.find("2 problems in the input"), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("thigh.stl"), std::string::npos) << "a line per mesh:\n" << result.output;
}

TEST(BadInputTest, StartOnABoxUnderTheFeet) {
  // feet stand only on ground: the robot would start with its feet in the crate, refused naming it and the links
  ExpectRefusedFile("start_on_crate.yaml",
                    {"start_on_crate.yaml: robot.start: the robot starts inside object 'crate': links ",
                     "'left_foot'", "'right_foot'", "`on: crate`"});
  const CommandResult validate = RunProxsim("validate " + kBadDir + "/start_on_crate.yaml");
  EXPECT_EQ(validate.exit_code, 2) << validate.output;
  EXPECT_NE(validate.output.find("inside object 'crate'"), std::string::npos) << validate.output;
}

TEST(BadInputTest, StartAtTheTable) {
  // under the table: its top cuts the thighs
  ExpectRefusedFile("start_at_table.yaml",
                    {"start_at_table.yaml: robot.start: the robot starts inside object 'table_top': links ",
                     "'left_thigh'", "'right_thigh'"});
}

TEST(BadInputTest, StartInsideAColumn) {
  // nothing to stand on below a start inside the column: the robot's links are in it
  const auto result = ExpectRefusedFile(
      "start_inside_column.yaml",
      {"start_inside_column.yaml: robot.start: the robot starts inside object 'column': links 'pelvis', ",
       "'left_tibia'", "reach into it", "start the robot clear of it"});
  EXPECT_EQ(result.output.find("step down"), std::string::npos) << result.output;
}

TEST(BadInputTest, StartWithALegInAMeshObject) {
  // the cube mesh around the left knee: the left thigh and tibia are named, nothing else
  const auto result = ExpectRefusedFile(
      "start_into_mesh.yaml", {"start_into_mesh.yaml: robot.start: the robot starts inside object 'mesh_crate': "
                               "links 'left_thigh', 'left_tibia' reach into it"});
  EXPECT_EQ(result.output.find("right_"), std::string::npos) << result.output;
}

TEST(BadInputTest, StartOnAnObjectItIsNotAbove) {
  ExpectRefusedFile("start_on_elsewhere.yaml",
                    {"start_on_elsewhere.yaml: robot.start: on: 'crate', but the robot's feet at its start "
                     "(3.000, 0.000) m stand on 'floor'; place the start above 'crate' or leave `on` out"});
}

TEST(BadInputTest, StartOnPurposeRuns) {
  // the crate under the feet, named by robot.start.on: the robot starts on it and steps down (exit 0)
  const auto out = FreshDir("start_on_purpose");
  const CommandResult result = RunProxsim("run " + std::string(PROXSIM_TEST_DATA_DIR) +
                                          "/cli/start_on_crate_on_purpose.yaml --out " + out.string() + " --no-report");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output.find("cannot_step"), std::string::npos) << result.output;
  std::filesystem::remove_all(out);
}

TEST(BadInputTest, StartOnAnUnknownObject) {
  ExpectRefusedFile("start_on_unknown.yaml",
                    {"start_on_unknown.yaml:14: robot.start.on: no object 'crat' in the scene (did you mean 'crate'?)"});
}

TEST(BadInputTest, SensorInsideItsOwnLinkIsAWarning) {
  // the same warning as a sensor inside a scene object; one mounted on its link's
  // surface is not inside (but, facing straight out of it, its ray meets that
  // surface at 0 mm: every reading `self`, which the end of the run says)
  const auto out = FreshDir("bad_input_inside_link");
  const CommandResult result =
      RunProxsim("run " + kBadDir + "/sensor_inside_link.yaml --out " + out.string() + " --no-report");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("proxsim: warning: " + kBadDir +
                               "/sensor_inside_link.yaml: sensor 'swallowed' is inside its own link 'left_tibia'"),
            std::string::npos)
      << result.output;
  EXPECT_EQ(result.output.find("sensor 'mounted' is inside"), std::string::npos) << result.output;
  // (its distance is a ray cast's, not compared: Embree's code path differs by CPU)
  EXPECT_NE(result.output.find("sensor 'mounted' saw only the robot's own body: all 1 of its readings were `self`, the "
                               "nearest 'right_tibia' at"),
            std::string::npos)
      << result.output;
  EXPECT_NE(testing::ReadFile(out / "summary.json").find("is inside its own link 'left_tibia'"), std::string::npos);
}

TEST(BadInputTest, LegMapThatDoesNotFitTheRobot) {
  ExpectRefusedFile(
      "bad_legs.yaml", {"builtin:biped: robot.joints_deg.neck_joint: the joint is not revolute",
                        "builtin:biped: robot.legs.left.hip: no joint 'left_hip_pich' in the URDF (did you mean 'left_hip_pitch'?)",
                        "builtin:biped: robot.legs.right.knee: joint 'left_knee_pitch' is not on the chain from the root "
                        "link to the foot 'right_foot'"});
}

// A gait beyond the legs' URDF limits on level ground: the joint, the speed
// or angle needed and the limit, from `validate` as from `run`.
TEST(BadInputTest, GaitBeyondTheJointLimits) {
  ExpectRefusedFile("gait_too_fast.yaml",
                    {"builtin:biped: gait: stride_m 0.60 m at period_s 0.300 s cannot be walked on level ground within "
                     "the URDF's joint limits", "joint 'right_knee_pitch' needs ", "beyond its velocity limit 12.00 rad/s"});
  ExpectRefusedFile("gait_beyond_limits.yaml",
                    {"builtin:biped: gait: stride_m 3.00 m", "joint '", " needs ", "beyond its"});
  const CommandResult validate = RunProxsim("validate " + kBadDir + "/gait_too_fast.yaml");
  EXPECT_EQ(validate.exit_code, 2) << validate.output;
  EXPECT_NE(validate.output.find("joint 'right_knee_pitch' needs "), std::string::npos) << validate.output;
}

TEST(BadInputTest, TrajectoryWithMissingColumns) {
  const auto result = ExpectRefusedFile("trajectory_missing_columns.yaml",
                                        {"missing_columns.csv:1:", "missing column 'z_m'", "'roll_deg'", "'pitch_deg'"});
  EXPECT_NE(result.output.find("3 problems"), std::string::npos) << result.output;
}

TEST(BadInputTest, TrajectoryWithTimeGoingBackwards) {
  ExpectRefusedFile("trajectory_time_backwards.yaml", {"time_backwards.csv:4:", "t_s"});
}

TEST(BadInputTest, AbsurdRate) {
  ExpectRefusedFile("absurd_rate.yaml", {"absurd_rate.yaml:2: rate_hz:", "too large", "1e+301 samples",
                                         "at most 50 GB"});
}

TEST(BadInputTest, RunThatWouldWriteTerabytesGivesTheEstimate) {
  // 604800 s × 10 kHz × 8 sensors × 300 B
  ExpectRefusedFile("terabytes.yaml", {"terabytes.yaml:3:", "duration_s", "6.05e+09 samples of 8 sensor(s)",
                                       "about 1.45e+04 GB", "at most 50 GB"});
}

TEST(BadInputTest, CommandLine) {
  ExpectRefused("threads_zero", "--threads 0", {"--threads"});
  ExpectRefused("seed_text", "--seed abc", {"--seed"});
  ExpectRefused("unknown_option", "--speed", {"not expected: --speed"});
  ExpectRefused("format", "--format xml", {"--format", "xml"});
}

TEST(BadInputTest, ValidateListsTheSameProblems) {
  const CommandResult result = RunProxsim("validate " + kBadDir + "/sensor_values.yaml");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("5 problems"), std::string::npos) << result.output;
}

TEST(BadInputTest, SensorInsideAnObjectIsAWarningNotAnError) {
  const auto out = FreshDir("bad_input_inside");
  const CommandResult result =
      RunProxsim("run " + kBadDir + "/sensor_inside_object.yaml --out " + out.string() + " --no-report");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("warning: "), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("sensor 'buried' is inside object 'crate'"), std::string::npos) << result.output;
  EXPECT_TRUE(std::filesystem::exists(out / "readings.csv"));
  EXPECT_NE(testing::ReadFile(out / "summary.json").find("is inside object 'crate'"), std::string::npos);
}

TEST(BadInputTest, SensorOnASurfaceIsAWarning) {
  const auto out = FreshDir("bad_input_on_surface");
  const CommandResult result =
      RunProxsim("run " + kBadDir + "/sensor_on_surface.yaml --out " + out.string() + " --no-report");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("warning: "), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("sensor 'flush' starts on the surface of object 'crate'"), std::string::npos)
      << result.output;
}

TEST(BadInputTest, SensorOutsideObjectsGetsNoWarning) {
  const auto out = FreshDir("bad_input_clean");
  const CommandResult result = RunProxsim("run " + std::string(PROXSIM_TEST_DATA_DIR) +
                                          "/cli/world_closed_form.yaml --out " + out.string() + " --no-report");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output.find("warning:"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace proxsim
