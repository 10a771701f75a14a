// `proxsim inspect` through the real binary, as a user with their own robot
// would use it: on the built-in biped and on the Unitree H1 (read from
// ../shared/robots/h1_description beside the project; skipped, saying so,
// when it is absent), the leg map it suggests — found by axes and heights,
// not names — is written into a scenario with sensors on the shins at the
// front surface it reports; `proxsim validate` accepts it, and `proxsim run`
// walks the robot forward. Also: a scenario file inspects its robot, a
// missing file is bad input (exit 2), and a sensor inside the H1's shin mesh
// gets the warning a sensor inside its own link gets.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::FreshDir;
using testing::RunProxsim;

const fs::path kH1Urdf =
    fs::path(PROXSIM_SOURCE_DIR) / ".." / "shared" / "robots" / "h1_description" / "urdf" / "h1.urdf";

#define SKIP_WITHOUT_H1_URDF()                                                                              \
  if (!fs::is_regular_file(kH1Urdf))                                                                   \
  GTEST_SKIP() << "skipped: the Unitree H1 is not at " << kH1Urdf.lexically_normal().string()          \
               << " (the H1 tests read ../shared/robots/h1_description from beside the project)"

nlohmann::json InspectJson(const std::string& target) {
  const CommandResult result = RunProxsim("inspect " + target + " --json");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  return nlohmann::json::parse(result.output);
}

std::string Yaml(const nlohmann::json& v) { return v.dump(); }  // JSON is YAML

// A scenario walking `model` with the suggested legs, a sensor at each shin's
// reported front surface (halfway down).
std::string WalkScenario(const std::string& model, const nlohmann::json& inspect) {
  const nlohmann::json& legs = inspect["legs"];
  std::string yaml = "proxsim: 1\nduration_s: 3\nrate_hz: 50\nscene: {builtin: dining_room}\nrobot:\n  model: " + model +
                     "\n  legs:\n";
  for (const char* side : {"left", "right"}) {
    yaml += std::string("    ") + side + ": {hip: " + legs[side]["hip"].get<std::string>() +
            ", knee: " + legs[side]["knee"].get<std::string>() + ", ankle: " + legs[side]["ankle"].get<std::string>() +
            ", foot: " + legs[side]["foot"].get<std::string>() + "}\n";
  }
  yaml += "sensors:\n";
  for (const char* side : {"left", "right"}) {
    const nlohmann::json& shank = inspect["shanks"][side];
    const nlohmann::json& spot = shank["front_surface"][1];  // halfway between knee and ankle
    yaml += std::string("  - {name: shin_") + side + ", type: ideal, link: " + shank["link"].get<std::string>() +
            ", pose: {xyz_m: " + Yaml(spot["xyz_m"]) + ", rpy_deg: " + Yaml(spot["rpy_deg"]) + "}}\n";
  }
  return yaml;
}

// The pelvis (the root link) x at the first and last sample of poses.csv.
std::pair<double, double> PelvisTravel(const fs::path& poses, const std::string& root) {
  const auto csv = testing::ReadCsv(poses);
  double first = 0, last = 0;
  bool seen = false;
  for (const auto& row : csv.rows) {
    if (row.at("link") != root) continue;
    const double x = std::stod(row.at("x"));
    if (!seen) first = x;
    seen = true;
    last = x;
  }
  EXPECT_TRUE(seen) << "no row of link " << root;
  return {first, last};
}

// Writes the scenario, validates it, runs it, and checks the robot walked forward without
// a warning about a sensor inside, on or seeing only its own link.
void ExpectWalks(const std::string& name, const std::string& yaml, const std::string& root) {
  const fs::path dir = FreshDir("inspect_" + name);
  fs::create_directories(dir);
  const fs::path scenario = dir / "walk.yaml";
  std::ofstream(scenario) << yaml;
  const CommandResult validate = RunProxsim("validate " + scenario.string());
  EXPECT_EQ(validate.exit_code, 0) << yaml << "\n" << validate.output;
  const CommandResult run = RunProxsim("run " + scenario.string() + " --out " + (dir / "out").string() + " --no-report");
  ASSERT_EQ(run.exit_code, 0) << yaml << "\n" << run.output;
  EXPECT_EQ(run.output.find("inside its own link"), std::string::npos) << run.output;
  // nor any other mounting warning: the suggested points stand off the shin, facing out of it
  EXPECT_EQ(run.output.find("of its own link"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("saw only the robot's own body"), std::string::npos) << run.output;
  const auto [x0, x1] = PelvisTravel(dir / "out" / "poses.csv", root);
  // 3 s of walking at about 0.5 m/s: well over 0.5 m whatever the legs' stride
  EXPECT_GT(x1 - x0, 0.5) << "the pelvis went from x = " << x0 << " to " << x1;
  fs::remove_all(dir);
}

TEST(InspectTest, BuiltinBipedListsItsLinksJointsAndLegs) {
  const nlohmann::json inspect = InspectJson("builtin:biped");
  EXPECT_EQ(inspect["proxsim_inspect"], 1);
  EXPECT_EQ(inspect["links"][0]["name"], "pelvis");
  EXPECT_EQ(inspect["links"].size(), 9u);
  // the tibia: a cylinder of radius 0.05 m and length 0.45 m hanging from the knee
  // (bounds from outline points in double: 1e-9 m is far above their rounding)
  for (const auto& link : inspect["links"]) {
    if (link["name"] != "left_tibia") continue;
    EXPECT_EQ(link["geometry"][0], "cylinder");
    EXPECT_NEAR(link["box_link_m"]["max"][0].get<double>(), 0.05, 1e-9);
    EXPECT_NEAR(link["box_link_m"]["min"][2].get<double>(), -0.45, 1e-9);
    EXPECT_NEAR(link["mass_kg"].get<double>(), 5.0, 1e-12);
  }
  bool knee_seen = false;
  for (const auto& joint : inspect["joints"]) {
    if (joint["name"] != "left_knee_pitch") continue;
    knee_seen = true;
    EXPECT_EQ(joint["type"], "revolute");
    EXPECT_EQ(joint["limits"]["upper"], 2.4);
    EXPECT_EQ(joint["limits"]["effort"], 300);
    EXPECT_EQ(joint["limits"]["velocity"], 12);  // the knee's top speed since joint-limits (docs/robots.md)
  }
  EXPECT_TRUE(knee_seen);
  // the legs, found by axes and heights: the built-in map
  EXPECT_TRUE(inspect["legs_accepted"].get<bool>()) << inspect["legs_problems"].dump();
  EXPECT_EQ(inspect["legs"]["left"], (nlohmann::json{{"hip", "left_hip_pitch"}, {"knee", "left_knee_pitch"},
                                                     {"ankle", "left_ankle_pitch"}, {"foot", "left_foot"},
                                                     {"ankle_zero_deg", 0.0}}));
  EXPECT_EQ(inspect["legs"]["right"]["knee"], "right_knee_pitch");
  EXPECT_EQ(inspect["feet_candidates"].size(), 2u);
  // the shank's front: the cylinder's surface, 0.05 m ahead of its axis, at every height
  EXPECT_EQ(inspect["shanks"]["left"]["link"], "left_tibia");
  ASSERT_EQ(inspect["shanks"]["left"]["front_surface"].size(), 3u);
  for (const auto& spot : inspect["shanks"]["left"]["front_surface"]) {
    // closed form in double, no ray caster: the tibia's radius, 5 mm proud of it
    EXPECT_NEAR(spot["xyz_m"][0].get<double>(), 0.05 + 0.005, 1e-9);
    // the pitched-down frame: +x turned 15° down about y (a level link at the zero pose)
    EXPECT_NEAR(spot["rpy_deg_pitched_down"][1].get<double>(), 15.0, 1e-9);
    EXPECT_NEAR(spot["xyz_m"][2].get<double>(), -0.45 * spot["fraction"].get<double>(), 1e-9);
  }
  ExpectWalks("biped", WalkScenario("builtin:biped", inspect), "pelvis");
}

TEST(InspectTest, TextOutputAndScenarioTarget) {
  // a scenario inspects its robot; the text names the sections a person reads
  const CommandResult text =
      RunProxsim("inspect " + std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/paper_dining_room.yaml");
  EXPECT_EQ(text.exit_code, 0) << text.output;
  for (const char* fragment : {"links, in tree order", "joints, in tree order", "feet candidates",
                               "left:  {hip: left_hip_pitch, knee: left_knee_pitch, ankle: left_ankle_pitch, foot: left_foot}",
                               "(read as the gait reads robot.legs: accepted)", "shank front surfaces", "left_tibia"}) {
    EXPECT_NE(text.output.find(fragment), std::string::npos) << "missing '" << fragment << "' in:\n" << text.output;
  }
  const CommandResult missing = RunProxsim("inspect /nonexistent/robot.urdf");
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("/nonexistent/robot.urdf: not found"), std::string::npos)
      << missing.output;
}

TEST(InspectTest, H1LegMapFoundByGeometryWalks) {
  SKIP_WITHOUT_H1_URDF();
  const std::string urdf = kH1Urdf.lexically_normal().string();
  const nlohmann::json inspect = InspectJson(urdf);
  EXPECT_EQ(inspect["links"].size(), 25u);
  EXPECT_TRUE(inspect["legs_accepted"].get<bool>()) << inspect["legs_problems"].dump();
  // the map docs/robots.md gives by hand, found without reading a name
  EXPECT_EQ(inspect["legs"]["left"], (nlohmann::json{{"hip", "left_hip_pitch_joint"}, {"knee", "left_knee_joint"},
                                                     {"ankle", "left_ankle_joint"}, {"foot", "left_ankle_link"},
                                                     {"ankle_zero_deg", 0.0}}));
  EXPECT_EQ(inspect["legs"]["right"]["hip"], "right_hip_pitch_joint");
  EXPECT_EQ(inspect["shanks"]["left"]["link"], "left_knee_link");
  ASSERT_EQ(inspect["shanks"]["left"]["front_surface"].size(), 3u);
  for (const auto& spot : inspect["shanks"]["left"]["front_surface"]) {
    // the shin mesh's front lies a few centimetres ahead of the knee's axis
    const double x_m = spot["xyz_m"][0].get<double>();
    EXPECT_GT(x_m, 0.02);
    EXPECT_LT(x_m, 0.12);
  }
  ExpectWalks("h1", WalkScenario(urdf, inspect), "pelvis");
}

TEST(InspectTest, H1SensorInsideItsShinMeshIsWarned) {
  SKIP_WITHOUT_H1_URDF();
  // halfway down, the H1's shin mesh is a shell from about x = 0 (behind) to
  // the reported front: a sensor at half the front's x is inside the mesh,
  // one at the front is on it (no warning)
  const std::string urdf = kH1Urdf.lexically_normal().string();
  const nlohmann::json inspect = InspectJson(urdf);
  const nlohmann::json& front = inspect["shanks"]["left"]["front_surface"][1]["xyz_m"];
  const double x_m = front[0].get<double>(), z_m = front[2].get<double>();
  const std::string yaml = WalkScenario(urdf, inspect) + "  - {name: buried, type: ideal, link: left_knee_link, pose: {xyz_m: [" +
                           std::to_string(x_m / 2) + ", 0, " + std::to_string(z_m) + "]}}\n";
  const fs::path dir = FreshDir("inspect_h1_inside");
  fs::create_directories(dir);
  std::ofstream(dir / "walk.yaml") << yaml;
  const CommandResult run =
      RunProxsim("run " + (dir / "walk.yaml").string() + " --out " + (dir / "out").string() + " --no-report");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("warning: " + (dir / "walk.yaml").string() +
                            ": sensor 'buried' is inside its own link 'left_knee_link'"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("sensor 'shin_left' is inside"), std::string::npos) << run.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace proxsim
