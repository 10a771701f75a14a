// The feet are the links `robot.legs` names, whatever they are called: the
// built-in biped with its feet renamed left_sole and right_ankle_link (the
// test renames them in the biped's own URDF) walks, sample for sample, as
// the built-in biped does when its legs say so, and is refused when they do
// not (the default map's left_foot is not in it).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_helpers.h"
#include "core/embedded_files.h"
#include "input_error_helpers.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;

// Every `"from"` (a quoted name) in `text` replaced by `"to"`.
std::string Rename(std::string text, const std::string& from, const std::string& to) {
  const std::string quoted_from = "\"" + from + "\"", quoted_to = "\"" + to + "\"";
  for (std::size_t at = text.find(quoted_from); at != std::string::npos; at = text.find(quoted_from, at))
    text.replace(at, quoted_from.size(), quoted_to);
  return text;
}

// The built-in biped's URDF with no "foot" in its feet's names, written into `dir`.
fs::path WriteRenamedBiped(const fs::path& dir) {
  std::string urdf(EmbeddedFiles().at("data/robots/biped.urdf"));
  urdf = Rename(Rename(urdf, "left_foot", "left_sole"), "right_foot", "right_ankle_link");
  fs::create_directories(dir);
  const fs::path path = dir / "soles.urdf";
  std::ofstream(path) << urdf;
  return path;
}

// Two seconds in the dining room toward the obstacle, a sensor on each foot
// (named by `left_foot`, `right_foot`) looking ahead; `robot_keys` completes the robot section.
Scenario Walk(const std::string& robot_keys, const std::string& left_foot, const std::string& right_foot) {
  return LoadScenarioText(
      "proxsim: 1\nduration_s: 2\nrate_hz: 50\nscene: {builtin: dining_room}\n"
      "robot:\n" + robot_keys + "  path: {waypoints_m: [[0, 0], [4, 0]]}\n"
      "sensors:\n"
      "  - {name: l, type: ultrasonic, link: " + left_foot + ", pose: {xyz_m: [0.15, 0, 0], rpy_deg: [0, 5, 0]}}\n"
      "  - {name: r, type: laser, link: " + right_foot + ", pose: {xyz_m: [0.15, 0, 0], rpy_deg: [0, 5, 0]}}\n",
      "walk.yaml");
}

class FeetFromLegsTest : public ::testing::Test {
 protected:
  void SetUp() override { urdf_ = WriteRenamedBiped(testing::FreshDir("feet_from_legs")); }
  void TearDown() override { fs::remove_all(urdf_.parent_path()); }
  fs::path urdf_;
};

TEST_F(FeetFromLegsTest, FeetNamedByTheLegsWalkAsTheBuiltinBipedsFeet) {
  Simulation builtin(Walk("  model: builtin:biped\n", "left_foot", "right_foot"));
  Simulation renamed(Walk("  model: " + urdf_.string() + "\n" +
                              "  legs:\n"
                              "    left: {hip: left_hip_pitch, knee: left_knee_pitch, ankle: left_ankle_pitch, "
                              "foot: left_sole}\n"
                              "    right: {hip: right_hip_pitch, knee: right_knee_pitch, ankle: right_ankle_pitch, "
                              "foot: right_ankle_link}\n",
                          "left_sole", "right_ankle_link"));
  ASSERT_EQ(builtin.sample_count(), renamed.sample_count());
  bool saw_the_floor = false;
  while (!builtin.done()) {
    builtin.Step();
    renamed.Step();
    const std::int64_t k = builtin.samples_taken();
    // every link where the built-in biped's is, to the bit
    ASSERT_EQ(builtin.robot()->X_WL().size(), renamed.robot()->X_WL().size());
    for (std::size_t link = 0; link < builtin.robot()->X_WL().size(); ++link)
      ASSERT_TRUE(builtin.robot()->X_WL(link).matrix() == renamed.robot()->X_WL(link).matrix()) << "sample " << k;
    // the feet the robot knows of: the renamed links' soles, heels and toes
    const RobotKnowledge& a = *builtin.observation().robot;
    const RobotKnowledge& b = *renamed.observation().robot;
    ASSERT_TRUE(b.has_feet);
    for (int side = 0; side < 2; ++side) {
      EXPECT_EQ(a.feet[side].p_W_sole, b.feet[side].p_W_sole) << "sample " << k;
      EXPECT_EQ(a.feet[side].p_W_heel, b.feet[side].p_W_heel) << "sample " << k;
      EXPECT_EQ(a.feet[side].p_W_toe, b.feet[side].p_W_toe) << "sample " << k;
    }
    EXPECT_EQ(a.ground_z_m, b.ground_z_m);
    EXPECT_EQ(a.p_W_front, b.p_W_front);
    // the sensors on the feet read the same
    for (std::size_t i = 0; i < builtin.frame().sensors.size(); ++i) {
      const SensorSample& x = builtin.frame().sensors[i];
      const SensorSample& y = renamed.frame().sensors[i];
      EXPECT_EQ(x.reading.status, y.reading.status) << "sample " << k << " sensor " << i;
      EXPECT_EQ(x.reading.d_m, y.reading.d_m) << "sample " << k << " sensor " << i;
      EXPECT_EQ(x.object_id, y.object_id) << "sample " << k << " sensor " << i;
      saw_the_floor |= x.object_id >= 0 && builtin.object_name(x.object_id) == "floor";
    }
  }
  EXPECT_EQ(builtin.robot_outcome().min_clearance_m, renamed.robot_outcome().min_clearance_m);
  EXPECT_EQ(builtin.robot_outcome().reached_goal, renamed.robot_outcome().reached_goal);
  EXPECT_TRUE(saw_the_floor);  // the sensors were not blind: the comparison compared readings
}

TEST_F(FeetFromLegsTest, WithoutLegsTheRenamedFeetAreNotFound) {
  const std::string error = testing::ErrorOf([&] {
    Simulation sim(Walk("  model: " + urdf_.string() + "\n", "left_sole", "right_ankle_link"));
  });
  EXPECT_NE(error.find("robot.legs is not given and the robot lacks the built-in biped's left_foot, right_foot"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace proxsim
