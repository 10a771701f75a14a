// The ground is a role a scene object declares (`ground: true`, a plane by
// default), never one read from its name: the built-in floors and treads are
// flagged, a box named floor_x that does not say so is an obstacle to the
// robot's clearance, a box named slab that does is the ground it stands on,
// and a `ground` that is not true or false is refused at its line.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "scenario/scenario.h"
#include "scene/scene.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

// The names of a scene's objects flagged as ground, in scene order.
std::vector<std::string> GroundNames(const Scene& scene) {
  std::vector<std::string> names;
  for (const SceneObject& object : scene.objects)
    if (object.ground) names.push_back(object.name);
  return names;
}

// The problems LoadScenarioText reports for `text`; fails the test if it loads.
std::vector<std::string> GroundFlagProblemsOf(const std::string& text) {
  try {
    LoadScenarioText(text, "scenario.yaml");
  } catch (const InputError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "expected an InputError for:\n" << text;
  return {};
}

TEST(GroundFlagTest, BuiltinFloorsAndTreadsAreGroundTheHolesBottomsAreNot) {
  EXPECT_EQ(GroundNames(MakeBuiltinScene("dining_room")), std::vector<std::string>{"floor"});
  // what the feet stand on when walking the stairs course; a hole's bottom is
  // below the legs' reach, and its slab stays in the clearance
  const std::vector<std::string> treads = {"floor",           "floor_stair_up_1",   "floor_stair_up_2",
                                           "floor_stair_up_3", "floor_landing",      "floor_stair_down_1",
                                           "floor_stair_down_2", "floor_stair_down_3", "floor_after_stairs",
                                           "floor_between_holes", "floor_end"};
  EXPECT_EQ(GroundNames(MakeBuiltinScene("stairs")), treads);
  EXPECT_TRUE(GroundNames(MakeBuiltinScene("empty")).empty());
}

TEST(GroundFlagTest, APlaneIsGroundUnlessItSaysOtherwiseAnyOtherShapeOnlyWhenItSaysSo) {
  const Scenario scenario = LoadScenarioText(
      "proxsim: 1\n"
      "scene:\n"
      "  objects:\n"
      "    - {name: plain_plane, plane: {}}\n"
      "    - {name: wall_plane, plane: {}, ground: false, pose: {xyz_m: [3, 0, 0], rpy_deg: [0, 90, 0]}}\n"
      "    - {name: floor_x, box: {size_m: [1, 1, 0.1]}}\n"
      "    - {name: slab, box: {size_m: [1, 1, 0.1]}, ground: true}\n"
      "    - {name: rock, sphere: {radius_m: 0.2}, ground: no}\n"
      "sensors:\n"
      "  - {name: s, type: ideal}\n",
      "scenario.yaml");
  EXPECT_EQ(GroundNames(scenario.scene), (std::vector<std::string>{"plain_plane", "slab"}));
}

TEST(GroundFlagTest, AGroundThatIsNotTrueOrFalseIsRefusedAtItsLine) {
  const auto problems = GroundFlagProblemsOf(
      "proxsim: 1\n"
      "scene:\n"
      "  objects:\n"
      "    - {name: a, plane: {}, ground: 1}\n"
      "    - {name: b, box: {size_m: [1, 1, 1]}, ground: \"true\"}\n"
      "    - name: c\n"
      "      sphere: {radius_m: 1}\n"
      "      ground: [true]\n"
      "    - {name: d, plane: {}, ground: floor}\n"
      "sensors:\n"
      "  - {name: s, type: ideal}\n");
  const std::vector<std::string> expected = {
      "scenario.yaml:4: scene.objects[0].ground: expected true or false, got 1",
      "scenario.yaml:5: scene.objects[1].ground: expected true or false, got \"true\"",
      "scenario.yaml:8: scene.objects[2].ground: expected true or false, got [true]",
      "scenario.yaml:9: scene.objects[3].ground: expected true or false, got floor"};
  EXPECT_EQ(problems, expected);
}

// The biped standing on a 0.5 m thick box named `name` (its top at z = 0),
// `ground_key` added to it, a wall's face 2 m ahead; a short walk of 0.4 s.
// A box that is not ground is started on on purpose (`robot.start.on`): a
// start on an object that is not ground is refused otherwise.
Scenario StandingOn(const std::string& name, const std::string& ground_key) {
  const std::string start = ground_key.empty() ? "  start: {on: " + name + "}\n" : "";
  return LoadScenarioText(
      "proxsim: 1\nduration_s: 0.4\nrate_hz: 50\n"
      "scene:\n"
      "  objects:\n"
      "    - {name: " + name + ", box: {size_m: [4, 3, 0.5]}, pose: {xyz_m: [0, 0, -0.25]}" + ground_key + "}\n"
      "    - {name: wall, box: {size_m: [0.1, 3, 2]}, pose: {xyz_m: [2.05, 0, 1]}}\n"
      "robot:\n  model: builtin:biped\n  path: {waypoints_m: [[0, 0], [3, 0]]}\n" + start +
      "sensors:\n  - {name: s, type: ideal, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.2]}}\n",
      name + ".yaml");
}

// The least clearance of the walk, and the world's ground ids.
struct GroundWalked {
  double min_clearance_m = 0;
  std::vector<std::int32_t> ground_ids;
};

GroundWalked WalkOn(Scenario scenario) {
  Simulation sim(std::move(scenario));
  while (!sim.done()) sim.Step();
  const auto ids = sim.world().ground_ids();
  return {sim.robot_outcome().min_clearance_m, std::vector<std::int32_t>(ids.begin(), ids.end())};
}

TEST(GroundFlagTest, TheClearanceLeavesOutTheDeclaredGroundNotWhatIsNamedFloor) {
  // named slab, declared ground: left out, the wall ahead is the nearest thing
  const GroundWalked slab = WalkOn(StandingOn("slab", ", ground: true"));
  EXPECT_EQ(slab.ground_ids, std::vector<std::int32_t>{0});
  EXPECT_GT(slab.min_clearance_m, 1.0);
  // named floor_x, not declared but started on on purpose (robot.start.on): the
  // robot's ground for that run, left out the same way
  const GroundWalked floor_x = WalkOn(StandingOn("floor_x", ""));
  EXPECT_EQ(floor_x.ground_ids, std::vector<std::int32_t>{0});
  EXPECT_GT(floor_x.min_clearance_m, 1.0);
  // a name is not a declaration: floor_y, beside the walk and not declared, is
  // an obstacle to the clearance, 0.1 m from the feet's sides at most
  Scenario beside = StandingOn("slab", ", ground: true");
  SceneObject floor_y = beside.scene.objects[1];
  floor_y.name = "floor_y";
  floor_y.shape = Box{Vec3(2.0, 0.2, 0.02)};
  floor_y.X_WO = Pose::Identity();
  floor_y.X_WO.translation() = Vec3(0.0, 0.35, 0.01);
  beside.scene.objects.push_back(floor_y);
  const GroundWalked with_floor_y = WalkOn(beside);
  EXPECT_EQ(with_floor_y.ground_ids, std::vector<std::int32_t>{0});
  EXPECT_LT(with_floor_y.min_clearance_m, 0.15);
}

}  // namespace
}  // namespace proxsim
