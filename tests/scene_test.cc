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

TEST(SceneTest, StairsHaveFloorHoleAndSteps) {
  const Scene scene = MakeBuiltinScene("stairs");
  for (const char* name : {"floor", "hole_bottom", "step_up", "step_down"}) {
    EXPECT_NE(Find(scene, name), nullptr) << name;
  }
}

TEST(SceneTest, StairsRaysStraightDownFindTheTrueHeights) {
  // hole: x 1.3–1.7, |y| < 0.5, bottom z = −0.3; platform: x 3.0–4.5, z = 0.15; else floor z = 0
  const Scene scene = MakeBuiltinScene("stairs");
  RayCaster caster;
  LoadIntoCaster(scene, &caster);
  int in_hole = 0, on_platform = 0, on_floor = 0;
  for (double x = -0.975; x < 6.0; x += 0.1) {
    for (double y = -1.975; y < 2.0; y += 0.1) {
      const auto [z, name] = HeightBelow(caster, scene, x, y);
      if (x > 1.3 && x < 1.7 && std::abs(y) < 0.5) {
        ++in_hole;
        EXPECT_NEAR(z, -0.3, 1e-5) << x << ", " << y;
        EXPECT_EQ(name, "hole_bottom");
      } else if (x > 3.0 && x < 4.5) {
        ++on_platform;
        EXPECT_NEAR(z, 0.15, 1e-5) << x << ", " << y;
        EXPECT_EQ(name, x < 3.75 ? "step_up" : "step_down");
      } else {
        ++on_floor;
        EXPECT_NEAR(z, 0.0, 1e-5) << x << ", " << y;
        EXPECT_EQ(name.rfind("floor", 0), 0u) << name << " at " << x << ", " << y;
      }
    }
  }
  EXPECT_GT(in_hole, 10);
  EXPECT_GT(on_platform, 100);
  EXPECT_GT(on_floor, 1000);
  // the piece the robot starts on is `floor` itself
  EXPECT_EQ(HeightBelow(caster, scene, 0.0, 0.0).second, "floor");
}

TEST(SceneTest, StairsStepEdgesFaceTheRobot) {
  // at ankle height along +x: the rising edge at x = 3; back along −x: the falling edge at x = 4.5
  const Scene scene = MakeBuiltinScene("stairs");
  RayCaster caster;
  LoadIntoCaster(scene, &caster);
  Ray ray;
  ray.origin_W = Vec3f(2.0f, 0, 0.075f);
  ray.max_range_m = 5;
  Hit hit;
  caster.Cast(std::span<const Ray>(&ray, 1), std::span<Hit>(&hit, 1));
  ASSERT_TRUE(hit.is_hit());
  EXPECT_EQ(scene.objects[hit.object_id].name, "step_up");
  EXPECT_NEAR(hit.distance_m, 1.0, 1e-5);
  ray.origin_W = Vec3f(5.0f, 0, 0.075f);
  ray.direction_W = -Vec3f::UnitX();
  caster.Cast(std::span<const Ray>(&ray, 1), std::span<Hit>(&hit, 1));
  ASSERT_TRUE(hit.is_hit());
  EXPECT_EQ(scene.objects[hit.object_id].name, "step_down");
  EXPECT_NEAR(hit.distance_m, 0.5, 1e-5);
}

}  // namespace
}  // namespace proxsim
