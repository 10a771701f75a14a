// Numerical edge cases of the ray caster (docs/trust.md), closed form. Rays
// along shared edges and through shared vertices of tiled floors are in
// ray_caster_test.cc (RaysThroughSharedVertices*, RaysAlongAFaceDiagonalHit);
// here: a ray starting on a surface, degenerate (zero-area) triangles, a scene
// 1e4 m from the origin, and objects of 1 mm and of 1 km.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <unistd.h>

#include "raycast/ray_caster.h"
#include "scene/mesh_loader.h"

namespace proxsim {
namespace {

Ray EdgeRay(const Vec3& origin_W, const Vec3& direction_W, double max_range_m = 10.0) {
  Ray ray;
  ray.origin_W = origin_W.cast<float>();
  ray.direction_W = direction_W.normalized().cast<float>();
  ray.max_range_m = static_cast<float>(max_range_m);
  return ray;
}

Hit CastEdgeRay(const RayCaster& caster, const Ray& ray) {
  Hit hit;
  caster.Cast(std::span<const Ray>(&ray, 1), std::span<Hit>(&hit, 1));
  return hit;
}

Pose Translated(const Vec3& p) {
  Pose X = Pose::Identity();
  X.translation() = p;
  return X;
}

void ExpectNoNan(const Hit& hit) {
  EXPECT_FALSE(std::isnan(hit.distance_m));
  EXPECT_FALSE(hit.normal_W.hasNaN());
}

// A ray that starts exactly on a surface: Embree's tnear is 0, so the surface
// it starts on is hit at d = 0 whichever way the ray goes. proxsim keeps that
// (no epsilon that would depend on the scene's scale) and warns about such a
// sensor at run time (BadInputTest.SensorOnASurfaceIsAWarning).
TEST(NumericalEdgeTest, RayStartingOnASurfaceGoingAwayHitsItAtZero) {
  // a sensor flush on the top face (z = 0.1) of a box, looking up at a plate
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(1, 1, 0.2)}, Pose::Identity(), 0},
                  BodyShape{Box{Vec3(1, 1, 0.2)}, Translated(Vec3(0, 0, 1.2)), 1}},
                 BodyKind::kWorld);
  caster.Commit();
  const Hit hit = CastEdgeRay(caster, EdgeRay(Vec3(0.1, 0.2, 0.1), Vec3(0, 0, 1)));
  ExpectNoNan(hit);
  ASSERT_TRUE(hit.is_hit());
  EXPECT_EQ(hit.object_id, 0);
  EXPECT_NEAR(hit.distance_m, 0.0f, 1e-6f);  // a few float ulps of the metre scale: Embree's paths differ by CPU
  // a millimetre off the surface it sees the plate, 1 m minus that millimetre away
  const Hit off = CastEdgeRay(caster, EdgeRay(Vec3(0.1, 0.2, 0.101), Vec3(0, 0, 1)));
  ASSERT_TRUE(off.is_hit());
  EXPECT_EQ(off.object_id, 1);
  EXPECT_NEAR(off.distance_m, 0.999, 1e-6);
}

TEST(NumericalEdgeTest, RayStartingOnASurfaceGoingInSeesItAtZeroOrItsFarSide) {
  // from the top face into the box: the surface it starts on (d = 0) or the
  // bottom face from inside (d = 0.2): either is finite, nothing else is right
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(1, 1, 0.2)}, Pose::Identity(), 0}}, BodyKind::kWorld);
  caster.Commit();
  const Hit hit = CastEdgeRay(caster, EdgeRay(Vec3(0.1, 0.2, 0.1), Vec3(0, 0, -1)));
  ExpectNoNan(hit);
  ASSERT_TRUE(hit.is_hit());
  EXPECT_TRUE(std::abs(hit.distance_m) < 1e-6 || std::abs(hit.distance_m - 0.2) < 1e-6) << hit.distance_m;
}

TEST(NumericalEdgeTest, DegenerateTrianglesAreNeverHitAndGiveNoNan) {
  // one good triangle at z = 0 and, beside it, zero-area ones: three collinear
  // vertices, and a triangle naming the same vertex twice
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_O = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0),                    // good
                      Vec3f(2, 0, 0), Vec3f(3, 0, 0), Vec3f(4, 0, 0), Vec3f(2.5f, 1, 0)};  // degenerate
  mesh->triangles = {{0, 1, 2}, {3, 4, 5}, {3, 6, 3}};
  RayCaster caster;
  Mesh shape;
  shape.data = mesh;
  caster.AddBody({BodyShape{shape, Pose::Identity(), 7}}, BodyKind::kWorld);
  caster.Commit();
  // through the good one: exact
  const Hit good = CastEdgeRay(caster, EdgeRay(Vec3(0.2, 0.2, 1), Vec3(0, 0, -1)));
  ASSERT_TRUE(good.is_hit());
  EXPECT_NEAR(good.distance_m, 1.0, 1e-6);
  // along and through the degenerate ones: a miss, never a NaN
  for (const Vec3& target : {Vec3(3, 0, 0), Vec3(2.5, 0, 0), Vec3(2.25, 0.5, 0), Vec3(2, 0, 0)}) {
    for (const Vec3& direction : {Vec3(0, 0, -1), Vec3(0.3, 0.1, -1), Vec3(0, 1, -0.01)}) {
      const Hit hit = CastEdgeRay(caster, EdgeRay(target - direction.normalized(), direction));
      ExpectNoNan(hit);
      EXPECT_FALSE(hit.is_hit()) << "target " << target.transpose() << " distance " << hit.distance_m;
    }
  }
}

TEST(NumericalEdgeTest, MeshLoaderKeepsDegenerateTrianglesHarmlessly) {
  // an OBJ with a zero-area face loads (it is legal), and casting through it gives no NaN
  const auto path = std::filesystem::temp_directory_path() / ("proxsim_test_degenerate_" + std::to_string(getpid()) + ".obj");
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 4 5 4\n";
  const auto mesh = LoadMeshFile(path.string(), Vec3(1, 1, 1));
  EXPECT_GE(mesh->triangles.size(), 1u);
  RayCaster caster;
  Mesh shape;
  shape.data = mesh;
  caster.AddBody({BodyShape{shape, Pose::Identity(), 0}}, BodyKind::kWorld);
  caster.Commit();
  const Hit hit = CastEdgeRay(caster, EdgeRay(Vec3(2.5, 0, 1), Vec3(0, 0, -1)));
  ExpectNoNan(hit);
  EXPECT_FALSE(hit.is_hit());
  std::filesystem::remove(path);
}

// The ray caster works in float (Embree): 1e4 m from the origin a float's
// spacing is 2^-10 m ≈ 0.98 mm, so positions and distances there carry about
// a millimetre of error. Measured here: a box face 1 m ahead of a sensor at
// (1e4, 1e4, 1) m, read at several sub-millimetre offsets.
TEST(NumericalEdgeTest, FarFromTheOriginTheErrorIsAboutOneFloatSpacing) {
  const Vec3 far(1e4, 1e4, 0);
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(0.2, 2, 2)}, Translated(far + Vec3(1.1, 0, 1)), 0}}, BodyKind::kWorld);
  caster.Commit();
  const double spacing_m = std::nextafter(1e4f, 2e4f) - 1e4f;
  EXPECT_NEAR(spacing_m, 0.0009765625, 1e-12);
  double worst_m = 0;
  for (int k = 0; k < 10; ++k) {
    const Vec3 origin = far + Vec3(k * 1e-4, 0.01 * k, 1);  // offsets finer than the float spacing
    const double expected_m = 1.0 - k * 1e-4;               // the face is at x = 1e4 + 1.0
    const Hit hit = CastEdgeRay(caster, EdgeRay(origin, Vec3(1, 0, 0)));
    ASSERT_TRUE(hit.is_hit());
    worst_m = std::max(worst_m, std::abs(hit.distance_m - expected_m));
  }
  // the origin is rounded to the float grid (half a spacing) and the hit too
  EXPECT_LE(worst_m, spacing_m) << "worst distance error " << worst_m << " m";
  RecordProperty("worst_error_m_at_1e4", std::to_string(worst_m));
  std::cout << "[ measured ] distance error 1e4 m from the origin: " << worst_m << " m (float spacing " << spacing_m
            << " m)\n";
}

TEST(NumericalEdgeTest, OneMillimetreObjectsAreHitExactly) {
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(0.001, 0.001, 0.001)}, Translated(Vec3(0.5, 0, 0)), 0},
                  BodyShape{Sphere{0.0005}, Translated(Vec3(0, 0.5, 0)), 1}},
                 BodyKind::kWorld);
  caster.Commit();
  const Hit box = CastEdgeRay(caster, EdgeRay(Vec3::Zero(), Vec3(1, 0, 0)));
  ASSERT_TRUE(box.is_hit());
  EXPECT_NEAR(box.distance_m, 0.4995, 1e-6);
  const Hit sphere = CastEdgeRay(caster, EdgeRay(Vec3::Zero(), Vec3(0, 1, 0)));
  ASSERT_TRUE(sphere.is_hit());
  EXPECT_NEAR(sphere.distance_m, 0.4995, 1e-6);
  // a ray passing 0.6 mm beside the 1 mm box misses it
  EXPECT_FALSE(CastEdgeRay(caster, EdgeRay(Vec3(0, 0.0011, 0), Vec3(1, 0, 0))).is_hit());
}

TEST(NumericalEdgeTest, OneKilometreObjectsAreHitExactly) {
  // a 1 km wall 10 m ahead, and a sphere of radius 1 km whose surface is 3 m ahead
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(1, 1000, 1000)}, Translated(Vec3(10.5, 0, 0)), 0},
                  BodyShape{Sphere{1000}, Translated(Vec3(0, 1003, 0)), 1}},
                 BodyKind::kWorld);
  caster.Commit();
  const Hit wall = CastEdgeRay(caster, EdgeRay(Vec3::Zero(), Vec3(1, 0, 0), 100));
  ASSERT_TRUE(wall.is_hit());
  EXPECT_NEAR(wall.distance_m, 10.0, 1e-5);
  const Hit sphere = CastEdgeRay(caster, EdgeRay(Vec3::Zero(), Vec3(0, 1, 0), 100));
  ASSERT_TRUE(sphere.is_hit());
  EXPECT_NEAR(sphere.distance_m, 3.0, 1e-4);  // float: 1003 m carries 6e-5 m of spacing
}

}  // namespace
}  // namespace proxsim
