// Xacro robots (robot/xacro_expand.h), through the CLI: a biped written with
// xacro's macros and properties (tests/data/xacro/biped.urdf.xacro) is
// expanded by PyPI's xacro and read as the URDF it prints — inspect finds its
// legs (the built-in biped's names, from the macro) and a scenario walks it;
// a xacro file xacro itself refuses (an undefined property) is exit 2 with
// xacro's own message, naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_helpers.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::FreshDir;
using testing::ReadFile;
using testing::RunProxsim;

const std::string kXacro = std::string(PROXSIM_TEST_DATA_DIR) + "/xacro/biped.urdf.xacro";

TEST(XacroTest, InspectFindsTheLegsTheMacroWrote) {
  const auto result = RunProxsim("inspect " + kXacro + " --json");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const nlohmann::json report = nlohmann::json::parse(result.output);
  EXPECT_EQ(report["robot"]["name"], "xacro_biped");
  EXPECT_EQ(report["links"].size(), 7u);
  EXPECT_TRUE(report["legs_accepted"].get<bool>()) << report["legs_problems"].dump();
  EXPECT_EQ(report["legs"]["left"]["knee"], "left_knee_pitch");
  EXPECT_EQ(report["legs"]["right"]["foot"], "right_foot");
  // the properties were evaluated: the thigh's cylinder hangs 0.45 m
  for (const auto& link : report["links"]) {
    if (link["name"] == "left_thigh") EXPECT_NEAR(link["box_world_m"]["min"][2].get<double>(), -0.45, 1e-9);
  }
}

TEST(XacroTest, AScenarioWalksIt) {
  const fs::path dir = FreshDir("xacro_walk");
  fs::create_directories(dir);
  std::ofstream(dir / "walk.yaml") << "proxsim: 1\nduration_s: 4\nrate_hz: 50\nscene: {builtin: dining_room}\n"
                                   << "robot:\n  model: " << kXacro << "\n  path: {waypoints_m: [[0, 0], [1.5, 0]]}\n"
                                   << "sensors:\n  - {name: shin, type: laser, link: left_tibia, pose: {xyz_m: [0.05, 0, -0.2]}}\n";
  const auto result = RunProxsim("run " + (dir / "walk.yaml").string() + " --no-report --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const nlohmann::json summary = nlohmann::json::parse(ReadFile(dir / "out" / "summary.json"));
  EXPECT_GT(summary["robot"]["distance_walked_m"].get<double>(), 1.0) << summary["robot"].dump();
  EXPECT_EQ(summary["robot"]["collisions"].size(), 0u) << summary["robot"].dump();
  fs::remove_all(dir);
}

TEST(XacroTest, XacrosOwnRefusalIsNamed) {
  const fs::path dir = FreshDir("xacro_bad");
  fs::create_directories(dir);
  std::ofstream(dir / "bad.urdf.xacro")
      << "<robot name=\"bad\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n"
      << "  <link name=\"base\"><visual><geometry><box size=\"${undefined_width} 1 1\"/></geometry></visual></link>\n"
      << "</robot>\n";
  const auto result = RunProxsim("inspect " + (dir / "bad.urdf.xacro").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("bad.urdf.xacro: `"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("failed"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("undefined_width"), std::string::npos) << result.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace proxsim
