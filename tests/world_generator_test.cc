// Generated worlds (docs/worlds.md): a thousand seeds of each kind generate
// and load as scenarios, every room keeps its free corridor (checked here by
// a grid search of the test's own, on a finer grid, with the objects as the
// loaded scenario has them), nothing stands where the robot starts, names
// and ground flags follow the roles; the same seed gives the same world;
// bad input is refused naming the fault; through the CLI, `proxsim generate`
// writes a scenario whose run equals the inline run byte for byte, and a
// generated room runs the same on 1 and 2 threads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <deque>
#include <set>
#include <string>

#include "cli_helpers.h"
#include "core/input_error.h"
#include "scenario/scenario.h"
#include "scenario/scenario_generate.h"
#include "scene/world_generator.h"

namespace proxsim {
namespace {

using testing::FreshDir;
using testing::ReadFile;
using testing::RunProxsim;

std::string GeneratedScenario(const std::string& generate, const std::string& robot = "") {
  return "proxsim: 1\nduration_s: 2\nscene:\n  generate: " + generate + "\n" + robot +
         "sensors:\n  - {name: s, type: ideal, link: world, pose: {xyz_m: [0, 0, 0.3]}}\n";
}

// The xy bounding box of a loaded object (people and planes aside).
bool XyBox(const SceneObject& object, Vec2* lo, Vec2* hi) {
  Vec3 half;
  if (const auto* box = std::get_if<Box>(&object.shape)) half = 0.5 * box->size_m;
  else if (const auto* cylinder = std::get_if<Cylinder>(&object.shape))
    half = Vec3(cylinder->radius_m, cylinder->radius_m, 0.5 * cylinder->length_m);
  else if (const auto* sphere = std::get_if<Sphere>(&object.shape)) half = Vec3::Constant(sphere->radius_m);
  else return false;
  // the corners of the (possibly rotated) box, projected
  *lo = Vec2::Constant(1e9);
  *hi = Vec2::Constant(-1e9);
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner = object.X_WO * Vec3((c & 1) ? half.x() : -half.x(), (c & 2) ? half.y() : -half.y(),
                                           (c & 4) ? half.z() : -half.z());
    *lo = lo->cwiseMin(corner.head<2>());
    *hi = hi->cwiseMax(corner.head<2>());
  }
  return true;
}

double DistanceToRect(const Vec2& p, const Vec2& lo, const Vec2& hi) { return (p.cwiseMax(lo).cwiseMin(hi) - p).norm(); }

// The test's own corridor check: 2 cm cells whose centres are at least
// `half_width` from every obstacle's footprint (walls and furniture: every
// object that is not ground and does not move), 8-connected search from start to goal.
bool CorridorExists(const Scenario& scenario, const Vec2& start, const Vec2& goal, double half_width) {
  constexpr double kCell = 0.02;
  std::vector<std::pair<Vec2, Vec2>> rects;
  Vec2 lo_all = Vec2::Constant(1e9), hi_all = Vec2::Constant(-1e9);
  for (const SceneObject& object : scenario.scene.objects) {
    Vec2 lo, hi;
    if (object.ground || object.motion || !XyBox(object, &lo, &hi)) continue;
    rects.emplace_back(lo, hi);
    lo_all = lo_all.cwiseMin(lo);
    hi_all = hi_all.cwiseMax(hi);
  }
  const int nx = static_cast<int>((hi_all.x() - lo_all.x()) / kCell) + 1;
  const int ny = static_cast<int>((hi_all.y() - lo_all.y()) / kCell) + 1;
  std::vector<char> blocked(static_cast<std::size_t>(nx) * ny, 0);
  const auto centre = [&](int ix, int iy) -> Vec2 { return lo_all + kCell * Vec2(ix + 0.5, iy + 0.5); };
  for (const auto& [lo, hi] : rects) {
    const int ix0 = std::max(0, static_cast<int>((lo.x() - half_width - lo_all.x()) / kCell) - 1);
    const int ix1 = std::min(nx - 1, static_cast<int>((hi.x() + half_width - lo_all.x()) / kCell) + 1);
    const int iy0 = std::max(0, static_cast<int>((lo.y() - half_width - lo_all.y()) / kCell) - 1);
    const int iy1 = std::min(ny - 1, static_cast<int>((hi.y() + half_width - lo_all.y()) / kCell) + 1);
    for (int iy = iy0; iy <= iy1; ++iy)
      for (int ix = ix0; ix <= ix1; ++ix)
        if (DistanceToRect(centre(ix, iy), lo, hi) < half_width) blocked[iy * nx + ix] = 1;
  }
  const auto cell_of = [&](const Vec2& p) {
    return std::make_pair(static_cast<int>((p.x() - lo_all.x()) / kCell), static_cast<int>((p.y() - lo_all.y()) / kCell));
  };
  // start and goal: the free cell nearest each (they lie between cell centres)
  const auto nearest_free = [&](const Vec2& p) {
    const auto [cx, cy] = cell_of(p);
    int best = -1;
    double best_d = 1e9;
    for (int iy = cy - 1; iy <= cy + 1; ++iy)
      for (int ix = cx - 1; ix <= cx + 1; ++ix)
        if (ix >= 0 && iy >= 0 && ix < nx && iy < ny && !blocked[iy * nx + ix] && (centre(ix, iy) - p).norm() < best_d)
          best_d = (centre(ix, iy) - p).norm(), best = iy * nx + ix;
    return best;
  };
  const int from = nearest_free(start), to = nearest_free(goal);
  if (from < 0 || to < 0) return false;
  std::vector<char> seen(blocked.size(), 0);
  std::deque<int> queue{from};
  seen[from] = 1;
  while (!queue.empty()) {
    const int cell = queue.front();
    queue.pop_front();
    if (cell == to) return true;
    const int ix = cell % nx, iy = cell / nx;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int jx = ix + dx, jy = iy + dy;
        if (jx < 0 || jy < 0 || jx >= nx || jy >= ny) continue;
        const int next = jy * nx + jx;
        if (blocked[next] || seen[next]) continue;
        seen[next] = 1;
        queue.push_back(next);
      }
  }
  return false;
}

// Checks shared by both kinds: names unique, nothing but ground under the robot's start.
void CheckStartAndNames(const Scenario& scenario, const std::string& what) {
  std::set<std::string> names;
  for (const SceneObject& object : scenario.scene.objects) {
    EXPECT_TRUE(names.insert(object.name).second) << what << ": duplicate " << object.name;
    EXPECT_FALSE(object.ground && object.motion) << what << ": " << object.name;
    Vec2 lo, hi;
    if (object.ground || !XyBox(object, &lo, &hi)) continue;
    // the robot (0.45 m wide) stands at the origin: no obstacle within its half width
    EXPECT_GT(DistanceToRect(Vec2::Zero(), lo, hi), 0.225) << what << ": " << object.name << " at the start";
  }
}

// How many worlds of each kind the two sweeps below generate: a thousand,
// or PROXSIM_GENERATED_WORLDS (the sanitizer pass's preset walks 200 of
// them: the same code, memory-checked, in a fifth of the time).
int GeneratedWorldCount() {
  const char* count = std::getenv("PROXSIM_GENERATED_WORLDS");
  return count != nullptr && std::atoi(count) > 0 ? std::atoi(count) : 1000;
}

TEST(WorldGenerator, AThousandCoursesGenerateWithTheirRolesAndNothingAtTheStart) {
  for (int seed = 1; seed <= GeneratedWorldCount(); ++seed) {
    const double difficulty = (seed % 11) / 10.0;
    const std::string what = "course seed " + std::to_string(seed);
    const Scenario scenario = LoadScenarioText(
        GeneratedScenario("{kind: course, seed: " + std::to_string(seed) + ", difficulty: " + std::to_string(difficulty) + "}",
                          "robot: {model: builtin:biped}\n"),
        "course.yaml");
    CheckStartAndNames(scenario, what);
    for (const SceneObject& object : scenario.scene.objects) {
      // holes' bottoms are not ground; everything else of a course is
      const bool hole = object.name.rfind("hole_", 0) == 0;
      EXPECT_EQ(object.ground, !hole) << what << ": " << object.name;
    }
    ASSERT_TRUE(scenario.robot.has_value());
    ASSERT_EQ(scenario.robot->waypoints_m.size(), 2u);
    EXPECT_DOUBLE_EQ(scenario.robot->waypoints_m.back().x(), 20.0);
  }
}

TEST(WorldGenerator, AThousandRoomsKeepTheirCorridorByTheTestsOwnSearch) {
  int people = 0, furniture = 0, blockers = 0;
  const int rooms = GeneratedWorldCount();
  for (int seed = 1; seed <= rooms; ++seed) {
    const double difficulty = (seed % 11) / 10.0;
    const std::string what = "room seed " + std::to_string(seed);
    const Scenario scenario = LoadScenarioText(
        GeneratedScenario("{kind: room, seed: " + std::to_string(seed) + ", difficulty: " + std::to_string(difficulty) + "}",
                          "robot: {model: builtin:biped}\n"),
        "room.yaml");
    CheckStartAndNames(scenario, what);
    ASSERT_TRUE(scenario.robot.has_value());
    const Vec2 goal = scenario.robot->waypoints_m.back();
    // the corridor: robot_width_m + margin_m = 0.45 + 0.2 wide
    EXPECT_TRUE(CorridorExists(scenario, Vec2::Zero(), goal, 0.5 * (0.45 + 0.2))) << what;
    for (const SceneObject& object : scenario.scene.objects) {
      if (object.name.rfind("person_", 0) == 0) {
        ++people;
        EXPECT_TRUE(object.motion.has_value()) << what << ": " << object.name;
        // people start 1.5 m or more from the robot
        if (object.name.ends_with("/torso")) EXPECT_GT(object.X_WO.translation().head<2>().norm(), 1.4) << what;
      }
      if (object.name.rfind("chair_", 0) == 0 || object.name.rfind("table_", 0) == 0) ++furniture;
      // blockers stand in the way from 2.2 m along the walk on (the centre
      // drawn there; a part of one, a chair's leg, up to its half-width
      // nearer): a study never counts a stop in the first stride as one
      // before them (kStopBeforeObstacle_m = 1.2 m short of where the blind walk meets one)
      if (object.name.rfind("blocker_", 0) == 0) {
        ++blockers;
        const Vec2 along = goal.normalized();
        EXPECT_GT(object.X_WO.translation().head<2>().dot(along), 2.2 - 0.35) << what << ": " << object.name;
      }
      EXPECT_EQ(object.ground, object.name == "floor") << what << ": " << object.name;
    }
  }
  // (every other room has a person, five pieces of furniture and more than one blocker on average)
  EXPECT_GT(people, rooms / 2);
  EXPECT_GT(furniture, 5 * rooms);
  EXPECT_GT(blockers, rooms);
}

TEST(WorldGenerator, TheSameSeedGivesTheSameWorldAndAnotherSeedAnother) {
  for (const char* kind : {"course", "room"}) {
    const std::string a = GeneratedScenario(std::string("{kind: ") + kind + ", seed: 7, difficulty: 0.6}");
    const std::string b = GeneratedScenario(std::string("{kind: ") + kind + ", seed: 8, difficulty: 0.6}");
    EXPECT_EQ(GeneratedScenarioText(a, "a.yaml"), GeneratedScenarioText(a, "a.yaml"));
    EXPECT_NE(GeneratedScenarioText(a, "a.yaml"), GeneratedScenarioText(b, "a.yaml"));
  }
}

TEST(WorldGenerator, ElementsChooseTheFamiliesAndTheirOrderWithRolesInTheirNames) {
  const Scenario scenario = LoadScenarioText(
      GeneratedScenario("{kind: course, seed: 3, difficulty: 1, length_m: 12, elements: [stairs_up, hole, stairs_down]}"),
      "course.yaml");
  std::vector<std::string> order;
  for (const SceneObject& object : scenario.scene.objects) {
    for (const char* family : {"stairs_up_", "hole_", "stairs_down_"}) {
      if (object.name.rfind(family, 0) == 0 && (order.empty() || order.back() != family)) order.push_back(family);
    }
  }
  ASSERT_GE(order.size(), 3u);
  EXPECT_EQ(order[0], "stairs_up_");
  EXPECT_EQ(order[1], "hole_");
  EXPECT_EQ(order[2], "stairs_down_");
  // the stairs' steps: each a rise above the last
  double last_top = 0;
  int steps = 0;
  for (const SceneObject& object : scenario.scene.objects) {
    if (object.name.rfind("stairs_up_1_step_", 0) != 0) continue;
    const double top = object.X_WO.translation().z() + 0.5 * std::get<Box>(object.shape).size_m.z();
    EXPECT_GT(top, last_top + 0.04) << object.name;
    last_top = top;
    ++steps;
  }
  EXPECT_GE(steps, 2);
}

std::string ErrorOf(const std::string& text) {
  try {
    LoadScenarioText(text, "gen.yaml");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(WorldGenerator, BadInputNamesTheFault) {
  EXPECT_NE(ErrorOf(GeneratedScenario("{kind: course, elements: [stairs_up, lava]}")).find("unknown family 'lava'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(GeneratedScenario("{kind: course, stairs: {tread_m: [0.4, 0.2]}}"))
                .find("stairs.tread_m: [0.4, 0.2]: expected treads at least a foot long (0.26 m)"),
            std::string::npos);
  EXPECT_NE(ErrorOf(GeneratedScenario("{kind: course, hole: {depth_m: [-0.1, 0.3]}}")).find("hole.depth_m"),
            std::string::npos);
  EXPECT_NE(ErrorOf(GeneratedScenario("{kind: room, height_m: 1.8, people_height_m: [1.6, 1.9]}"))
                .find("a person 1.9 m tall does not fit in a room 1.8 m high"),
            std::string::npos);
  EXPECT_NE(ErrorOf(GeneratedScenario("{kind: room, length_m: 5}")).find("length_m is for kind: course"),
            std::string::npos);
  EXPECT_NE(ErrorOf(GeneratedScenario("{kind: maze}")).find("unknown kind 'maze'"), std::string::npos);
  // through the CLI: exit 2, the fault named, nothing written
  const auto dir = FreshDir("generate_bad");
  std::filesystem::create_directories(dir);
  {
    std::ofstream(dir / "bad.yaml") << GeneratedScenario("{kind: course, elements: [lava]}");
  }
  const auto result = RunProxsim("generate " + (dir / "bad.yaml").string() + " --out " + (dir / "w.yaml").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("unknown family 'lava'"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "w.yaml"));
}

// The run's files that carry readings and poses: byte-identical between two runs.
void ExpectSameRun(const std::filesystem::path& a, const std::filesystem::path& b) {
  for (const char* file : {"readings.csv", "poses.csv", "profile.ply"}) {
    ASSERT_TRUE(std::filesystem::exists(a / file)) << file;
    EXPECT_EQ(ReadFile(a / file), ReadFile(b / file)) << file;
  }
}

// `room_yaml` written to DIR/room.yaml (DIR a fresh folder `name`), then
// `proxsim generate DIR/room.yaml --out DIR/world.yaml`, and both run into
// DIR/inline and DIR/written, which must be the same run; returns DIR.
std::filesystem::path WriteAndRunBoth(const std::string& name, const std::string& room_yaml) {
  const auto dir = FreshDir(name);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "room.yaml") << room_yaml;
  const std::string room = (dir / "room.yaml").string(), world = (dir / "world.yaml").string();
  auto result = RunProxsim("generate " + room + " --out " + world);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  for (const auto& [scenario, out] : {std::pair{room, "inline"}, std::pair{world, "written"}}) {
    result = RunProxsim("run " + scenario + " --out " + (dir / out).string() + " --no-report");
    EXPECT_EQ(result.exit_code, 0) << result.output;
  }
  ExpectSameRun(dir / "inline", dir / "written");
  return dir;
}

TEST(WorldGenerator, TheWrittenWorldRunsAsTheInlineOneAndThreadsChangeNothing) {
  const auto dir = WriteAndRunBoth(
      "generate_run",
      "proxsim: 1\nduration_s: 3\nrate_hz: 50\n"
      "scene:\n  generate: {kind: room, seed: 11, difficulty: 0.8, size_m: [8, 8]}\n"
      "robot: {model: builtin:biped, on_collision: continue}\n"
      "sensors:\n"
      "  - {name: us, type: ultrasonic, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.15]}, flight_time: true}\n"
      "  - {name: laser, type: laser, link: right_tibia, pose: {xyz_m: [0.06, 0, -0.15]}, beam: {aperture_deg: 10, rays: 7}}\n");
  const std::string world = (dir / "world.yaml").string();
  EXPECT_EQ(ReadFile(world).find("generate"), ReadFile(world).find("generated by proxsim"));
  const auto result = RunProxsim("run " + (dir / "room.yaml").string() + " --out " + (dir / "two").string() +
                                 " --no-report --threads 2");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  ExpectSameRun(dir / "inline", dir / "two");
}

TEST(WorldGenerator, AGeneratedWorldKeepsTheScenesAmbientLight) {
  // the scene's own keys beside generate: ambient_klux (which the VL53L1X's
  // range and error tables read) is kept in the written world, which runs as the inline one
  const auto dir = WriteAndRunBoth(
      "generate_ambient",
      "proxsim: 1\nduration_s: 1\nrate_hz: 10\n"
      "scene:\n  generate: {kind: course, seed: 3, difficulty: 0.2}\n  ambient_klux: 5\n"
      "robot: {model: builtin:biped}\n"
      "sensors:\n  - {name: tof, type: vl53l1x, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.15]}}\n");
  const std::string world = (dir / "world.yaml").string();
  EXPECT_NE(ReadFile(world).find("ambient_klux: 5"), std::string::npos) << ReadFile(world);
}

}  // namespace
}  // namespace proxsim
