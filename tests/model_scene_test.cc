// A MuJoCo scene file that includes the robot (MuJoCo Menagerie's
// scene.xml: `<include file="robot.xml"/>`, a floor plane, lights): the robot
// is the world body's one tree, the world body's geoms a scene the model
// offers (robot/mjcf_model.h), which a scenario takes as objects `model:GEOM`
// unless `robot.model_scene: ignore` (scenario_robot.cc). A small scene
// written here, a crate on the floor in the robot's way, runs exactly as the
// robot's own file in a scenario that draws the same floor and crate itself:
// the same link poses, readings (an ideal sensor on the crate's face at its
// closed-form distance) and collision with the crate. Menagerie's own TALOS
// scene (read in place from ../shared/robots/pal_talos; skipped, saying so,
// without it) walks to its goal on its own floor and in the dining room, as
// its robot file does.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_helpers.h"
#include "input_error_helpers.h"
#include "mjcf_twin.h"
#include "robot/mjcf_model.h"
#include "robot/robot_model.h"
#include "scenario/scenario.h"
#include "sim/run_summary.h"

namespace proxsim {
namespace {

namespace fs = std::filesystem;

const fs::path kTalosDir = fs::path(PROXSIM_SOURCE_DIR) / ".." / "shared" / "robots" / "pal_talos";

#define SKIP_WITHOUT_TALOS()                                                                              \
  if (!fs::is_regular_file(kTalosDir / "scene_position.xml"))                                             \
  GTEST_SKIP() << "skipped: MuJoCo Menagerie's TALOS is not at " << kTalosDir.lexically_normal().string() \
               << " (these tests read ../shared/robots/pal_talos from beside the project)"

// The scene file: the robot (tests/mjcf_twin.h: a biped with the built-in
// one's leg names, a mast and a head on its pelvis) included, lights and a camera (not read), the
// floor, a crate 0.2 × 0.3 × 0.2 m on it at x = 1.5 in the robot's way, and an
// unnamed capsule off the path (along y, at x = 0.5, y = 1).
constexpr const char* kSceneTestScene = R"(<mujoco model="scene_biped scene">
  <include file="robot.xml"/>
  <worldbody>
    <light name="sun" pos="0 0 5"/>
    <camera name="side" pos="0 -3 1"/>
    <geom name="floor" type="plane" size="0 0 0.05"/>
    <geom name="crate" type="box" size="0.1 0.15 0.1" pos="1.5 0 0.1"/>
    <geom type="capsule" size="0.05 0.2" pos="0.5 1 0.05" euler="90 0 0"/>
  </worldbody>
</mujoco>
)";

// `output` holds `text`
void ExpectModelSceneOutputHas(const std::string& output, const std::string& text) {
  EXPECT_NE(output.find(text), std::string::npos) << text << "\n" << output;
}

// inspect's text says the robot's root and how many world geoms it found, the first the floor it takes as the ground
void ExpectInspectTookTheFloor(const std::string& output, const std::string& root, int geoms) {
  ExpectModelSceneOutputHas(output, "the robot is the tree under the world body from '" + root + "'; the world body's " +
                                        std::to_string(geoms) + " geom(s) are a scene, not the robot");
  ExpectModelSceneOutputHas(output, "  floor (plane, group 0): the ground (z = 0, facing up), scene object 'model:floor', a plane");
}

class ModelSceneTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::FreshDir("model_scene");
    fs::create_directories(dir_);
    std::ofstream(dir_ / "robot.xml") << testing::MjcfTwin();
    std::ofstream(dir_ / "scene.xml") << kSceneTestScene;
  }
  void TearDown() override { fs::remove_all(dir_); }
  void Write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
  Scenario Load(const std::string& yaml) const { return LoadScenarioText(yaml, (dir_ / "s.yaml").string()); }
  fs::path dir_;
};

TEST_F(ModelSceneTest, TheRobotIsTheOneTreeAndTheWorldGeomsAreOfferedApart) {
  const RobotModel own = RobotModel::FromFile((dir_ / "robot.xml").string());
  const RobotModel scene = RobotModel::FromFile((dir_ / "scene.xml").string());
  EXPECT_TRUE(own.scene_geoms().empty());
  // the same robot: its links and their shapes, nothing of the scene on them
  ASSERT_EQ(scene.link_count(), own.link_count());
  for (int i = 0; i < own.link_count(); ++i) {
    EXPECT_EQ(scene.link_name(i), own.link_name(i));
    EXPECT_EQ(scene.link(i).shapes.size(), own.link(i).shapes.size()) << own.link_name(i);
  }
  // the world's geoms, in file order (the light and the camera are not geoms)
  const auto& geoms = scene.scene_geoms();
  ASSERT_EQ(geoms.size(), 3u);
  EXPECT_EQ(geoms[0].geom, "floor");
  EXPECT_EQ(geoms[0].type, "plane");
  EXPECT_TRUE(geoms[0].ground_plane);
  ASSERT_EQ(geoms[0].objects.size(), 1u);
  EXPECT_EQ(geoms[0].objects[0].name, "model:floor");
  EXPECT_TRUE(std::holds_alternative<Plane>(geoms[0].objects[0].shape));
  EXPECT_TRUE(geoms[0].objects[0].ground);
  // the crate: a box of MuJoCo's half sizes doubled, where the file puts it
  EXPECT_EQ(geoms[1].geom, "crate");
  EXPECT_FALSE(geoms[1].ground_plane);
  ASSERT_EQ(geoms[1].objects.size(), 1u);
  EXPECT_EQ(geoms[1].objects[0].name, "model:crate");
  ASSERT_TRUE(std::holds_alternative<Box>(geoms[1].objects[0].shape));
  EXPECT_LT((std::get<Box>(geoms[1].objects[0].shape).size_m - Vec3(0.2, 0.3, 0.2)).norm(), 1e-12);
  EXPECT_LT((geoms[1].objects[0].X_WO.translation() - Vec3(1.5, 0, 0.1)).norm(), 1e-12);
  EXPECT_FALSE(geoms[1].objects[0].ground);
  // the unnamed capsule: its place among the world's geoms names it; a cylinder and its two ends
  EXPECT_EQ(geoms[2].geom, "geom_2");
  ASSERT_EQ(geoms[2].objects.size(), 3u);
  EXPECT_EQ(geoms[2].objects[0].name, "model:geom_2");
  EXPECT_EQ(geoms[2].objects[1].name, "model:geom_2:top");
  EXPECT_EQ(geoms[2].objects[2].name, "model:geom_2:bottom");
  // (euler 90 about x turns its +z to −y: the top end at y = 1 − 0.2)
  EXPECT_LT((geoms[2].objects[1].X_WO.translation() - Vec3(0.5, 0.8, 0.05)).norm(), 1e-9);
  EXPECT_LT((geoms[2].objects[2].X_WO.translation() - Vec3(0.5, 1.2, 0.05)).norm(), 1e-9);
  for (const ModelSceneGeom& geom : geoms) EXPECT_EQ(geom.problem, "") << geom.geom;
}

// A scenario compiles the model when it reads it only when the file's text
// may give the world body geoms (a robot's own file is compiled once, by the
// run): the scan agrees with what MuJoCo compiles, through frames, includes,
// defaults and comments.
TEST_F(ModelSceneTest, TheTextScanFindsWorldGeomsWhereMuJoCoDoes) {
  Write("framed.xml", R"(<mujoco><include file="robot.xml"/><worldbody><frame pos="1 0 0">
    <geom name="post" type="cylinder" size="0.05 0.5"/></frame></worldbody></mujoco>)");
  Write("parts.xml", R"(<mujoco><geom name="slab" type="box" size="1 1 0.05" pos="0 0 -0.05"/></mujoco>)");
  Write("included.xml", R"(<mujoco><include file="robot.xml"/><worldbody><include file="parts.xml"/></worldbody></mujoco>)");
  Write("quiet.xml", R"(<mujoco><include file="robot.xml"/>
    <default><geom type="box" size="0.1 0.1 0.1"/></default>
    <worldbody><!-- <geom name="floor" type="plane" size="0 0 0.05"/> -->
      <light name="sun" pos="0 0 5"/><body name="x" pos="9 9 9"/></worldbody></mujoco>)");
  // (a static body fused into the world body: its geoms are the world's)
  Write("fused.xml", R"(<mujoco><compiler fusestatic="true"/><include file="robot.xml"/><worldbody>
    <body name="table" pos="2 0 0.4"><geom type="box" size="0.4 0.4 0.02"/></body></worldbody></mujoco>)");
  for (const auto& [file, has] : std::map<std::string, bool>{{"robot.xml", false},
                                                             {"scene.xml", true},
                                                             {"framed.xml", true},
                                                             {"included.xml", true},
                                                             {"fused.xml", true},
                                                             {"quiet.xml", false}}) {
    EXPECT_EQ(MjcfMayHaveWorldGeoms((dir_ / file).string()), has) << file;
    if (file == "quiet.xml") continue;  // (two bodies under its world: not a robot)
    EXPECT_EQ(RobotModel::FromFile((dir_ / file).string()).scene_geoms().empty(), !has) << file;
  }
  // Menagerie's TALOS: its robot files give none, its scene files their floor
  if (fs::is_regular_file(kTalosDir / "scene_position.xml")) {
    for (const auto& [file, has] : std::map<std::string, bool>{
             {"talos.xml", false}, {"talos_position.xml", false}, {"scene_position.xml", true}, {"scene_motor.xml", true}})
      EXPECT_EQ(MjcfMayHaveWorldGeoms((kTalosDir / file).string()), has) << file;
  }
}

TEST_F(ModelSceneTest, APlaneOffTheGroundIsNamedAndRefusedOnlyWhenTheSceneIsTaken) {
  Write("tilted.xml", R"(<mujoco><include file="robot.xml"/>
  <asset>
    <mesh name="tetra" vertex="0 0 0  0.2 0 0  0 0.2 0  0 0 0.2"/>
    <hfield name="bumps" nrow="2" ncol="2" size="1 1 0.1 0.1"/>
  </asset>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 0.05"/>
    <geom name="ramp" type="plane" size="1 1 0.05" pos="3 0 0" euler="0 -10 0"/>
    <geom name="raised" type="plane" size="1 1 0.05" pos="0 0 0.3"/>
    <geom name="rock" type="mesh" mesh="tetra" pos="2 2 0"/>
    <geom name="egg" type="ellipsoid" size="0.3 0.1 0.2" pos="2 -2 0.2"/>
    <geom name="terrain" type="hfield" hfield="bumps" pos="5 0 0"/>
  </worldbody></mujoco>)");
  // the robot loads: the planes are not its own
  const RobotModel model = RobotModel::FromFile((dir_ / "tilted.xml").string());
  const auto& geoms = model.scene_geoms();
  ASSERT_EQ(geoms.size(), 6u);
  EXPECT_TRUE(geoms[0].ground_plane);
  for (int k : {1, 2}) {
    EXPECT_NE(geoms[k].problem.find("a plane that is not the ground (z = 0, facing up)"), std::string::npos);
    EXPECT_TRUE(geoms[k].objects.empty());
  }
  // a mesh with its compiled vertices (4), an ellipsoid as the robot's are (a mesh), a height field named
  ASSERT_EQ(geoms[3].objects.size(), 1u);
  ASSERT_TRUE(std::holds_alternative<Mesh>(geoms[3].objects[0].shape));
  EXPECT_EQ(std::get<Mesh>(geoms[3].objects[0].shape).data->vertices_O.size(), 4u);
  ASSERT_EQ(geoms[4].objects.size(), 1u);
  ASSERT_TRUE(std::holds_alternative<Mesh>(geoms[4].objects[0].shape));
  EXPECT_LT((geoms[4].objects[0].X_WO.translation() - Vec3(2, -2, 0.2)).norm(), 1e-12);
  EXPECT_EQ(geoms[5].type, "hfield");
  EXPECT_NE(geoms[5].problem.find("a hfield: not supported in a scene"), std::string::npos) << geoms[5].problem;
  EXPECT_TRUE(geoms[5].objects.empty());
  // a scenario taking the model's scene is refused, naming each geom and the way out
  const std::string refused = testing::ErrorOf([&] { Load("proxsim: 1\nrobot: {model: tilted.xml}\nsensors: []\n"); });
  EXPECT_NE(refused.find("robot.model: geom 'ramp' of the model's world body (its scene) is a plane that is not the ground"),
            std::string::npos)
      << refused;
  EXPECT_NE(refused.find("geom 'raised'"), std::string::npos) << refused;
  EXPECT_NE(refused.find("geom 'terrain' of the model's world body (its scene) is a hfield"), std::string::npos) << refused;
  EXPECT_NE(refused.find("robot.model_scene: ignore"), std::string::npos) << refused;
  // leaving it out, the robot walks in the scenario's scene alone
  const Scenario ignored = Load("proxsim: 1\nrobot: {model: tilted.xml, model_scene: ignore}\nsensors: []\n");
  EXPECT_TRUE(ignored.scene.objects.empty());
  EXPECT_TRUE(ignored.scene_from_model.objects.empty());
  // a value other than include or ignore is named
  const std::string bad = testing::ErrorOf([&] { Load("proxsim: 1\nrobot: {model: scene.xml, model_scene: keep}\nsensors: []\n"); });
  EXPECT_NE(bad.find("robot.model_scene: expected include (the world geoms of the model's file join the scene) or ignore"),
            std::string::npos)
      << bad;
}

TEST_F(ModelSceneTest, TheScenarioTakesTheWorldGeomsAndTheGroundPlaneOnlyWithoutAGroundOfItsOwn) {
  // an empty scene: the model's floor is the ground, its crate and capsule objects
  const Scenario empty = Load("proxsim: 1\nrobot: {model: scene.xml}\nsensors: []\n");
  std::vector<std::string> names;
  for (const SceneObject& o : empty.scene.objects) names.push_back(o.name);
  const std::vector<std::string> all = {"model:floor", "model:crate", "model:geom_2", "model:geom_2:top",
                                        "model:geom_2:bottom"};
  EXPECT_EQ(names, all);
  EXPECT_EQ(empty.scene_from_model.objects, all);
  EXPECT_TRUE(empty.scene.objects[0].ground);
  EXPECT_EQ(empty.scene_from_model.ground_left_out, "");
  // the dining room has its floor: the model's is left out (said), the crate added after the room's objects
  const Scenario room =
      Load("proxsim: 1\nscene: {builtin: dining_room}\nrobot: {model: scene.xml}\nsensors: []\n");
  EXPECT_EQ(room.scene.objects.front().name, "floor");
  EXPECT_EQ(room.scene_from_model.ground_left_out, "floor");
  EXPECT_EQ(room.scene_from_model.objects.front(), "model:crate");
  EXPECT_EQ(room.scene.objects[room.scene.objects.size() - 4].name, "model:crate");
  EXPECT_EQ(std::ranges::count_if(room.scene.objects, [](const SceneObject& o) { return o.ground; }), 1);
  // so does a scenario's own ground object (a box floor here)
  const Scenario slab = Load("proxsim: 1\nscene: {objects: [{name: slab, box: {size_m: [9, 9, 0.1]}, pose: {xyz_m: [0, 0, -0.05]}, "
                             "ground: true}]}\nrobot: {model: scene.xml}\nsensors: []\n");
  EXPECT_EQ(slab.scene_from_model.ground_left_out, "floor");
  EXPECT_EQ(slab.scene.objects.size(), 1u + 4u);
  // start.on may name one of them (the check that the feet stand on it is the run's)
  EXPECT_EQ(Load("proxsim: 1\nrobot: {model: scene.xml, start: {xyz_m: [1.5, 0, 0.2], on: 'model:crate'}}\nsensors: []\n")
                .robot->start_on,
            "model:crate");
  // a name the scene uses already is refused
  const std::string clash = testing::ErrorOf([&] {
    Load("proxsim: 1\nscene: {objects: [{name: 'model:crate', sphere: {radius_m: 0.1}, pose: {xyz_m: [0, 3, 0.1]}}]}\n"
         "robot: {model: scene.xml}\nsensors: []\n");
  });
  EXPECT_NE(clash.find("geom 'crate' of the model's world body becomes scene object 'model:crate', a name the scene "
                       "already uses"),
            std::string::npos)
      << clash;
  // the robot's own file brings nothing
  const Scenario own = Load("proxsim: 1\nrobot: {model: robot.xml}\nsensors: []\n");
  EXPECT_TRUE(own.scene.objects.empty());
  // summary.json echoes the key and what the scene took
  const nlohmann::json inputs = InputsJson(room);
  EXPECT_EQ(inputs["robot"]["model_scene"], "include");
  EXPECT_EQ(inputs["scene"]["from_model"]["objects"].size(), 4u);
  EXPECT_EQ(inputs["scene"]["from_model"]["ground_left_out"], "floor");
  const nlohmann::json ignored =
      InputsJson(Load("proxsim: 1\nrobot: {model: scene.xml, model_scene: ignore}\nsensors: []\n"));
  EXPECT_EQ(ignored["robot"]["model_scene"], "ignore");
  EXPECT_TRUE(ignored["scene"]["from_model"]["objects"].empty());
  EXPECT_TRUE(ignored["scene"]["from_model"]["ground_left_out"].is_null());
}

// The scene file walked in an empty scene, and the robot's own file in a
// scenario drawing the same floor and crate (named as the model's): the same
// walk, readings and collision.
TEST_F(ModelSceneTest, ItsCrateIsSeenAndHitAsTheScenariosOwnObjectWouldBe) {
  const std::string common = R"(proxsim: 1
seed: 2
duration_s: 6
rate_hz: 50
robot:
  model: MODEL
  path: {waypoints_m: [[0, 0], [3, 0]]}
sensors:
  - {name: shin, type: laser, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.3], rpy_deg: [0, 15, 0]}}
  - {name: side, type: ideal, link: world, pose: {xyz_m: [1.5, 1.0, 0.1], rpy_deg: [0, 0, -90]}}
)";
  Write("with_scene.yaml", std::string(common).replace(common.find("MODEL"), 5, "scene.xml"));
  Write("drawn.yaml", std::string(common).replace(common.find("MODEL"), 5, "robot.xml") +
                          "scene:\n  objects:\n"
                          "    - {name: 'model:floor', plane: {}, material: {albedo: 1}}\n"
                          "    - {name: 'model:crate', box: {size_m: [0.2, 0.3, 0.2]}, pose: {xyz_m: [1.5, 0, 0.1]}}\n");
  std::map<std::string, testing::Csv> poses, readings;
  std::map<std::string, nlohmann::json> summary;
  for (const std::string name : {"with_scene", "drawn"}) {
    const fs::path out = dir_ / ("out_" + name);
    const auto run = testing::RunProxsim("run " + (dir_ / (name + ".yaml")).string() + " --no-report --out " + out.string());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    poses[name] = testing::ReadCsv(out / "poses.csv");
    readings[name] = testing::ReadCsv(out / "readings.csv");
    summary[name] = nlohmann::json::parse(testing::ReadFile(out / "summary.json"));
  }
  // the side sensor reads the crate's face y = 0.15 from y = 1: 0.85 m
  int side_rows = 0, shin_on_crate = 0;
  for (const auto& row : readings["with_scene"].rows) {
    if (row.at("sensor") == "side") {
      ++side_rows;
      EXPECT_EQ(row.at("object"), "model:crate");
      EXPECT_NEAR(std::stod(row.at("d_m")), 0.85, 1e-6);
    } else {
      shin_on_crate += row.at("object") == "model:crate";
    }
  }
  EXPECT_GT(side_rows, 10);
  EXPECT_GT(shin_on_crate, 0) << "the shin's laser sees the crate ahead";
  // the same readings as with the scenario's own objects
  const auto& a = readings["with_scene"].rows;
  const auto& b = readings["drawn"].rows;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].at("status"), b[k].at("status")) << k;
    EXPECT_EQ(a[k].at("object"), b[k].at("object")) << k;
    EXPECT_NEAR(std::stod(a[k].at("d_m")), std::stod(b[k].at("d_m")), 1e-9) << k;
  }
  // the same walk, link by link, and the same end: it walks into the crate
  ASSERT_EQ(poses["with_scene"].rows.size(), poses["drawn"].rows.size());
  double worst_m = 0;
  for (std::size_t k = 0; k < poses["drawn"].rows.size(); ++k) {
    for (const char* c : {"x", "y", "z"})
      worst_m = std::max(worst_m, std::abs(std::stod(poses["with_scene"].rows[k].at(c)) - std::stod(poses["drawn"].rows[k].at(c))));
  }
  EXPECT_LT(worst_m, 1e-9);
  const nlohmann::json& robot = summary["with_scene"]["robot"];
  EXPECT_EQ(robot["outcome"], "collided") << robot.dump(1);
  ASSERT_FALSE(robot["collisions"].empty());
  EXPECT_EQ(robot["collisions"][0]["object"], "model:crate");
  EXPECT_EQ(robot["outcome"], summary["drawn"]["robot"]["outcome"]);
  EXPECT_EQ(robot["outcome_t_s"], summary["drawn"]["robot"]["outcome_t_s"]);
  EXPECT_EQ(summary["with_scene"]["inputs"]["scene"]["from_model"]["objects"].size(), 5u);
}

TEST_F(ModelSceneTest, InspectAndValidateSayWhatItTook) {
  // validate counts what the model brought, and says when its floor was left out
  Write("v_empty.yaml", "proxsim: 1\nrobot: {model: scene.xml}\nsensors: []\n");
  Write("v_room.yaml", "proxsim: 1\nscene: {builtin: dining_room}\nrobot: {model: scene.xml}\nsensors: []\n");
  const auto empty = testing::RunProxsim("validate " + (dir_ / "v_empty.yaml").string());
  ASSERT_EQ(empty.exit_code, 0) << empty.output;
  ExpectModelSceneOutputHas(empty.output, "valid (5 objects, 5 from the robot's model file, 0 sensors");
  EXPECT_EQ(empty.output.find("left out"), std::string::npos) << empty.output;
  const auto room = testing::RunProxsim("validate " + (dir_ / "v_room.yaml").string());
  ASSERT_EQ(room.exit_code, 0) << room.output;
  ExpectModelSceneOutputHas(room.output, "4 from the robot's model file");
  ExpectModelSceneOutputHas(room.output,
                            "the model file's ground plane 'floor' is left out: the scene's own ground stands for it");

  const auto text = testing::RunProxsim("inspect " + (dir_ / "scene.xml").string());
  ASSERT_EQ(text.exit_code, 0) << text.output;
  ExpectInspectTookTheFloor(text.output, "pelvis", 3);
  ExpectModelSceneOutputHas(text.output,
                            "  crate (box, group 0): scene object 'model:crate', a box at [1.5000, 0.0000, 0.1000] m");
  ExpectModelSceneOutputHas(text.output, "scene object 'model:geom_2:top', a sphere");
  const auto json_run = testing::RunProxsim("inspect --json " + (dir_ / "scene.xml").string() + " 2>/dev/null");
  ASSERT_EQ(json_run.exit_code, 0) << json_run.output;
  const nlohmann::json json = nlohmann::json::parse(json_run.output);
  const nlohmann::json& geoms = json["model_scene"];
  ASSERT_EQ(geoms.size(), 3u);
  EXPECT_EQ(geoms[0]["geom"], "floor");
  EXPECT_EQ(geoms[0]["ground_plane"], true);
  EXPECT_EQ(geoms[1]["objects"][0]["name"], "model:crate");
  EXPECT_EQ(geoms[1]["objects"][0]["shape"], "box");
  EXPECT_NEAR(geoms[1]["objects"][0]["xyz_m"][0].get<double>(), 1.5, 1e-12);
  EXPECT_TRUE(geoms[1]["problem"].is_null());
  EXPECT_EQ(geoms[2]["objects"].size(), 3u);
  EXPECT_EQ(json["robot"]["root_link"], "pelvis");
  // the robot's own file has none
  const auto own = testing::RunProxsim("inspect --json " + (dir_ / "robot.xml").string() + " 2>/dev/null");
  EXPECT_TRUE(nlohmann::json::parse(own.output)["model_scene"].empty());
}

// Menagerie's TALOS scene file, as it comes: inspect takes its robot and its
// floor; walked on its own floor (an empty scene) and in the dining room
// (whose floor stands for it), it reaches its goal exactly as the robot's own
// file does on a floor the scenario draws.
TEST(ModelSceneTalos, TheMenagerieSceneFileWalksToItsGoalAsTheRobotsOwnFile) {
  SKIP_WITHOUT_TALOS();
  const auto inspected = testing::RunProxsim("inspect " + (kTalosDir / "scene_position.xml").string());
  ASSERT_EQ(inspected.exit_code, 0) << inspected.output;
  ExpectInspectTookTheFloor(inspected.output, "base_link", 1);
  ExpectModelSceneOutputHas(inspected.output, "(read as the gait reads robot.legs: accepted)");

  const fs::path dir = testing::FreshDir("model_scene_talos");
  fs::create_directories(dir);
  const auto scenario = [&](const std::string& model, const std::string& scene) {
    return "proxsim: 1\nseed: 1\nduration_s: 8\nrate_hz: 50\nscene: " + scene + "\nrobot:\n  model: " + model +
           "\n  geom_group: 2\n"
           "  legs:\n"
           "    left:  {hip: leg_left_3_joint,  knee: leg_left_4_joint,  ankle: leg_left_5_joint,  foot: leg_left_6_link}\n"
           "    right: {hip: leg_right_3_joint, knee: leg_right_4_joint, ankle: leg_right_5_joint, foot: leg_right_6_link}\n"
           "  joints_deg: {arm_left_2_joint: 10, arm_right_2_joint: -10, arm_left_4_joint: -30, arm_right_4_joint: -30}\n"
           "  path: {waypoints_m: [[0, 0], [1.8, 0]]}\n"
           "sensors:\n  - {name: shin, type: laser, link: leg_left_4_link, pose: {xyz_m: [0.07, 0, -0.16], rpy_deg: [0, 15, 0]}}\n";
  };
  const std::string scene_file = (kTalosDir / "scene_position.xml").string();
  const std::string robot_file = (kTalosDir / "talos_position.xml").string();
  const std::map<std::string, std::string> runs = {
      {"scene_empty", scenario(scene_file, "{builtin: empty}")},
      {"own_floor", scenario(robot_file, "{objects: [{name: 'model:floor', plane: {}}]}")},
      {"scene_room", scenario(scene_file, "{builtin: dining_room}")},
      {"own_room", scenario(robot_file, "{builtin: dining_room}")}};
  std::map<std::string, nlohmann::json> summary;
  std::map<std::string, testing::Csv> poses, readings;
  for (const auto& [name, yaml] : runs) {
    std::ofstream(dir / (name + ".yaml")) << yaml;
    const auto run = testing::RunProxsim("run " + (dir / (name + ".yaml")).string() + " --no-report --out " + (dir / name).string());
    ASSERT_EQ(run.exit_code, 0) << name << ": " << run.output;
    summary[name] = nlohmann::json::parse(testing::ReadFile(dir / name / "summary.json"));
    poses[name] = testing::ReadCsv(dir / name / "poses.csv");
    readings[name] = testing::ReadCsv(dir / name / "readings.csv");
    EXPECT_EQ(summary[name]["robot"]["outcome"], "reached_goal") << name << ": " << summary[name]["robot"].dump(1);
  }
  EXPECT_EQ(summary["scene_empty"]["inputs"]["scene"]["from_model"]["objects"], nlohmann::json::array({"model:floor"}));
  EXPECT_EQ(summary["scene_room"]["inputs"]["scene"]["from_model"]["ground_left_out"], "floor");
  EXPECT_TRUE(summary["scene_room"]["inputs"]["scene"]["from_model"]["objects"].empty());
  // the scene file walks exactly as the robot's own file, and reads the same
  for (const auto& [scene, own] : {std::pair{"scene_empty", "own_floor"}, std::pair{"scene_room", "own_room"}}) {
    ASSERT_EQ(poses[scene].rows.size(), poses[own].rows.size()) << scene;
    double worst_m = 0;
    for (std::size_t k = 0; k < poses[own].rows.size(); ++k)
      for (const char* c : {"x", "y", "z"})
        worst_m = std::max(worst_m, std::abs(std::stod(poses[scene].rows[k].at(c)) - std::stod(poses[own].rows[k].at(c))));
    EXPECT_LT(worst_m, 1e-9) << scene;
    ASSERT_EQ(readings[scene].rows.size(), readings[own].rows.size()) << scene;
    for (std::size_t k = 0; k < readings[own].rows.size(); ++k) {
      EXPECT_EQ(readings[scene].rows[k].at("object"), readings[own].rows[k].at("object")) << scene << " " << k;
      EXPECT_NEAR(std::stod(readings[scene].rows[k].at("d_m")), std::stod(readings[own].rows[k].at("d_m")), 1e-9);
    }
    EXPECT_EQ(summary[scene]["robot"]["reached_goal_t_s"], summary[own]["robot"]["reached_goal_t_s"]) << scene;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace proxsim
