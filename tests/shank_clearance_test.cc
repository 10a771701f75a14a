// The swing shank's clearance (src/gait/shank_clearance.h) against closed
// forms: the convex hull of points, and how far a polygon lies below a
// step-shaped ground's profile plus the clearance.
#include "gait/shank_clearance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "gait/terrain_query.h"

namespace proxsim {
namespace {

// The edge of a tread: z = 0.6 m before x = 3.1 m, 0.45 m after (the built-in
// stairs course's landing and first tread down).
class LandingEdge : public TerrainQuery {
 public:
  void HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const override {
    for (std::size_t i = 0; i < from_W.size(); ++i) {
      const double z = from_W[i].x() < 3.1 ? 0.6 : 0.45;
      z_W[i] = z < from_W[i].z() - depth_m ? kNoGround : z;
    }
  }
};

TerrainProfile EdgeProfile() {
  ProfileLine line;
  line.s_begin_m = 2.5;
  line.s_end_m = 3.8;
  line.z_top_m = 1.5;
  line.depth_m = 3;
  return TerrainProfile(LandingEdge(), line);
}

// An axis-aligned rectangle, counter-clockwise.
std::vector<Vec2> Rectangle(double x0, double x1, double z0, double z1) {
  return {Vec2(x0, z0), Vec2(x1, z0), Vec2(x1, z1), Vec2(x0, z1)};
}

TEST(ShankClearance, TheHullOfASquareAndPointsInsideItIsTheSquareCounterClockwise) {
  const std::vector<Vec2> hull = ConvexHull2(
      {Vec2(1, 1), Vec2(0, 0), Vec2(0.5, 0.5), Vec2(1, 0), Vec2(0, 1), Vec2(0.2, 0.7), Vec2(0.5, 0), Vec2(1, 1)});
  ASSERT_EQ(hull.size(), 4u);
  EXPECT_EQ(hull[0], Vec2(0, 0));
  EXPECT_EQ(hull[1], Vec2(1, 0));
  EXPECT_EQ(hull[2], Vec2(1, 1));
  EXPECT_EQ(hull[3], Vec2(0, 1));
  double area2 = 0;  // the shoelace sum: positive when counter-clockwise
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2& a = hull[i];
    const Vec2& b = hull[(i + 1) % hull.size()];
    area2 += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_DOUBLE_EQ(area2, 2.0);
}

TEST(ShankClearance, AnUprightShankOverTheLowerTreadClearsItByItsHeightAboveIt) {
  const TerrainProfile profile = EdgeProfile();
  // 0.1 m wide, its bottom 0.05 m above the lower tread, wholly past the edge
  const double deficit = ShankDeficit(profile, Rectangle(3.12, 3.22, 0.50, 0.95), kShankClearance_m);
  EXPECT_NEAR(deficit, 0.45 + kShankClearance_m - 0.50, 1e-9);
}

TEST(ShankClearance, AShankOverTheEdgeIsMeasuredAgainstTheHigherTread) {
  const TerrainProfile profile = EdgeProfile();
  // straddling the edge (3.05 to 3.15 m): its bottom, 0.5 m high, is inside the landing
  const double deficit = ShankDeficit(profile, Rectangle(3.05, 3.15, 0.50, 0.95), kShankClearance_m);
  EXPECT_NEAR(deficit, 0.6 + kShankClearance_m - 0.50, 1e-9);
}

TEST(ShankClearance, ALeaningShankIsMeasuredAtTheEdgeWhereItsBackFacePassesOverIt) {
  const TerrainProfile profile = EdgeProfile();
  // a square turned 45°: its lower-left face rises 1:1 to the left from its
  // lowest corner at (3.14, 0.55), so above the edge at x = 3.1 it is at 0.59 m
  const double h = 0.05;
  const std::vector<Vec2> diamond = {Vec2(3.14, 0.55), Vec2(3.14 + h, 0.55 + h), Vec2(3.14, 0.55 + 2 * h),
                                     Vec2(3.14 - h, 0.55 + h)};
  const double deficit = ShankDeficit(profile, diamond, kShankClearance_m);
  // the profile locates the edge to kEdgeResolution_m; the face's slope is 1
  EXPECT_NEAR(deficit, 0.6 + kShankClearance_m - 0.59, kEdgeResolution_m + 1e-9);
  // over the lower tread its lowest corner clears it by 0.1 m: the edge decides
  EXPECT_GT(deficit, 0.45 + kShankClearance_m - 0.55);
  // moved 5 mm forward, the face passes over the edge 5 mm higher
  std::vector<Vec2> forward = diamond;
  for (Vec2& p : forward) p.x() += 0.005;
  EXPECT_NEAR(ShankDeficit(profile, forward, kShankClearance_m), 0.6 + kShankClearance_m - 0.595,
              kEdgeResolution_m + 1e-9);
}

}  // namespace
}  // namespace proxsim
