// Tests of the Embree-backed RayCaster.
//
// Closed forms first (a plane at height h read at pitch θ is h/sin θ, a box
// face at distance d read at yaw θ is d/cos θ, a sphere at c of radius r reads
// c − r ...), then the watertight (robust) mode along shared edges and
// vertices, then equivalence on a random scene: batch = single-ray calls =
// the analytic reference in analytic_intersector.h, and 1 thread = 2 threads
// bit for bit. Last, DistanceToWorld against closed forms, with and without a cap.
#include "raycast/ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <array>
#include <vector>
#include <random>

#include "analytic_intersector.h"

namespace proxsim {
namespace {

using testing::ReferenceCast;
using testing::ReferenceShape;

Ray MakeRay(const Vec3& origin_W, const Vec3& direction_W, double max_range_m = 10.0,
            bool see_robot = true) {
  Ray ray;
  ray.origin_W = origin_W.cast<float>();
  ray.direction_W = direction_W.normalized().cast<float>();
  ray.max_range_m = static_cast<float>(max_range_m);
  ray.see_robot = see_robot;
  return ray;
}

Hit CastOne(const RayCaster& caster, const Ray& ray) {
  Hit hit;
  caster.Cast(std::span<const Ray>(&ray, 1), std::span<Hit>(&hit, 1));
  return hit;
}

Pose Translation(double x, double y, double z) {
  Pose X = Pose::Identity();
  X.translation() = Vec3(x, y, z);
  return X;
}

Pose XyzRpyDeg(double x, double y, double z, double roll, double pitch, double yaw) {
  return PoseFromXyzRpy(Vec3(x, y, z), Vec3(DegToRad(roll), DegToRad(pitch), DegToRad(yaw)));
}

void ExpectNormalNear(const Vec3f& actual, const Vec3& expected, double tolerance = 1e-5) {
  EXPECT_NEAR(actual.norm(), 1.0, 1e-5);
  EXPECT_LT((actual.cast<double>() - expected).norm(), tolerance)
      << "normal " << actual.transpose() << " expected " << expected.transpose();
}

// ---------------------------------------------------------------- closed forms

TEST(RayCasterTest, PlaneAtHeightReadsHeightOverSinPitch) {
  RayCaster caster;
  caster.AddBody({BodyShape{Plane{}, Pose::Identity(), 7}}, BodyKind::kWorld);
  caster.Commit();
  for (double h : {0.05, 0.3, 1.2}) {
    for (double pitch_deg : {5.0, 10.0, 30.0, 60.0, 90.0}) {
      const double pitch = DegToRad(pitch_deg);
      // from above, looking down at pitch θ below the horizontal
      const Hit down = CastOne(caster, MakeRay(Vec3(0.3, -0.2, h), Vec3(std::cos(pitch), 0, -std::sin(pitch)), 50));
      ASSERT_TRUE(down.is_hit()) << "h=" << h << " pitch=" << pitch_deg;
      EXPECT_NEAR(down.distance_m, h / std::sin(pitch), 1e-6 * (1 + h / std::sin(pitch)));
      EXPECT_EQ(down.object_id, 7);
      ExpectNormalNear(down.normal_W, Vec3::UnitZ());
      // from below, looking up: the plane is two-sided
      const Hit up = CastOne(caster, MakeRay(Vec3(0, 0, -h), Vec3(0, std::cos(pitch), std::sin(pitch)), 50));
      ASSERT_TRUE(up.is_hit());
      EXPECT_NEAR(up.distance_m, h / std::sin(pitch), 1e-6 * (1 + h / std::sin(pitch)));
      EXPECT_NEAR(std::abs(up.normal_W.z()), 1.0, 1e-6);
    }
  }
  // parallel to the plane and looking away from it: no hit
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3(0, 0, 0.5), Vec3(1, 0, 0))).is_hit());
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3(0, 0, 0.5), Vec3(0, 0.3, 1))).is_hit());
}

TEST(RayCasterTest, TiltedPlaneNormalIsRotated) {
  // the plane z_O = 0 pitched by 30° about y: normal_W = R·(0,0,1)
  RayCaster caster;
  const Pose X_WO = XyzRpyDeg(2, 0, 0, 0, 30, 0);
  caster.AddBody({BodyShape{Plane{}, X_WO, 1}}, BodyKind::kWorld);
  caster.Commit();
  const Hit hit = CastOne(caster, MakeRay(Vec3(0, 0, 0), Vec3(1, 0, 0)));
  ASSERT_TRUE(hit.is_hit());
  EXPECT_NEAR(hit.distance_m, 2.0, 1e-6);
  ExpectNormalNear(hit.normal_W, X_WO.linear() * Vec3::UnitZ());
}

TEST(RayCasterTest, BoxFaceAtYawReadsDistanceOverCosYaw) {
  // a wall whose near face is the plane x = d
  const double d = 0.5;
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(0.2, 4, 2)}, Translation(d + 0.1, 0, 0), 3}}, BodyKind::kWorld);
  caster.Commit();
  for (double yaw_deg : {0.0, 10.0, 25.0, 45.0, -40.0, 60.0}) {
    const double yaw = DegToRad(yaw_deg);
    const Hit hit = CastOne(caster, MakeRay(Vec3::Zero(), Vec3(std::cos(yaw), std::sin(yaw), 0)));
    ASSERT_TRUE(hit.is_hit()) << "yaw " << yaw_deg;
    EXPECT_NEAR(hit.distance_m, d / std::cos(yaw), 1e-6) << "yaw " << yaw_deg;
    EXPECT_EQ(hit.object_id, 3);
    ExpectNormalNear(hit.normal_W, -Vec3::UnitX());
  }
}

TEST(RayCasterTest, EveryBoxFaceHasItsOutwardNormal) {
  // a rotated box seen along each of its six face normals, from outside
  RayCaster caster;
  const Pose X_WO = XyzRpyDeg(1, 2, 0.5, 20, -35, 70);
  const Vec3 size(0.4, 0.6, 0.8);
  caster.AddBody({BodyShape{Box{size}, X_WO, 0}}, BodyKind::kWorld);
  caster.Commit();
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      Vec3 n_O = Vec3::Zero();
      n_O[axis] = sign;
      const Vec3 n_W = X_WO.linear() * n_O;
      const Vec3 start_W = X_WO * (n_O * (0.5 * size[axis] + 1.0));
      const Hit hit = CastOne(caster, MakeRay(start_W, -n_W));
      ASSERT_TRUE(hit.is_hit()) << "face " << axis << sign;
      EXPECT_NEAR(hit.distance_m, 1.0, 1e-5);
      ExpectNormalNear(hit.normal_W, n_W, 1e-5);
    }
  }
}

TEST(RayCasterTest, SphereReadsCentreDistanceMinusRadius) {
  RayCaster caster;
  caster.AddBody({BodyShape{Sphere{0.1}, Translation(1, 0, 0), 4},
                  BodyShape{Sphere{0.25}, Translation(-1, 2, 0.5), 5}},
                 BodyKind::kWorld);
  caster.Commit();
  // MuJoCo's example: radius 0.1 at x = 1 reads 0.9
  const Hit near = CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX()));
  ASSERT_TRUE(near.is_hit());
  EXPECT_NEAR(near.distance_m, 0.9, 1e-6);
  EXPECT_EQ(near.object_id, 4);
  ExpectNormalNear(near.normal_W, -Vec3::UnitX());

  // an oblique line of sight to the second centre
  const Vec3 origin(0.2, -0.3, 0.1);
  const Vec3 to_centre = Vec3(-1, 2, 0.5) - origin;
  const Hit far = CastOne(caster, MakeRay(origin, to_centre));
  ASSERT_TRUE(far.is_hit());
  EXPECT_NEAR(far.distance_m, to_centre.norm() - 0.25, 1e-5);
  EXPECT_EQ(far.object_id, 5);
  ExpectNormalNear(far.normal_W, -to_centre.normalized());

  // from inside the sphere the ray meets its surface once, at the radius
  const Hit inside = CastOne(caster, MakeRay(Vec3(1, 0, 0), Vec3(0, 0, 1)));
  ASSERT_TRUE(inside.is_hit());
  EXPECT_NEAR(inside.distance_m, 0.1, 1e-6);
}

TEST(RayCasterTest, CylinderSideAndCapHits) {
  // axis along z, radius 0.2, from z = 0 to z = 1, centred at x = 2
  RayCaster caster;
  caster.AddBody({BodyShape{Cylinder{0.2, 1.0}, Translation(2, 0, 0.5), 9}}, BodyKind::kWorld);
  caster.Commit();

  const Hit side = CastOne(caster, MakeRay(Vec3(0, 0, 0.5), Vec3::UnitX()));
  ASSERT_TRUE(side.is_hit());
  EXPECT_NEAR(side.distance_m, 1.8, 1e-6);
  ExpectNormalNear(side.normal_W, -Vec3::UnitX());

  // side, off-centre by y = 0.1: the chord's near end is at x = 2 − √(0.2² − 0.1²)
  const Hit chord = CastOne(caster, MakeRay(Vec3(0, 0.1, 0.3), Vec3::UnitX()));
  ASSERT_TRUE(chord.is_hit());
  const double x_hit = 2 - std::sqrt(0.04 - 0.01);
  EXPECT_NEAR(chord.distance_m, x_hit, 1e-6);
  ExpectNormalNear(chord.normal_W, Vec3(x_hit - 2, 0.1, 0).normalized());

  // top cap from above, bottom cap from below
  const Hit top = CastOne(caster, MakeRay(Vec3(2.05, 0.1, 3), -Vec3::UnitZ()));
  ASSERT_TRUE(top.is_hit());
  EXPECT_NEAR(top.distance_m, 2.0, 1e-6);
  ExpectNormalNear(top.normal_W, Vec3::UnitZ());
  const Hit bottom = CastOne(caster, MakeRay(Vec3(1.9, 0, -0.5), Vec3::UnitZ()));
  ASSERT_TRUE(bottom.is_hit());
  EXPECT_NEAR(bottom.distance_m, 0.5, 1e-6);
  ExpectNormalNear(bottom.normal_W, -Vec3::UnitZ());

  // just above the top cap, passing over it: a miss
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3(0, 0, 1.01), Vec3::UnitX())).is_hit());
  // just beside it
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3(0, 0.21, 0.5), Vec3::UnitX())).is_hit());
}

TEST(RayCasterTest, LyingCylinderCapIsHitAlongItsAxis) {
  // pitched 90°: its axis is world x, so a ray along x meets the flat cap
  RayCaster caster;
  caster.AddBody({BodyShape{Cylinder{0.1, 0.6}, XyzRpyDeg(1, 0, 0, 0, 90, 0), 2}}, BodyKind::kWorld);
  caster.Commit();
  const Hit hit = CastOne(caster, MakeRay(Vec3(0, 0.05, 0), Vec3::UnitX()));
  ASSERT_TRUE(hit.is_hit());
  EXPECT_NEAR(hit.distance_m, 0.7, 1e-6);
  ExpectNormalNear(hit.normal_W, -Vec3::UnitX());
}

TEST(RayCasterTest, RaysThatMissReportInfinityAndNoObject) {
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(1, 1, 1)}, Translation(3, 0, 0), 0},
                  BodyShape{Sphere{0.5}, Translation(0, 3, 0), 1}},
                 BodyKind::kWorld);
  caster.Commit();
  for (const Vec3& direction : {Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(1, 1, 0)}) {
    const Hit hit = CastOne(caster, MakeRay(Vec3::Zero(), direction));
    EXPECT_FALSE(hit.is_hit());
    EXPECT_EQ(hit.object_id, -1);
    EXPECT_TRUE(std::isinf(hit.distance_m));
  }
}

TEST(RayCasterTest, EmptyCasterMissesEverything) {
  RayCaster caster;
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX())).is_hit());
  EXPECT_EQ(caster.triangle_count(), 0u);
}

TEST(RayCasterTest, EmptyMeshIsAcceptedAndNeverHit) {
  RayCaster caster;
  Mesh mesh;
  mesh.data = std::make_shared<TriangleMesh>();
  caster.AddBody({BodyShape{mesh, Pose::Identity(), 0}, BodyShape{Sphere{0.5}, Translation(2, 0, 0), 1}},
                 BodyKind::kWorld);
  caster.Commit();
  EXPECT_EQ(CastOne(caster, MakeRay(Vec3(-1, 0, 0), Vec3::UnitX())).object_id, 1);
  EXPECT_NEAR(caster.DistanceToWorld(Vec3::Zero(), std::vector<std::int32_t>{}), 1.5, 1e-9);
}

TEST(RayCasterTest, HitBeyondMaxRangeIsAMiss) {
  RayCaster caster;
  caster.AddBody({BodyShape{Sphere{0.1}, Translation(1, 0, 0), 0},
                  BodyShape{Box{Vec3(2, 0.2, 2)}, Translation(0, -1.1, 0), 1},
                  BodyShape{Plane{}, Translation(0, 0, -0.5), 2}},
                 BodyKind::kWorld);
  caster.Commit();
  // sphere at 0.9, box face at 1.0 (along −y), plane at 0.5 (along −z)
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX(), 0.89)).is_hit());
  EXPECT_TRUE(CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX(), 0.91)).is_hit());
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3::Zero(), -Vec3::UnitY(), 0.99)).is_hit());
  EXPECT_TRUE(CastOne(caster, MakeRay(Vec3::Zero(), -Vec3::UnitY(), 1.01)).is_hit());
  EXPECT_FALSE(CastOne(caster, MakeRay(Vec3::Zero(), -Vec3::UnitZ(), 0.49)).is_hit());
  EXPECT_TRUE(CastOne(caster, MakeRay(Vec3::Zero(), -Vec3::UnitZ(), 0.51)).is_hit());
}

TEST(RayCasterTest, NearestOfSeveralShapesWins) {
  // a sphere in front of a wall, a cylinder behind it
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(0.1, 3, 3)}, Translation(2, 0, 0), 10},
                  BodyShape{Cylinder{0.3, 2}, Translation(3, 0, 0), 11},
                  BodyShape{Sphere{0.2}, Translation(1, 0, 0), 12}},
                 BodyKind::kWorld);
  caster.Commit();
  EXPECT_EQ(CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX())).object_id, 12);
  EXPECT_EQ(CastOne(caster, MakeRay(Vec3(0, 0.5, 0), Vec3::UnitX())).object_id, 10);
  EXPECT_EQ(CastOne(caster, MakeRay(Vec3(5, 0, 0), -Vec3::UnitX())).object_id, 11);
}

// ---------------------------------------------------------------- moving bodies

TEST(RayCasterTest, MovedBodyIsHitAtItsNewPlaceWithRotatedNormal) {
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(0.1, 10, 10)}, Translation(20, 0, 0), 0}}, BodyKind::kWorld);
  // a thin plate, its face normal −x_B, and a cylinder with its axis along z_B
  const int link = caster.AddBody({BodyShape{Box{Vec3(0.1, 1, 1)}, Pose::Identity(), 1},
                                   BodyShape{Cylinder{0.1, 0.4}, Translation(0, 0, 1), 2}},
                                  BodyKind::kRobot, Translation(2, 0, 0));
  caster.Commit();
  Hit hit = CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX()));
  ASSERT_EQ(hit.object_id, 1);
  EXPECT_NEAR(hit.distance_m, 1.95, 1e-6);
  ExpectNormalNear(hit.normal_W, -Vec3::UnitX());

  // yaw the body by 90° and put it at y = 2: x_B is now +y_W
  caster.SetBodyPose(link, XyzRpyDeg(0, 2, 0, 0, 0, 90));
  caster.Commit();
  hit = CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX(), 30));
  EXPECT_EQ(hit.object_id, 0) << "the plate left the x axis; the far wall is seen";
  hit = CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitY()));
  ASSERT_EQ(hit.object_id, 1);
  EXPECT_NEAR(hit.distance_m, 1.95, 1e-6);
  ExpectNormalNear(hit.normal_W, -Vec3::UnitY());

  // roll it by 90° instead: the cylinder's axis z_B becomes −y_W, at y = −1 from the body
  caster.SetBodyPose(link, XyzRpyDeg(2, 0, 0, 90, 0, 0));
  caster.Commit();
  hit = CastOne(caster, MakeRay(Vec3(2, 0, 0), -Vec3::UnitY()));
  ASSERT_EQ(hit.object_id, 1) << "starting inside the plate, its far face";
  hit = CastOne(caster, MakeRay(Vec3(2.05, -3, 0), Vec3::UnitY()));
  ASSERT_EQ(hit.object_id, 2) << "the cylinder's cap, now facing −y";
  EXPECT_NEAR(hit.distance_m, 3 - 1.2, 1e-5);
  ExpectNormalNear(hit.normal_W, -Vec3::UnitY());
  hit = CastOne(caster, MakeRay(Vec3(2, -1, 3), -Vec3::UnitZ()));
  ASSERT_EQ(hit.object_id, 2) << "the cylinder's side, from above";
  EXPECT_NEAR(hit.distance_m, 2.9, 1e-5);
  ExpectNormalNear(hit.normal_W, Vec3::UnitZ());
}

TEST(RayCasterTest, RaysThatIgnoreTheRobotPassThroughItsBodies) {
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(0.2, 4, 4)}, Translation(3, 0, 0), 0}}, BodyKind::kWorld);
  caster.AddBody({BodyShape{Sphere{0.2}, Pose::Identity(), 1}}, BodyKind::kRobot, Translation(1, 0, 0));
  caster.Commit();
  const Hit seen = CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX(), 10, /*see_robot=*/true));
  EXPECT_EQ(seen.object_id, 1);
  EXPECT_NEAR(seen.distance_m, 0.8, 1e-6);
  const Hit through = CastOne(caster, MakeRay(Vec3::Zero(), Vec3::UnitX(), 10, /*see_robot=*/false));
  EXPECT_EQ(through.object_id, 0);
  EXPECT_NEAR(through.distance_m, 2.9, 1e-6);
}

// The world is cast first (straight into its scene when it is one body at the
// identity, through instances otherwise), then the robot up to the world hit:
// the nearer surface wins in every layout, and a moved link is seen moved.
TEST(RayCasterTest, TheNearerOfWorldAndRobotWinsWhateverTheWorldsLayout) {
  for (int layout = 0; layout < 3; ++layout) {
    SCOPED_TRACE(layout == 0 ? "one world body at the identity" : layout == 1 ? "one posed world body" : "two world bodies");
    RayCaster caster;
    // a wall whose near face is at x = 2.9, as one body or split in two (y < 0 and y > 0)
    if (layout == 0) {
      caster.AddBody({BodyShape{Box{Vec3(0.2, 4, 4)}, Translation(3, 0, 0), 0}}, BodyKind::kWorld);
    } else if (layout == 1) {
      caster.AddBody({BodyShape{Box{Vec3(0.2, 4, 4)}, Pose::Identity(), 0}}, BodyKind::kWorld, Translation(3, 0, 0));
    } else {
      caster.AddBody({BodyShape{Box{Vec3(0.2, 2, 4)}, Translation(3, -1, 0), 0}}, BodyKind::kWorld);
      caster.AddBody({BodyShape{Box{Vec3(0.2, 2, 4)}, Translation(3, 1, 0), 0}}, BodyKind::kWorld);
    }
    // a link in front of the wall on y = 0.5, another behind it on y = -0.5
    const int front = caster.AddBody({BodyShape{Sphere{0.2}, Pose::Identity(), 7}}, BodyKind::kRobot,
                                     Translation(1, 0.5, 0));
    caster.AddBody({BodyShape{Sphere{0.2}, Pose::Identity(), 8}}, BodyKind::kRobot, Translation(5, -0.5, 0));
    caster.Commit();

    Hit hit = CastOne(caster, MakeRay(Vec3(0, 0.5, 0), Vec3::UnitX(), 10));
    EXPECT_EQ(hit.object_id, 7);
    EXPECT_NEAR(hit.distance_m, 0.8, 1e-6);
    ExpectNormalNear(hit.normal_W, -Vec3::UnitX());
    hit = CastOne(caster, MakeRay(Vec3(0, -0.5, 0), Vec3::UnitX(), 10));
    EXPECT_EQ(hit.object_id, 0) << "the link behind the wall is hidden";
    EXPECT_NEAR(hit.distance_m, 2.9, 1e-6);
    ExpectNormalNear(hit.normal_W, -Vec3::UnitX());
    hit = CastOne(caster, MakeRay(Vec3(0, 0.5, 0), Vec3::UnitX(), 0.5));
    EXPECT_FALSE(hit.is_hit()) << "both beyond the range";

    // the front link moves out of the way, then comes back nearer
    caster.SetBodyPose(front, Translation(1, 3, 0));
    caster.Commit();
    hit = CastOne(caster, MakeRay(Vec3(0, 0.5, 0), Vec3::UnitX(), 10));
    EXPECT_EQ(hit.object_id, 0);
    EXPECT_NEAR(hit.distance_m, 2.9, 1e-6);
    caster.SetBodyPose(front, Translation(0.5, 0.5, 0));
    caster.Commit();
    hit = CastOne(caster, MakeRay(Vec3(0, 0.5, 0), Vec3::UnitX(), 10));
    EXPECT_EQ(hit.object_id, 7);
    EXPECT_NEAR(hit.distance_m, 0.3, 1e-6);
  }
}

// ---------------------------------------------------------------- robust mode

TEST(RayCasterTest, RaysAlongAFaceDiagonalHit) {
  // a posed box; rays aimed at points on both diagonals of each face (one of
  // them is the edge the face's two triangles share), straight in and oblique
  RayCaster caster;
  const Pose X_WO = XyzRpyDeg(0.3, -0.2, 0.7, 10, 20, 30);
  const Vec3 size(0.8, 0.6, 0.4);
  caster.AddBody({BodyShape{Box{size}, X_WO, 5}}, BodyKind::kWorld);
  caster.Commit();
  int rays = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (double sign : {-1.0, 1.0}) {
      for (double diagonal : {-1.0, 1.0}) {
        for (int k = 1; k < 40; ++k) {
          const double s = -0.5 + k / 40.0;
          Vec3 p_O = Vec3::Zero();
          p_O[axis] = sign * 0.5 * size[axis];
          p_O[u] = s * size[u];
          p_O[v] = diagonal * s * size[v];
          Vec3 n_O = Vec3::Zero();
          n_O[axis] = sign;
          for (const Vec3& tilt_O : {Vec3(0, 0, 0), Vec3(0.3, -0.2, 0.1)}) {
            const Vec3 in_O = (-n_O + tilt_O - tilt_O[axis] * Vec3::Unit(axis)).normalized();
            const Vec3 target_W = X_WO * p_O;
            const Vec3 direction_W = X_WO.linear() * in_O;
            const Hit hit = CastOne(caster, MakeRay(target_W - 2 * direction_W, direction_W));
            ++rays;
            ASSERT_TRUE(hit.is_hit()) << "axis " << axis << " sign " << sign << " s " << s;
            EXPECT_NEAR(hit.distance_m, 2.0, 1e-5);
          }
        }
      }
    }
  }
  EXPECT_EQ(rays, 3 * 2 * 2 * 39 * 2);
}

/// A floor of n×n square tiles of side `tile_m`, tops at z = 0, from (0, 0).
std::vector<BodyShape> TiledBoxFloor(int n, double tile_m) {
  std::vector<BodyShape> tiles;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      tiles.push_back(BodyShape{Box{Vec3(tile_m, tile_m, 0.1)},
                                Translation((i + 0.5) * tile_m, (j + 0.5) * tile_m, -0.05),
                                i * n + j});
    }
  }
  return tiles;
}

/// The same floor as one mesh; `shared` makes neighbouring squares share vertices.
std::shared_ptr<TriangleMesh> GridMesh(int n, double tile_m, bool shared) {
  auto mesh = std::make_shared<TriangleMesh>();
  auto vertex = [&](int i, int j) -> std::uint32_t {
    if (shared) return static_cast<std::uint32_t>(i * (n + 1) + j);
    mesh->vertices_O.emplace_back(static_cast<float>(i * tile_m), static_cast<float>(j * tile_m), 0.0f);
    return static_cast<std::uint32_t>(mesh->vertices_O.size() - 1);
  };
  if (shared) {
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        mesh->vertices_O.emplace_back(static_cast<float>(i * tile_m), static_cast<float>(j * tile_m), 0.0f);
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const std::uint32_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      // alternate the diagonal so that both kinds of vertex fan are tested
      if ((i + j) % 2 == 0) {
        mesh->triangles.push_back({a, b, c});
        mesh->triangles.push_back({a, c, d});
      } else {
        mesh->triangles.push_back({a, b, d});
        mesh->triangles.push_back({b, c, d});
      }
    }
  }
  return mesh;
}

/// Casts rays through every vertex of the n×n grid (straight down and
/// oblique) and along the grid lines; every one must hit at the expected distance.
void ExpectGridIsWatertight(const RayCaster& caster, int n, double tile_m) {
  const Vec3 directions[] = {Vec3(0, 0, -1), Vec3(0.3, 0.2, -1).normalized(),
                             Vec3(-0.7, 0.1, -0.3).normalized(), Vec3(1, 1, -1).normalized()};
  int misses = 0, rays = 0;
  for (int i = 1; i < n; ++i) {
    for (int j = 1; j < n; ++j) {
      for (double offset : {0.0, 0.37}) {
        const Vec3 target(i * tile_m, (j + offset) * tile_m, 0);  // a vertex, then a point on an edge
        for (const Vec3& direction : directions) {
          const Hit hit = CastOne(caster, MakeRay(target - 1.5 * direction, direction));
          ++rays;
          if (!hit.is_hit() || std::abs(hit.distance_m - 1.5) > 1e-5) ++misses;
        }
      }
    }
  }
  EXPECT_EQ(misses, 0) << "of " << rays << " rays through shared vertices and edges";
}

TEST(RayCasterTest, RaysThroughSharedVerticesOfTiledBoxFloorHit) {
  RayCaster caster;
  caster.AddBody(TiledBoxFloor(8, 0.5), BodyKind::kWorld);
  caster.Commit();
  ExpectGridIsWatertight(caster, 8, 0.5);
}

TEST(RayCasterTest, RaysThroughSharedVerticesOfMeshFloorHit) {
  for (bool shared : {true, false}) {
    RayCaster caster;
    Mesh mesh;
    mesh.data = GridMesh(10, 0.3, shared);
    caster.AddBody({BodyShape{mesh, Pose::Identity(), 0}}, BodyKind::kWorld);
    caster.Commit();
    EXPECT_EQ(caster.triangle_count(), 200u);
    SCOPED_TRACE(shared ? "shared vertices" : "duplicated vertices");
    ExpectGridIsWatertight(caster, 10, 0.3);
  }
}

// ---------------------------------------------------------------- equivalence

/// Deterministic uniform doubles from mt19937 (whose output the standard fixes).
class Uniform {
 public:
  explicit Uniform(unsigned seed) : engine_(seed) {}
  double operator()(double lo, double hi) {
    const double u = static_cast<double>(engine_()) / 4294967296.0;
    return lo + (hi - lo) * u;
  }

 private:
  std::mt19937 engine_;
};

/// True when p_W is inside a solid shape of the reference scene.
bool InsideAnySolid(const std::vector<ReferenceShape>& shapes, const Vec3& p_W, double margin_m) {
  for (const ReferenceShape& s : shapes) {
    const Vec3 p_O = s.X_WO.inverse() * p_W;
    if (const auto* box = std::get_if<Box>(&s.shape)) {
      if ((p_O.cwiseAbs() - 0.5 * box->size_m).maxCoeff() < margin_m) return true;
    } else if (const auto* sphere = std::get_if<Sphere>(&s.shape)) {
      if (p_O.norm() < sphere->radius_m + margin_m) return true;
    } else if (const auto* cylinder = std::get_if<Cylinder>(&s.shape)) {
      if (p_O.head<2>().norm() < cylinder->radius_m + margin_m &&
          std::abs(p_O.z()) < cylinder->length_m / 2 + margin_m) {
        return true;
      }
    }
  }
  return false;
}

/// A random scene spread over four bodies (two world, two robot), and random
/// rays that start outside every solid.
struct RandomScene {
  RayCaster caster;
  std::vector<ReferenceShape> reference;
  std::vector<Ray> rays;
};

void BuildRandomScene(RandomScene* scene, unsigned seed, int ray_count) {
  Uniform uniform(seed);
  auto random_pose = [&](double spread_m) {
    return XyzRpyDeg(uniform(-spread_m, spread_m), uniform(-spread_m, spread_m), uniform(0, 2),
                     uniform(-180, 180), uniform(-90, 90), uniform(-180, 180));
  };
  std::int32_t next_id = 0;
  for (int b = 0; b < 4; ++b) {
    const BodyKind kind = b < 2 ? BodyKind::kWorld : BodyKind::kRobot;
    const Pose X_WB = random_pose(1.0);
    std::vector<BodyShape> shapes;
    for (int s = 0; s < 10; ++s) {
      Shape shape;
      switch (s % 3) {
        case 0: shape = Box{Vec3(uniform(0.1, 1), uniform(0.1, 1), uniform(0.1, 1))}; break;
        case 1: shape = Sphere{uniform(0.05, 0.6)}; break;
        default: shape = Cylinder{uniform(0.05, 0.5), uniform(0.1, 1.2)}; break;
      }
      shapes.push_back(BodyShape{shape, random_pose(4.0), next_id++});
    }
    if (b == 0) shapes.push_back(BodyShape{Plane{}, XyzRpyDeg(0, 0, -1, 3, -4, 0), next_id++});
    if (b == 1) shapes.push_back(BodyShape{Plane{}, XyzRpyDeg(9, 0, 0, 0, 80, 10), next_id++});
    for (const BodyShape& s : shapes) scene->reference.push_back(ReferenceShape{s.shape, X_WB * s.X_BO, s.object_id});
    scene->caster.AddBody(std::move(shapes), kind, X_WB);
  }
  scene->caster.Commit();

  while (static_cast<int>(scene->rays.size()) < ray_count) {
    const Vec3 origin(uniform(-6, 6), uniform(-6, 6), uniform(-0.5, 3));
    if (InsideAnySolid(scene->reference, origin, 1e-3)) continue;
    const Vec3 direction(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    if (direction.norm() < 0.1 || direction.norm() > 1) continue;  // uniform over the sphere
    scene->rays.push_back(MakeRay(origin, direction, 15));
  }
}

TEST(RayCasterTest, BatchEqualsSingleCallsAndTheAnalyticReference) {
  RandomScene scene;
  BuildRandomScene(&scene, 20240611u, 3000);
  scene.caster.set_threads(2);
  std::vector<Hit> batch(scene.rays.size());
  scene.caster.Cast(scene.rays, batch);

  int hits = 0, mismatches = 0;
  std::vector<int> hits_per_object(scene.reference.size(), 0);
  for (std::size_t i = 0; i < scene.rays.size(); ++i) {
    const Ray& ray = scene.rays[i];
    // (a) one call per ray gives the same bits
    const Hit single = CastOne(scene.caster, ray);
    ASSERT_EQ(std::memcmp(&single.distance_m, &batch[i].distance_m, sizeof(float)), 0) << "ray " << i;
    ASSERT_EQ(single.object_id, batch[i].object_id);
    ASSERT_EQ(single.normal_W, batch[i].normal_W);

    // (b) the analytic reference, in double, from the same float ray
    const auto expected = ReferenceCast(scene.reference, ray.origin_W.cast<double>(),
                                        ray.direction_W.cast<double>(), ray.max_range_m);
    const Hit& hit = batch[i];
    if (hit.object_id != expected.object_id ||
        (hit.is_hit() && (std::abs(hit.distance_m - expected.distance_m) > 1e-4 ||
                          (hit.normal_W.cast<double>() - expected.normal_W).norm() > 1e-3))) {
      ++mismatches;
      ADD_FAILURE() << "ray " << i << ": embree id " << hit.object_id << " d " << hit.distance_m
                    << " n " << hit.normal_W.transpose() << "; reference id " << expected.object_id
                    << " d " << expected.distance_m << " n " << expected.normal_W.transpose();
      if (mismatches > 10) break;
    }
    if (hit.is_hit()) {
      ++hits;
      ++hits_per_object[hit.object_id];
    }
  }
  // the test means something only if most rays hit, and many shapes are hit
  EXPECT_GT(hits, 1500);
  EXPECT_GT(std::count_if(hits_per_object.begin(), hits_per_object.end(), [](int n) { return n > 0; }), 30);
}

TEST(RayCasterTest, OneThreadEqualsTwoThreadsBitForBit) {
  RandomScene scene;
  BuildRandomScene(&scene, 77u, 4096);
  std::vector<Hit> one(scene.rays.size()), two(scene.rays.size());
  scene.caster.set_threads(1);
  scene.caster.Cast(scene.rays, one);
  scene.caster.set_threads(2);
  scene.caster.Cast(scene.rays, two);
  int hits = 0;
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(std::memcmp(&one[i].distance_m, &two[i].distance_m, sizeof(float)), 0) << "ray " << i;
    ASSERT_EQ(std::memcmp(one[i].normal_W.data(), two[i].normal_W.data(), 3 * sizeof(float)), 0);
    ASSERT_EQ(one[i].object_id, two[i].object_id);
    hits += one[i].is_hit();
  }
  EXPECT_GT(hits, 2000);
}

TEST(RayCasterTest, SeeRobotFalseMatchesReferenceWithoutRobotBodies) {
  RandomScene scene;
  BuildRandomScene(&scene, 5u, 1000);
  // the robot bodies are the last two; their ids follow the world's
  std::vector<ReferenceShape> world_only;
  for (const ReferenceShape& s : scene.reference) {
    if (s.object_id <= 21) world_only.push_back(s);  // 2 world bodies × (10 shapes + 1 plane)
  }
  std::vector<Ray> rays = scene.rays;
  for (Ray& ray : rays) ray.see_robot = false;
  std::vector<Hit> hits(rays.size());
  scene.caster.Cast(rays, hits);
  int robot_seen_otherwise = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto expected = ReferenceCast(world_only, rays[i].origin_W.cast<double>(),
                                        rays[i].direction_W.cast<double>(), rays[i].max_range_m);
    ASSERT_EQ(hits[i].object_id, expected.object_id) << "ray " << i;
    if (hits[i].is_hit()) {
      EXPECT_NEAR(hits[i].distance_m, expected.distance_m, 1e-4);
    }
    const auto with_robot = ReferenceCast(scene.reference, rays[i].origin_W.cast<double>(),
                                          rays[i].direction_W.cast<double>(), rays[i].max_range_m);
    robot_seen_otherwise += with_robot.object_id > 21;
  }
  EXPECT_GT(robot_seen_otherwise, 20) << "the robot bodies should block many of these rays";
}

// ---------------------------------------------------------------- DistanceToWorld

TEST(RayCasterTest, DistanceToBoxInItsFrame) {
  RayCaster caster;
  const Pose X_WO = XyzRpyDeg(1, 2, 0.5, 0, 0, 30);
  const Vec3 half(0.5, 0.25, 0.1);
  caster.AddBody({BodyShape{Box{2 * half}, X_WO, 0}}, BodyKind::kWorld);
  caster.Commit();
  const std::vector<std::int32_t> none;
  // off a face, off an edge, off a corner, inside
  EXPECT_NEAR(caster.DistanceToWorld(X_WO * Vec3(0.8, 0, 0), none), 0.3, 1e-9);
  EXPECT_NEAR(caster.DistanceToWorld(X_WO * Vec3(0.8, 0.65, 0), none), std::hypot(0.3, 0.4), 1e-9);
  EXPECT_NEAR(caster.DistanceToWorld(X_WO * Vec3(-0.6, -0.35, 0.3), none), std::sqrt(0.01 + 0.01 + 0.04), 1e-9);
  EXPECT_EQ(caster.DistanceToWorld(X_WO * Vec3(0.1, 0.1, 0), none), 0.0);
}

TEST(RayCasterTest, DistanceToSphereCylinderAndPlane) {
  const std::vector<std::int32_t> none;
  {
    RayCaster caster;
    caster.AddBody({BodyShape{Sphere{0.3}, Translation(1, 1, 1), 0}}, BodyKind::kWorld);
    caster.Commit();
    EXPECT_NEAR(caster.DistanceToWorld(Vec3(0, 0, 0), none), std::sqrt(3.0) - 0.3, 1e-9);
    EXPECT_EQ(caster.DistanceToWorld(Vec3(1.1, 1, 1), none), 0.0);
  }
  {
    // a cylinder lying along world x (pitched 90°), radius 0.2, length 1, centred at the origin
    RayCaster caster;
    caster.AddBody({BodyShape{Cylinder{0.2, 1.0}, XyzRpyDeg(0, 0, 0, 0, 90, 0), 0}}, BodyKind::kWorld);
    caster.Commit();
    EXPECT_NEAR(caster.DistanceToWorld(Vec3(0.1, 0.5, 0), none), 0.3, 1e-9);          // side
    EXPECT_NEAR(caster.DistanceToWorld(Vec3(-0.9, 0.05, 0.05), none), 0.4, 1e-9);     // cap
    EXPECT_NEAR(caster.DistanceToWorld(Vec3(0.8, 0, 0.6), none), std::hypot(0.3, 0.4), 1e-9);  // rim
    EXPECT_EQ(caster.DistanceToWorld(Vec3(0.4, 0.1, 0), none), 0.0);                  // inside
  }
  {
    RayCaster caster;
    const Pose X_WO = XyzRpyDeg(0, 0, 0.5, 0, 45, 0);
    caster.AddBody({BodyShape{Plane{}, X_WO, 0}}, BodyKind::kWorld);
    caster.Commit();
    EXPECT_NEAR(caster.DistanceToWorld(X_WO * Vec3(3, -2, 0.7), none), 0.7, 1e-9);
    EXPECT_NEAR(caster.DistanceToWorld(X_WO * Vec3(-1e6, 5, -0.2), none), 0.2, 1e-6) << "unbounded";
  }
}

TEST(RayCasterTest, DistanceToMeshUsesItsTriangles) {
  // a tetrahedron with corners at the origin and on the three axes, posed twice over
  auto tetrahedron = std::make_shared<TriangleMesh>();
  tetrahedron->vertices_O = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0), Vec3f(0, 0, 1)};
  tetrahedron->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  Mesh mesh;
  mesh.data = tetrahedron;
  const Pose X_WB = XyzRpyDeg(1, 0, 0, 0, 0, 90);
  const Pose X_BO = XyzRpyDeg(0, 0, 2, 30, 0, 0);
  RayCaster caster;
  caster.AddBody({BodyShape{mesh, X_BO, 4}}, BodyKind::kWorld, X_WB);
  caster.Commit();
  EXPECT_EQ(caster.triangle_count(), 4u);
  const Pose X_WO = X_WB * X_BO;
  const std::vector<std::int32_t> none;
  // below the z = 0 face, over its interior
  EXPECT_NEAR(caster.DistanceToWorld(X_WO * Vec3(0.2, 0.2, -0.5), none), 0.5, 1e-6);
  // beyond the corner (1, 0, 0), along x
  EXPECT_NEAR(caster.DistanceToWorld(X_WO * Vec3(1.7, 0, 0), none), 0.7, 1e-6);
  // off the slanted face x + y + z = 1, along its normal
  const Vec3 centroid(1.0 / 3, 1.0 / 3, 1.0 / 3);
  EXPECT_NEAR(caster.DistanceToWorld(X_WO * (centroid + 0.4 * Vec3(1, 1, 1).normalized()), none), 0.4, 1e-6);
  // a mesh has no inside: from (¼, ¼, ¼) the nearest face is the slanted one, (1 − ¾)/√3 away
  EXPECT_NEAR(caster.DistanceToWorld(X_WO * Vec3(0.25, 0.25, 0.25), none), 0.25 / std::sqrt(3.0), 1e-6);
  // and it can be excluded
  const std::vector<std::int32_t> mesh_id{4};
  EXPECT_TRUE(std::isinf(caster.DistanceToWorld(Vec3::Zero(), mesh_id)));
}

TEST(RayCasterTest, DistanceToWorldTakesTheNearestNotExcludedWorldShape) {
  RayCaster caster;
  caster.AddBody({BodyShape{Sphere{0.5}, Translation(2, 0, 0), 0}}, BodyKind::kWorld);
  caster.AddBody({BodyShape{Box{Vec3(1, 1, 1)}, Translation(0, 3, 0), 1},
                  BodyShape{Plane{}, Translation(0, 0, -4), 2}},
                 BodyKind::kWorld);
  caster.AddBody({BodyShape{Sphere{0.1}, Pose::Identity(), 3}}, BodyKind::kRobot, Translation(0.5, 0, 0));
  caster.Commit();
  const Vec3 p_W = Vec3::Zero();
  EXPECT_NEAR(caster.DistanceToWorld(p_W, std::vector<std::int32_t>{}), 1.5, 1e-9) << "robot bodies never count";
  EXPECT_NEAR(caster.DistanceToWorld(p_W, std::vector<std::int32_t>{0}), 2.5, 1e-9);
  EXPECT_NEAR(caster.DistanceToWorld(p_W, std::vector<std::int32_t>{0, 1}), 4.0, 1e-9);
  EXPECT_TRUE(std::isinf(caster.DistanceToWorld(p_W, std::vector<std::int32_t>{0, 1, 2})));
}

// A cap answers min(distance, cap): the exact distance below it, the cap itself above.
TEST(RayCasterTest, DistanceToWorldWithACapIsExactBelowItAndTheCapAbove) {
  const std::vector<std::int32_t> none;
  {
    // a box face 0.3 away (closed form), under and over caps
    RayCaster caster;
    const Pose X_WO = XyzRpyDeg(1, 2, 0.5, 0, 0, 30);
    caster.AddBody({BodyShape{Box{Vec3(1, 0.5, 0.2)}, X_WO, 0}}, BodyKind::kWorld);
    caster.Commit();
    const Vec3 p_W = X_WO * Vec3(0.8, 0, 0);
    EXPECT_NEAR(caster.DistanceToWorld(p_W, none, 0.5), 0.3, 1e-9);
    EXPECT_EQ(caster.DistanceToWorld(p_W, none, 0.2), 0.2);
    EXPECT_EQ(caster.DistanceToWorld(p_W, none, 0.0), 0.0);
  }
  {
    // a mesh: a point 0.7 beyond a tetrahedron's corner, and a point far from it
    auto tetrahedron = std::make_shared<TriangleMesh>();
    tetrahedron->vertices_O = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0), Vec3f(0, 0, 1)};
    tetrahedron->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    Mesh mesh;
    mesh.data = tetrahedron;
    RayCaster caster;
    caster.AddBody({BodyShape{mesh, Pose::Identity(), 4}}, BodyKind::kWorld);
    caster.Commit();
    EXPECT_NEAR(caster.DistanceToWorld(Vec3(1.7, 0, 0), none, 0.8), 0.7, 1e-6);
    EXPECT_EQ(caster.DistanceToWorld(Vec3(1.7, 0, 0), none, 0.6), 0.6);
    EXPECT_EQ(caster.DistanceToWorld(Vec3(1.7, 0, 0), none, 0.01), 0.01);
    EXPECT_EQ(caster.DistanceToWorld(Vec3(500, 0, 0), none, 3.0), 3.0) << "far from every triangle";
    EXPECT_EQ(caster.DistanceToWorld(Vec3::Zero(), std::vector<std::int32_t>{4}, 3.0), 3.0) << "excluded";
  }
}

// Over a cloud of points around every kind of shape, a capped distance equals
// min(uncapped distance, cap) bit for bit, for caps below, near and above it.
TEST(RayCasterTest, DistanceToWorldWithACapEqualsTheUncappedOneCapped) {
  Mesh wall;
  wall.data = GridMesh(8, 0.1, true);  // 0.8 m square, 128 triangles
  const std::vector<std::vector<BodyShape>> worlds = {
      {BodyShape{Box{Vec3(0.4, 0.3, 0.2)}, XyzRpyDeg(0.1, 0, 0.2, 10, 20, 30), 0}},
      {BodyShape{Sphere{0.25}, Translation(0.2, -0.1, 0.3), 0}},
      {BodyShape{Cylinder{0.1, 0.6}, XyzRpyDeg(0, 0.1, 0.3, 0, 90, 20), 0}},
      {BodyShape{Plane{}, XyzRpyDeg(0, 0, -0.2, 5, 0, 0), 0}},
      {BodyShape{wall, XyzRpyDeg(-0.4, -0.4, 0, 90, 0, 0), 0}},
      {BodyShape{Box{Vec3(0.2, 0.2, 0.2)}, Translation(0.5, 0.5, 0), 0},
       BodyShape{wall, XyzRpyDeg(-0.4, 0.3, -0.1, 0, 0, 0), 1},
       BodyShape{Sphere{0.1}, Translation(-0.5, 0, 0.5), 2}},
  };
  const std::vector<std::int32_t> none;
  for (std::size_t w = 0; w < worlds.size(); ++w) {
    SCOPED_TRACE("world " + std::to_string(w));
    RayCaster caster;
    caster.AddBody(worlds[w], BodyKind::kWorld);
    caster.Commit();
    Uniform uniform(17 + static_cast<unsigned>(w));
    int capped_count = 0, exact_count = 0;
    for (int i = 0; i < 300; ++i) {
      const Vec3 p_W(uniform(-1.5, 1.5), uniform(-1.5, 1.5), uniform(-1.0, 1.5));
      const double exact_m = caster.DistanceToWorld(p_W, none);
      ASSERT_TRUE(std::isfinite(exact_m));
      for (double cap_m : {0.01, 0.1, 0.5 * exact_m, exact_m, 2 * exact_m + 1e-3, 0.7, 3.0}) {
        const double capped_m = caster.DistanceToWorld(p_W, none, cap_m);
        EXPECT_EQ(capped_m, std::min(exact_m, cap_m)) << "at " << p_W.transpose() << " cap " << cap_m;
        capped_count += exact_m > cap_m;
        exact_count += exact_m < cap_m;
      }
    }
    // both sides of the cap were tried
    EXPECT_GT(capped_count, 300);
    EXPECT_GT(exact_count, 300);
  }
}

TEST(RayCasterTest, TriangleCountCountsBoxesAndMeshesOnly) {
  RayCaster caster;
  Mesh mesh;
  mesh.data = GridMesh(3, 1.0, true);
  caster.AddBody({BodyShape{Box{}, Pose::Identity(), 0}, BodyShape{Sphere{}, Translation(3, 0, 0), 1},
                  BodyShape{Cylinder{}, Translation(6, 0, 0), 2}, BodyShape{Plane{}, Pose::Identity(), 3}},
                 BodyKind::kWorld);
  caster.AddBody({BodyShape{mesh, Pose::Identity(), 4}, BodyShape{Box{}, Pose::Identity(), 5}}, BodyKind::kRobot);
  caster.Commit();
  EXPECT_EQ(caster.triangle_count(), 12u + 18u + 12u);
}

}  // namespace
}  // namespace proxsim

namespace proxsim {
namespace {

// A robot body is cast into, its ray moved into the body's frame, only when
// the ray may meet its box (ray_caster_internal.h): however many moves no ray
// came near, the first ray that does sees the body where it is now, never
// where a ray last met it, and a ray through a place it left sees what lies behind.
TEST(RayCasterTest, RobotMovedWhileNoRayCameNearIsSeenWhereItIs) {
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(0.2, 40, 4)}, Translation(10, 0, 0), 0}}, BodyKind::kWorld);
  const int link = caster.AddBody({BodyShape{Sphere{0.2}, Pose::Identity(), 1}}, BodyKind::kRobot, Translation(2, 0, 0));
  caster.Commit();
  const Ray along_x = MakeRay(Vec3::Zero(), Vec3::UnitX(), 20, /*see_robot=*/true);
  EXPECT_NEAR(CastOne(caster, along_x).distance_m, 1.8, 1e-6);
  // moved three times, each committed, with only rays far from it cast meanwhile
  const Ray far_away = MakeRay(Vec3(0, -5, 0), Vec3::UnitX(), 20, /*see_robot=*/true);
  for (const double y : {1.0, 2.0, 3.0}) {
    caster.SetBodyPose(link, Translation(4, y, 0));
    caster.Commit();
    const Hit hit = CastOne(caster, far_away);
    EXPECT_EQ(hit.object_id, 0);
    EXPECT_NEAR(hit.distance_m, 9.9, 1e-6);
  }
  // the place it was committed at is empty: the wall behind
  const Hit behind = CastOne(caster, along_x);
  EXPECT_EQ(behind.object_id, 0);
  EXPECT_NEAR(behind.distance_m, 9.9, 1e-6);
  // where it is now: at (4, 3, 0)
  const Hit seen = CastOne(caster, MakeRay(Vec3(0, 3, 0), Vec3::UnitX(), 20, /*see_robot=*/true));
  EXPECT_EQ(seen.object_id, 1);
  EXPECT_NEAR(seen.distance_m, 3.8, 1e-6);
  // and a ray that only grazes its box (inside the box's corner, outside the sphere) misses it
  const double corner = 0.19;  // the box's half side is 0.2: (0.19, 0.19) is in the box, 0.27 from the centre
  const Hit grazing = CastOne(caster, MakeRay(Vec3(0, 3 + corner, corner), Vec3::UnitX(), 20, /*see_robot=*/true));
  EXPECT_EQ(grazing.object_id, 0);
}

// RayCaster::Nearby: queries from a ball walk only the shapes near it; their
// answers (distance, object, depth) are those over every shape, bit for bit,
// for every point of the ball and every cap up to the reach, and for a list
// narrowed from a larger ball's; a point outside the ball, or a cap beyond the
// reach, is answered over every shape.
TEST(RayCasterTest, NearbyShapesGiveTheAnswersOfEveryShape) {
  RayCaster caster;
  // a room: long walls (their spheres reach everything), furniture of every
  // closed form, a box turned about two axes, a mesh panel, in two bodies
  caster.AddBody({BodyShape{Plane{}, Pose::Identity(), 0},
                  BodyShape{Box{Vec3(0.1, 10, 2.5)}, Translation(-1, 0, 1.25), 1},
                  BodyShape{Box{Vec3(10, 0.1, 2.5)}, Translation(4, 5, 1.25), 2},
                  BodyShape{Box{Vec3(0.6, 0.8, 0.04)}, XyzRpyDeg(1.5, 0.4, 0.7, 0, 0, 20), 3},
                  BodyShape{Cylinder{0.03, 0.7}, Translation(1.3, 0.1, 0.35), 4},
                  BodyShape{Sphere{0.2}, Translation(2.2, -0.5, 0.4), 5},
                  BodyShape{Box{Vec3(0.3, 0.2, 0.5)}, XyzRpyDeg(0.8, -0.6, 0.4, 30, 0, 45), 6}},
                 BodyKind::kWorld);
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices_O = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 0, 1), Vec3f(0, 0, 1)};
  mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
  Mesh panel;
  panel.data = mesh;
  caster.AddBody({BodyShape{panel, Pose::Identity(), 7}, BodyShape{Box{Vec3(0.2, 0.2, 0.2)}, Translation(0.5, 0.5, 0.5), 8}},
                 BodyKind::kWorld, XyzRpyDeg(2.5, 0.6, 0, 0, 0, 15));
  caster.Commit();
  const std::vector<std::int32_t> exclude{0};
  int near_something = 0;
  for (int ball = 0; ball < 40; ++ball) {
    // balls along and across the room, 0.05–0.3 m across, reaching 0.1–0.8 m
    const Vec3 center_W(0.1 * ball - 0.5, 0.03 * (ball % 17) - 0.3, 0.05 + 0.02 * (ball % 30));
    const double radius_m = 0.05 + 0.25 * (ball % 5) / 4, reach_m = 0.1 + 0.7 * (ball % 7) / 6;
    RayCaster::Nearby nearby, narrowed;
    caster.FindNearby(center_W, radius_m, reach_m, &nearby);
    caster.FindNearby(center_W + Vec3(0.3 * radius_m, 0, 0), 0.5 * radius_m, 0.8 * reach_m, &narrowed, &nearby);
    for (int k = 0; k < 30; ++k) {
      // points over the ball (its edge included), and a few just outside
      const double u = (k % 10) / 9.0, theta = 0.7 * k, phi = 0.3 * k;
      const double r_m = (k < 27 ? u : 1.2) * radius_m;
      const Vec3 p_W = center_W + r_m * Vec3(std::cos(theta) * std::sin(phi), std::sin(theta) * std::sin(phi), std::cos(phi));
      for (const double cap_m : {0.5 * reach_m, reach_m, 2 * reach_m, std::numeric_limits<double>::infinity()}) {
        for (const auto* list : {&nearby, &narrowed}) {
          const RayCaster::NearestSurface every = caster.NearestToWorld(p_W, exclude, cap_m);
          const RayCaster::NearestSurface near = caster.NearestToWorld(p_W, exclude, cap_m, list);
          ASSERT_EQ(near.distance_m, every.distance_m) << "ball " << ball << " point " << k << " cap " << cap_m;
          ASSERT_EQ(near.object_id, every.object_id) << "ball " << ball << " point " << k << " cap " << cap_m;
          ASSERT_EQ(near.depth_m, every.depth_m) << "ball " << ball << " point " << k << " cap " << cap_m;
          ASSERT_EQ(caster.DistanceToWorld(p_W, exclude, cap_m, list), every.distance_m);
          near_something += every.object_id >= 0 ? 1 : 0;
        }
      }
    }
    // the lists leave the far walls out of a ball in the room's middle
    if (center_W.x() > 1.5) {
      for (std::size_t body = 0; body < nearby.bodies.size(); ++body)
        for (std::uint32_t g = nearby.geom_begin[body]; g < nearby.geom_begin[body + 1]; ++g)
          if (nearby.bodies[body] == 0) EXPECT_NE(nearby.geoms[g], 1u) << "the west wall, 2.5 m away, in ball " << ball;
    }
  }
  // the points must meet shapes within their caps, or nothing was compared
  EXPECT_GT(near_something, 1000);
}

// A batch of rays from one point is tested against the robot as a cone
// (ray_caster_cast.cc, RobotCandidates): bodies outside it are not walked.
// The answers must be those of the same rays cast where no cone applies (each
// ray beside one from another point), bit for bit: same binary, same rays.
// Beams from inside, beside and away from the links, wide and narrow, and
// cones whose edge passes near the first link's bounding sphere's tangent.
TEST(RayCasterTest, BeamsFromOnePointSeeTheRobotAsWhenCastRayByRay) {
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(0.2, 40, 4)}, Translation(6, 0, 0), 0}}, BodyKind::kWorld);
  const std::vector<Pose> link_poses = {Translation(1, 0, 0), Translation(0, 0.5, -0.3), Translation(-0.4, -0.2, 0.1),
                                        Translation(2.5, 0.8, 0.4)};
  int object = 1;
  for (const Pose& X_WL : link_poses) {
    caster.AddBody({BodyShape{Cylinder{0.05, 0.4}, Pose::Identity(), object},
                    BodyShape{Box{Vec3(0.1, 0.08, 0.06)}, Translation(0, 0, -0.25), object + 1}},
                   BodyKind::kRobot, X_WL);
    object += 2;
  }
  caster.Commit();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto beam = [](const Vec3& origin_W, const Vec3& axis_W, double half_angle_rad, int rings) {
    std::vector<Ray> rays{MakeRay(origin_W, axis_W, 8.0)};
    const Vec3 u = axis_W.unitOrthogonal(), v = axis_W.normalized().cross(u);
    for (int k = 1; k <= rings; ++k) {
      const double theta = half_angle_rad * k / rings;
      for (int j = 0; j < 8; ++j) {
        const double phi = 2 * std::numbers::pi * j / 8;
        rays.push_back(MakeRay(origin_W, std::cos(theta) * axis_W.normalized() +
                                             std::sin(theta) * (std::cos(phi) * u + std::sin(phi) * v), 8.0));
      }
    }
    return rays;
  };
  std::vector<std::vector<Ray>> beams;
  for (int b = 0; b < 600; ++b) {
    // from near the links, and from afar, aimed at a link's centre, off by up to 0.5 rad
    const Vec3 origin_W = b % 2 ? Vec3(1.5 * unit(rng), 1.0 * unit(rng), 0.5 * unit(rng))
                                : Vec3(4 * unit(rng), 4 * unit(rng), 2 * unit(rng));
    const Vec3 link_W = link_poses[static_cast<std::size_t>(b) % link_poses.size()].translation();
    const Vec3 axis_W = (link_W - origin_W).normalized() + 0.5 * Vec3(unit(rng), unit(rng), unit(rng));
    if (axis_W.norm() < 1e-3) continue;
    beams.push_back(beam(origin_W, axis_W, b % 3 ? 0.05 + 0.2 * (1 + unit(rng)) : 0.8 * (0.5 + 0.5 * unit(rng)), 3));
  }
  // cones whose edge passes near the tangent to the first link's bounding
  // sphere from a point 1 m away (its radius about 0.33 m: half its box's diagonal)
  for (const double off_rad : {-2e-4, 0.0, 2e-4}) {
    const double tangent_rad = std::asin(0.33);
    beams.push_back(beam(Vec3(0, 0, -0.13), Vec3(std::cos(tangent_rad + 0.3 + off_rad), std::sin(tangent_rad + 0.3 + off_rad), 0), 0.3, 2));
  }
  int robot_hits = 0;
  for (const std::vector<Ray>& rays : beams) {
    std::vector<Hit> together(rays.size());
    caster.Cast(rays, together);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      // beside a ray from elsewhere: the batch has no single apex
      const std::array<Ray, 2> pair = {rays[i], MakeRay(Vec3(9, 9, 9), Vec3::UnitX(), 1.0)};
      std::array<Hit, 2> apart;
      caster.Cast(pair, apart);
      EXPECT_EQ(together[i].object_id, apart[0].object_id);
      EXPECT_EQ(std::memcmp(&together[i].distance_m, &apart[0].distance_m, sizeof(float)), 0);
      EXPECT_EQ(together[i].normal_W, apart[0].normal_W);
      robot_hits += together[i].object_id >= 1;
    }
  }
  EXPECT_GT(robot_hits, 100);  // the robot is met, not only missed
}

}  // namespace
}  // namespace proxsim

namespace proxsim {
namespace {

// A robot body is cast into on its own, each ray moved into the body's frame
// (ray_caster_cast.cc, CastIntoRobotBody): a turned box on a turned, moved
// body is met where the closed form (the slab test in the box's frame) puts
// it, with its face's normal; a ray along a face 2 mm outside it misses it,
// 2 mm inside it meets the face it enters.
TEST(RayCasterTest, ATurnedRobotBodyIsMetWhereTheClosedFormPutsIt) {
  RayCaster caster;
  caster.AddBody({BodyShape{Box{Vec3(0.2, 40, 4)}, Translation(6, 0, 0), 0}}, BodyKind::kWorld);
  const Vec3 size_m(0.12, 0.3, 0.5);
  const Pose X_BO = XyzRpyDeg(0.02, -0.05, 0.1, 10, 0, 35);
  const int body = caster.AddBody({BodyShape{Box{size_m}, X_BO, 1}}, BodyKind::kRobot, Pose::Identity());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int met = 0, beside = 0;
  for (const Pose& X_WB : {XyzRpyDeg(1.2, 0.3, 0.4, 20, -30, 60), XyzRpyDeg(-0.7, 1.1, -0.2, -45, 15, 170)}) {
    caster.SetBodyPose(body, X_WB);
    caster.Commit();
    const Pose X_WO = X_WB * X_BO;
    const Pose X_OW = X_WO.inverse();
    // the closed form: the slab test in O of the ray as cast (its float origin and direction)
    const auto expect_met_as_closed_form = [&](const Ray& ray, const Hit& hit, const char* what, int k) {
      const Vec3 o_O = X_OW * ray.origin_W.cast<double>(), d_O = X_OW.linear() * ray.direction_W.cast<double>();
      double t_in = 0, t_out = ray.max_range_m;
      int in_axis = -1;
      for (int a = 0; a < 3; ++a) {
        double t0 = (-0.5 * size_m[a] - o_O[a]) / d_O[a], t1 = (0.5 * size_m[a] - o_O[a]) / d_O[a];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > t_in) {
          t_in = t0;
          in_axis = a;
        }
        t_out = std::min(t_out, t1);
      }
      ASSERT_TRUE(t_in <= t_out && in_axis >= 0) << what << " " << k << ": the closed form misses";
      ASSERT_EQ(hit.object_id, 1) << what << " " << k;
      // float sums err by ~1e-7 m across; along the ray that grows as 1/cos of the incidence
      const double cos_incidence = std::abs(d_O[in_axis]) / d_O.norm();
      EXPECT_NEAR(hit.distance_m, t_in, 1e-6 + 1e-6 / cos_incidence) << what << " " << k;
      Vec3 normal_O = Vec3::Zero();
      normal_O[in_axis] = d_O[in_axis] > 0 ? -1 : 1;
      ExpectNormalNear(hit.normal_W, X_WO.linear() * normal_O, 1e-4);
      ++met;
    };
    for (int k = 0; k < 200; ++k) {
      // a ray from 1-3 m away towards a point of a face
      Vec3 target_O(unit(rng) * 0.45 * size_m.x(), unit(rng) * 0.45 * size_m.y(), unit(rng) * 0.45 * size_m.z());
      const int face = k % 3;
      target_O[face] = (unit(rng) > 0 ? 1 : -1) * 0.5 * size_m[face];
      const Vec3 from_O = target_O + (2 + unit(rng)) * (target_O.normalized() + 0.3 * Vec3(unit(rng), unit(rng), unit(rng)));
      const Vec3 origin_W = X_WO * from_O;
      const Ray ray = MakeRay(origin_W, X_WO * target_O - origin_W, 5.0);
      expect_met_as_closed_form(ray, CastOne(caster, ray), "ray", k);
    }
    for (int k = 0; k < 60; ++k) {
      // along a face, from 1 m before the box, 2 mm outside it (a miss) and 2 mm inside (a hit)
      const int face = k % 3, along = (k + 1) % 3, across = (k + 2) % 3;
      const double sign = k % 2 ? 1.0 : -1.0;
      for (const double off_m : {0.002, -0.002}) {
        Vec3 from_O = Vec3::Zero();
        from_O[face] = sign * (0.5 * size_m[face] + off_m);
        from_O[along] = -0.5 * size_m[along] - 1.0;
        from_O[across] = 0.4 * unit(rng) * size_m[across];
        const Vec3 origin_W = X_WO * from_O;
        const Ray ray = MakeRay(origin_W, X_WO.linear().col(along), 5.0);
        const Hit hit = CastOne(caster, ray);
        if (off_m > 0) {
          EXPECT_NE(hit.object_id, 1) << "ray " << k << " passes 2 mm beside the box";
          ++beside;
        } else {
          expect_met_as_closed_form(ray, hit, "grazing ray", k);
        }
      }
    }
  }
  EXPECT_EQ(met, 2 * (200 + 60));
  EXPECT_EQ(beside, 2 * 60);
}

}  // namespace
}  // namespace proxsim
