// Tests of the built-in scenes: the catalogue, unique names, the objects the
// scenarios and strategies rely on (`floor`, `obstacle`, `hole_bottom`,
// `step_up`, `step_down`), a clear corridor for the robot in the dining
// room, and the heights that rays cast straight down actually find.
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "core/input_error.h"
#include "raycast/ray_caster.h"

namespace proxsim {
namespace {

const SceneObject* Find(const Scene& scene, const std::string& name) {
  for (const SceneObject& object : scene.objects) {
    if (object.name == name) return &object;
  }
  return nullptr;
}

/// A caster holding the whole scene as one world body; object_id = index in scene.objects.
void LoadIntoCaster(const Scene& scene, RayCaster* caster) {
  std::vector<BodyShape> shapes;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    shapes.push_back(BodyShape{scene.objects[i].shape, scene.objects[i].X_WO, static_cast<std::int32_t>(i)});
  }
  caster->AddBody(std::move(shapes), BodyKind::kWorld);
  caster->Commit();
}

/// The world point hit by a ray straight down from (x, y, 3), and the object's name.
std::pair<double, std::string> HeightBelow(const RayCaster& caster, const Scene& scene, double x, double y) {
  Ray ray;
  ray.origin_W = Vec3f(static_cast<float>(x), static_cast<float>(y), 3.0f);
  ray.direction_W = -Vec3f::UnitZ();
  ray.max_range_m = 10.0f;
  Hit hit;
  caster.Cast(std::span<const Ray>(&ray, 1), std::span<Hit>(&hit, 1));
  if (!hit.is_hit()) return {-1e9, ""};
  return {3.0 - hit.distance_m, scene.objects[hit.object_id].name};
}

/// World bounds of a box or cylinder (the box around the cylinder's box).
Eigen::AlignedBox3d WorldBounds(const SceneObject& object) {
  Vec3 half = Vec3::Zero();
  if (const auto* box = std::get_if<Box>(&object.shape)) half = 0.5 * box->size_m;
  if (const auto* cylinder = std::get_if<Cylinder>(&object.shape)) {
    half = Vec3(cylinder->radius_m, cylinder->radius_m, 0.5 * cylinder->length_m);
  }
  Eigen::AlignedBox3d bounds;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 sign((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
    bounds.extend(object.X_WO * half.cwiseProduct(sign));
  }
  return bounds;
}

TEST(SceneTest, CatalogueListsTheThreeBuiltinScenes) {
  const auto& names = BuiltinSceneNames();
  EXPECT_EQ(names, (std::vector<std::string>{"empty", "dining_room", "stairs"}));
  for (const std::string& name : names) EXPECT_NO_THROW(MakeBuiltinScene(name)) << name;
  EXPECT_TRUE(MakeBuiltinScene("empty").objects.empty());
}

TEST(SceneTest, UnknownSceneThrowsInputErrorListingTheKnownOnes) {
  try {
    MakeBuiltinScene("kitchen");
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("kitchen"), std::string::npos) << message;
    EXPECT_NE(message.find("dining_room"), std::string::npos) << message;
  }
}

TEST(SceneTest, ObjectNamesAreUniqueAndMaterialsPlausible) {
  for (const std::string& scene_name : BuiltinSceneNames()) {
    const Scene scene = MakeBuiltinScene(scene_name);
    std::set<std::string> names;
    for (const SceneObject& object : scene.objects) {
      EXPECT_FALSE(object.name.empty());
      EXPECT_TRUE(names.insert(object.name).second) << scene_name << ": duplicate " << object.name;
      EXPECT_GT(object.material.albedo, 0.0) << object.name;
      EXPECT_LE(object.material.albedo, 1.0) << object.name;
      EXPECT_GE(object.material.specular, 0.0) << object.name;
      EXPECT_LE(object.material.specular, 1.0) << object.name;
    }
  }
}

TEST(SceneTest, DiningRoomHasFloorObstacleWallsAndFurniture) {
  const Scene scene = MakeBuiltinScene("dining_room");
  for (const char* name : {"floor", "obstacle", "wall_north", "wall_south", "wall_east", "wall_west",
                           "table_top", "table_leg_1", "table_leg_4", "chair_1_seat", "chair_2_back",
                           "cupboard"}) {
    EXPECT_NE(Find(scene, name), nullptr) << name;
  }
  // the obstacle: 0.20 × 0.30 × 0.15 m, centred at x = 2.5, y = 0, standing on the floor
  const SceneObject* obstacle = Find(scene, "obstacle");
  ASSERT_NE(obstacle, nullptr);
  const auto bounds = WorldBounds(*obstacle);
  EXPECT_TRUE(bounds.min().isApprox(Vec3(2.4, -0.15, 0.0), 1e-12)) << bounds.min().transpose();
  EXPECT_TRUE(bounds.max().isApprox(Vec3(2.6, 0.15, 0.15), 1e-12)) << bounds.max().transpose();
}

TEST(SceneTest, DiningRoomCorridorIsClearButForTheObstacle) {
  // the robot walks along +x from the origin: |y| < 0.5 from x = −0.5 to 3
  const Scene scene = MakeBuiltinScene("dining_room");
  const Eigen::AlignedBox3d corridor(Vec3(-0.5, -0.5, 0.001), Vec3(3.0, 0.5, 2.4));
  for (const SceneObject& object : scene.objects) {
    if (object.name == "floor" || object.name == "obstacle") continue;
    EXPECT_FALSE(WorldBounds(object).intersects(corridor)) << object.name << " is in the corridor";
  }
}

TEST(SceneTest, DiningRoomRaysFindFloorObstacleAndWalls) {
  const Scene scene = MakeBuiltinScene("dining_room");
  RayCaster caster;
  LoadIntoCaster(scene, &caster);

  // down onto the floor, and onto the obstacle's top
  auto [floor_z, floor_name] = HeightBelow(caster, scene, 1.0, 0.2);
  EXPECT_NEAR(floor_z, 0.0, 1e-5);
  EXPECT_EQ(floor_name, "floor");
  auto [top_z, top_name] = HeightBelow(caster, scene, 2.5, 0.0);
  EXPECT_NEAR(top_z, 0.15, 1e-5);
  EXPECT_EQ(top_name, "obstacle");

  // along the corridor at ankle height: the obstacle's near face at x = 2.4
  Ray ray;
  ray.origin_W = Vec3f(0, 0, 0.07f);
  ray.max_range_m = 10;
  Hit hit;
  caster.Cast(std::span<const Ray>(&ray, 1), std::span<Hit>(&hit, 1));
  ASSERT_TRUE(hit.is_hit());
  EXPECT_EQ(scene.objects[hit.object_id].name, "obstacle");
  EXPECT_NEAR(hit.distance_m, 2.4, 1e-5);

  // above the obstacle, the east wall's inner face at x = 5
  ray.origin_W = Vec3f(0, 0, 1.0f);
  caster.Cast(std::span<const Ray>(&ray, 1), std::span<Hit>(&hit, 1));
  ASSERT_TRUE(hit.is_hit());
  EXPECT_EQ(scene.objects[hit.object_id].name, "wall_east");
  EXPECT_NEAR(hit.distance_m, 5.0, 1e-5);
}

TEST(SceneTest, StairsHaveTheCoursePieces) {
  const Scene scene = MakeBuiltinScene("stairs");
  for (const char* name : {"floor", "floor_stair_up_1", "floor_landing", "floor_stair_down_3", "hole_bottom",
                           "floor_between_holes", "wide_hole_bottom", "floor_end"}) {
    EXPECT_NE(Find(scene, name), nullptr) << name;
  }
}

TEST(SceneTest, StairsRaysStraightDownFindTheTrueHeights) {
  // the course as builtin_scenes.cc documents it: [x0, x1) at height z
  struct Level {
    double x0, x1, z;
    const char* name;
  };
  const Level course[] = {{-1.0, 1.0, 0.0, "floor"},
                          {1.0, 1.3, 0.15, "floor_stair_up_1"},
                          {1.3, 1.6, 0.30, "floor_stair_up_2"},
                          {1.6, 1.9, 0.45, "floor_stair_up_3"},
                          {1.9, 3.1, 0.60, "floor_landing"},
                          {3.1, 3.4, 0.45, "floor_stair_down_1"},
                          {3.4, 3.7, 0.30, "floor_stair_down_2"},
                          {3.7, 4.0, 0.15, "floor_stair_down_3"},
                          {4.0, 5.0, 0.0, "floor_after_stairs"},
                          {5.0, 5.25, -0.5, "hole_bottom"},
                          {5.25, 6.5, 0.0, "floor_between_holes"},
                          {6.5, 7.1, -0.5, "wide_hole_bottom"},
                          {7.1, 9.0, 0.0, "floor_end"}};
  const Scene scene = MakeBuiltinScene("stairs");
  RayCaster caster;
  LoadIntoCaster(scene, &caster);
  int checked = 0;
  for (double x = -0.975; x < 9.0; x += 0.05) {
    for (double y = -1.45; y < 1.5; y += 0.3) {
      const Level* level = nullptr;
      for (const Level& l : course) if (x >= l.x0 && x < l.x1) level = &l;
      ASSERT_NE(level, nullptr);
      const auto [z, name] = HeightBelow(caster, scene, x, y);
      EXPECT_NEAR(z, level->z, 1e-5) << x << ", " << y;
      EXPECT_EQ(name, level->name) << x << ", " << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1500);
}

TEST(SceneTest, StairsRisersAndHoleWallsFaceTheRobot) {
  // along +x at 0.1 m above each level: the first riser at x = 1.0, the hole's far wall at 5.25;
  // along −x from the landing, 0.1 m above the floor: the last riser down at x = 4.0
  const Scene scene = MakeBuiltinScene("stairs");
  RayCaster caster;
  LoadIntoCaster(scene, &caster);
  const auto cast = [&](Vec3f origin, Vec3f direction) {
    Ray ray;
    ray.origin_W = origin;
    ray.direction_W = direction;
    ray.max_range_m = 5;
    Hit hit;
    caster.Cast(std::span<const Ray>(&ray, 1), std::span<Hit>(&hit, 1));
    return std::pair{hit.distance_m, hit.is_hit() ? scene.objects[hit.object_id].name : std::string()};
  };
  auto [d, name] = cast(Vec3f(0.5f, 0, 0.1f), Vec3f::UnitX());
  EXPECT_EQ(name, "floor_stair_up_1");
  EXPECT_NEAR(d, 0.5, 1e-5);
  std::tie(d, name) = cast(Vec3f(5.1f, 0, -0.1f), Vec3f::UnitX());
  EXPECT_EQ(name, "floor_between_holes");
  EXPECT_NEAR(d, 0.15, 1e-5);
  std::tie(d, name) = cast(Vec3f(4.5f, 0, 0.1f), -Vec3f::UnitX());
  EXPECT_EQ(name, "floor_stair_down_3");
  EXPECT_NEAR(d, 0.5, 1e-5);
}

}  // namespace
}  // namespace proxsim
