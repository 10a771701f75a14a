// Mounting mistakes said by a run (src/run/mounting_warnings.h at its end,
// run_recorder.cc at its start), through the CLI: a sensor turned into its own
// shin, one on its link's surface facing into it, and radians typed into
// rpy_deg; and no such warning for a sensor mounted as the paper mounts it.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_helpers.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadFile;
using testing::RunProxsim;

// The biped walks 2 s in the dining room with one sensor (`link`, `pose`);
// what the run said: its output (stdout and stderr) and summary.json's warnings.
struct Said {
  std::string output;
  std::string warnings;  // summary.json's `warnings`, as JSON text
  bool none = false;     // no warning at all
};
Said RunWithSensor(const std::string& name, const std::string& link, const std::string& pose) {
  const fs::path dir = FreshDir(name);
  fs::create_directories(dir);
  std::ofstream(dir / "scenario.yaml") << "proxsim: 1\nseed: 1\nduration_s: 2\nrate_hz: 50\n"
                                          "scene: {builtin: dining_room}\n"
                                          "robot: {model: builtin:biped}\n"
                                          "sensors:\n  - {name: tof, type: laser, link: " + link + ", pose: " + pose + "}\n";
  const auto run = RunProxsim("run " + (dir / "scenario.yaml").string() + " --no-report --out " + (dir / "out").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  const auto warnings = nlohmann::json::parse(ReadFile(dir / "out" / "summary.json"))["warnings"];
  return {run.output, warnings.dump(), warnings.empty()};
}

TEST(MountingWarnings, ASensorTurnedIntoItsOwnShinIsSaidToSeeOnlyTheRobot) {
  // the paper's tibia point, facing back into the tibia
  const Said said = RunWithSensor("mount_self", "left_tibia", "{xyz_m: [0.06, 0, -0.15], rpy_deg: [0, 0, 180]}");
  EXPECT_NE(said.warnings.find("sensor 'tof' saw only the robot's own body: all 100 of its readings were `self`, the "
                               "nearest 'left_tibia' at"),
            std::string::npos)
      << said.warnings;
  EXPECT_NE(said.output.find("saw only the robot's own body"), std::string::npos) << said.output;
}

TEST(MountingWarnings, ASensorOnItsLinksSurfaceFacingIntoItIsSaidAtTheStart) {
  // the tibia is a cylinder of radius 0.05 m: 0.5 mm proud of it, turned back into it
  const Said in = RunWithSensor("mount_facing_in", "left_tibia", "{xyz_m: [0.0505, 0, -0.2], rpy_deg: [0, 0, 180]}");
  EXPECT_NE(in.warnings.find("sensor 'tof' sits within 2 mm of the surface of its own link 'left_tibia', facing into it"),
            std::string::npos)
      << in.warnings;
  // facing out of it, at the same point: nothing to say
  const Said out = RunWithSensor("mount_facing_out", "left_tibia", "{xyz_m: [0.0505, 0, -0.2], rpy_deg: [0, 8, 0]}");
  EXPECT_TRUE(out.none) << out.warnings;
}

TEST(MountingWarnings, RadiansTypedIntoRpyDegAreSuspectedWhenNothingIsSeen) {
  // the example: the angles of a shin sensor typed in radians, on a world
  // sensor high above the room looking nearly level over it
  const Said said = RunWithSensor("mount_radians", "world", "{xyz_m: [0, 0, 5], rpy_deg: [1.616, 0.168, 1.836]}");
  EXPECT_NE(said.warnings.find("sensor 'tof' detected nothing, and its rpy_deg [1.616, 0.168, 1.836] are all below 2π: "
                               "radians typed as degrees?"),
            std::string::npos)
      << said.warnings;
}

TEST(MountingWarnings, ThePapersTibiaSensorGetsNoWarning) {
  const Said paper = RunWithSensor("mount_paper", "left_tibia", "{xyz_m: [0.06, 0, -0.15], rpy_deg: [0, 8, 0]}");
  EXPECT_TRUE(paper.none) << paper.warnings;
  // nor does a level sensor that sees nothing (its angles are all 0: nothing was typed)
  const Said level = RunWithSensor("mount_level", "world", "{xyz_m: [0, 0, 5], rpy_deg: [0, 0, 0]}");
  EXPECT_TRUE(level.none) << level.warnings;
}

}  // namespace
}  // namespace proxsim
