// `proxsim generate SCENARIO --out WORLD` into another folder (docs/worlds.md):
// the scenario's relative paths (a mesh, a moving object's trajectory) are
// rewritten to name the same files from the written file's folder, and the
// written world runs byte-identical to the inline one.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_helpers.h"
#include "scenario/scenario_paths.h"

namespace proxsim {
namespace {

using testing::FreshDir;
using testing::ReadFile;
using testing::RunProxsim;

TEST(ScenarioPaths, RelativePathsAreRebasedAbsoluteOnesAndTheSameFolderKept) {
  const auto dir = FreshDir("rebase");
  EXPECT_EQ(RebasedPath("meshes/a.obj", dir / "src", dir / "out/deep"), "../../src/meshes/a.obj");
  EXPECT_EQ(RebasedPath("../shared/t.csv", dir / "src/scenarios", dir / "out"), "../src/shared/t.csv");
  EXPECT_EQ(RebasedPath("meshes/a.obj", dir / "src", dir / "src/meshes"), "a.obj");
  EXPECT_EQ(RebasedPath("./meshes/a.obj", dir / "src", dir / "src"), "./meshes/a.obj");  // untouched
  EXPECT_EQ(RebasedPath("/abs/a.obj", dir / "src", dir / "out"), "/abs/a.obj");
  // folders given relative to the working directory: the same answer
  const auto cwd = std::filesystem::current_path();
  EXPECT_EQ(RebasedPath("a.obj", "", "sub"), "../a.obj");
  EXPECT_EQ(RebasedPath("a.obj", "x/y", cwd / "x"), "y/a.obj");
}

TEST(GeneratePaths, AWorldWrittenIntoAnotherFolderFindsItsFilesAndRunsTheSame) {
  const auto dir = FreshDir("generate_paths");
  std::filesystem::create_directories(dir / "src/meshes");
  std::filesystem::create_directories(dir / "src/walks");
  std::filesystem::copy_file(std::filesystem::path(PROXSIM_TEST_DATA_DIR) / "meshes/cube.obj",
                             dir / "src/meshes/cube.obj");
  {
    // a box walking across the robot's way, a mesh crate ahead of it (both 0.8 m high)
    std::ofstream(dir / "src/walks/crossing.csv") << "t_s,x_m,y_m,z_m,yaw_deg\n0,1.0,-1.5,0.4,90\n2.5,1.0,1.5,0.4,90\n";
    std::ofstream(dir / "src/room.yaml")
        << "proxsim: 1\nduration_s: 2.5\nrate_hz: 50\n"
           "scene:\n  generate: {kind: room, seed: 5, difficulty: 0.3, size_m: [6, 6], people: [0, 0]}\n"
           "  objects:\n"
           "    - {name: crate, mesh: {file: meshes/cube.obj, scale: [0.3, 0.8, 0.8]}, pose: {xyz_m: [1.6, 0, 0.4]}}\n"
           "    - {name: walker, box: {size_m: [0.3, 0.3, 0.8]}, motion: {trajectory: walks/crossing.csv}}\n"
           "robot: {model: builtin:biped, on_collision: continue}\n"
           "sensors:\n"
           "  - {name: ideal, type: ideal, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.15]}}\n"
           "  - {name: us, type: ultrasonic, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.15]}}\n"
           "  - {name: laser, type: laser, link: right_tibia, pose: {xyz_m: [0.06, 0, -0.15]}}\n";
  }
  const std::string room = (dir / "src/room.yaml").string(), world = (dir / "out/deep/world.yaml").string();
  std::filesystem::create_directories(dir / "out/deep");
  auto result = RunProxsim("generate " + room + " --out " + world);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const std::string text = ReadFile(world);
  EXPECT_NE(text.find("../../src/meshes/cube.obj"), std::string::npos) << text;
  EXPECT_NE(text.find("../../src/walks/crossing.csv"), std::string::npos) << text;

  for (const auto& [scenario, out] : {std::pair{room, "inline"}, std::pair{world, "written"}}) {
    result = RunProxsim("run " + scenario + " --out " + (dir / out).string() + " --no-report");
    ASSERT_EQ(result.exit_code, 0) << result.output;
  }
  for (const char* file : {"readings.csv", "poses.csv"}) {
    const std::string inline_text = ReadFile(dir / "inline" / file);
    EXPECT_FALSE(inline_text.empty()) << file;
    EXPECT_EQ(inline_text, ReadFile(dir / "written" / file)) << file;
  }
  // the crate and the walker are seen (the files are found, not only accepted)
  const std::string readings = ReadFile(dir / "inline/readings.csv");
  EXPECT_NE(readings.find("crate"), std::string::npos);
  EXPECT_NE(readings.find("walker"), std::string::npos);
}

}  // namespace
}  // namespace proxsim
