// scene/shape_inside.h against closed forms written here: how deep a point
// lies inside a box, sphere, cylinder and a closed cube mesh (inside,
// outside, on the surface), and where a line leaves each shape (a shank's
// front surface for `proxsim inspect`). Pure double arithmetic, no ray
// caster, so the tolerances are rounding (1e-12 m), not Embree's float.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "scene/shape_inside.h"

namespace proxsim {
namespace {

constexpr double kRounding_m = 1e-12;

// A closed cube mesh of side `side_m` centred on the origin, outward winding.
Shape CubeMesh(double side_m) {
  auto mesh = std::make_shared<TriangleMesh>();
  const float h = static_cast<float>(side_m / 2);
  for (int i = 0; i < 8; ++i) mesh->vertices_O.emplace_back(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h);
  // two triangles per face, counter-clockwise seen from outside
  const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    mesh->triangles.push_back({f[0], f[1], f[2]});
    mesh->triangles.push_back({f[0], f[2], f[3]});
  }
  return Mesh{.file = "cube", .scale = Vec3::Ones(), .data = mesh};
}

TEST(ShapeInsideTest, DepthInsidePrimitives) {
  const Shape box = Box{Vec3(0.4, 0.2, 1.0)};
  EXPECT_NEAR(DepthInside_m(box, Vec3::Zero()), 0.1, kRounding_m);               // nearest face: y = ±0.1
  EXPECT_NEAR(DepthInside_m(box, Vec3(0.15, 0, 0)), 0.05, kRounding_m);          // x face 0.2 − 0.15
  EXPECT_NEAR(DepthInside_m(box, Vec3(0.2, 0, 0)), 0.0, kRounding_m);            // on the x face
  EXPECT_NEAR(DepthInside_m(box, Vec3(0.5, 0, 0)), -0.3, kRounding_m);           // 0.3 beyond it
  EXPECT_NEAR(DepthInside_m(box, Vec3(0.5, 0.5, 0)), -std::hypot(0.3, 0.4), kRounding_m);  // off a corner edge
  const Shape sphere = Sphere{0.5};
  EXPECT_NEAR(DepthInside_m(sphere, Vec3(0.3, 0, 0)), 0.2, kRounding_m);
  EXPECT_NEAR(DepthInside_m(sphere, Vec3(0, 0.8, 0)), -0.3, kRounding_m);
  const Shape cylinder = Cylinder{0.05, 0.45};
  EXPECT_NEAR(DepthInside_m(cylinder, Vec3(0.02, 0, 0)), 0.03, kRounding_m);     // radius 0.05 − 0.02
  EXPECT_NEAR(DepthInside_m(cylinder, Vec3(0, 0, 0.2)), 0.025, kRounding_m);     // cap 0.225 − 0.2
  EXPECT_NEAR(DepthInside_m(cylinder, Vec3(0.08, 0, 0)), -0.03, kRounding_m);
  EXPECT_NEAR(DepthInside_m(Plane{}, Vec3(3, 4, -0.2)), -0.2, kRounding_m);      // a plane has no inside
}

TEST(ShapeInsideTest, DepthInsideAClosedMesh) {
  // the cube's vertices are floats: ±0.25 is exact in float
  const Shape cube = CubeMesh(0.5);
  EXPECT_NEAR(DepthInside_m(cube, Vec3::Zero()), 0.25, kRounding_m);
  EXPECT_NEAR(DepthInside_m(cube, Vec3(0.2, 0.1, -0.05)), 0.05, kRounding_m);
  EXPECT_NEAR(DepthInside_m(cube, Vec3(0.25, 0, 0)), 0.0, kRounding_m);
  EXPECT_NEAR(DepthInside_m(cube, Vec3(0.4, 0, 0)), -0.15, kRounding_m);        // beyond its bounding box
  // the cube without its top face: the first of the three rays leaves through
  // the hole (no crossing), the two others through the sides; the majority
  // keeps the centre inside, so one ray through a hole does not decide alone
  auto open = std::make_shared<TriangleMesh>(*std::get<Mesh>(cube).data);
  open->triangles.erase(open->triangles.begin() + 2, open->triangles.begin() + 4);
  const Shape open_cube = Mesh{.file = "open", .scale = Vec3::Ones(), .data = open};
  EXPECT_NEAR(DepthInside_m(open_cube, Vec3::Zero()), 0.25, kRounding_m);
}

TEST(ShapeInsideTest, FarthestAlongALine) {
  const Vec3 x = Vec3::UnitX();
  // a cylinder of radius 0.05 along z: the front along +x from its axis is x = 0.05, at any height within it
  EXPECT_NEAR(*FarthestAlongLine_m(Cylinder{0.05, 0.45}, Vec3(0, 0, -0.1), x), 0.05, kRounding_m);
  // off the axis by y = 0.03: √(0.05² − 0.03²) = 0.04
  EXPECT_NEAR(*FarthestAlongLine_m(Cylinder{0.05, 0.45}, Vec3(0, 0.03, 0), x), 0.04, kRounding_m);
  EXPECT_FALSE(FarthestAlongLine_m(Cylinder{0.05, 0.45}, Vec3(0, 0, 0.3), x));  // above its cap
  EXPECT_NEAR(*FarthestAlongLine_m(Box{Vec3(0.4, 0.2, 1.0)}, Vec3(-1, 0, 0), x), 1.2, kRounding_m);
  // a sphere of radius 0.5 met along a diagonal through its centre: t = 0.5 past the centre
  const Vec3 diagonal = Vec3(1, 1, 0).normalized();
  EXPECT_NEAR(*FarthestAlongLine_m(Sphere{0.5}, -diagonal, diagonal), 1.5, kRounding_m);
  EXPECT_NEAR(*FarthestAlongLine_m(CubeMesh(0.5), Vec3(0, 0.1, 0.1), x), 0.25, kRounding_m);
  EXPECT_FALSE(FarthestAlongLine_m(CubeMesh(0.5), Vec3(0, 0.3, 0), x));
  EXPECT_NEAR(*FarthestAlongLine_m(Plane{}, Vec3(0, 0, 2), -Vec3::UnitZ()), 2.0, kRounding_m);
}

}  // namespace
}  // namespace proxsim
