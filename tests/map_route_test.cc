// A route around the map's obstacles (knowledge/map_route.h) and the
// obstacles' outlines (knowledge/map_queries.h), on maps filled from the
// scene's truth (map.truth_within_m): a wall across the way is walked around
// at the clearance asked, an L-shaped wall's outline follows the wall (not
// its bounding box across the room), a goal walled in has no route.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "knowledge/map_queries.h"
#include "knowledge/map_route.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

// A blind robot at the origin facing +x whose map holds the truth within 3 m,
// with `objects` (YAML list items) on a floor.
std::string RouteWorldText(const std::string& objects) {
  return "proxsim: 1\nduration_s: 1.0\nrate_hz: 50\nscene:\n  objects:\n"
         "    - {name: floor, plane: {}, ground: true}\n" +
         objects +
         "robot:\n  model: builtin:biped\n  path: {waypoints_m: [[0, 0], [6, 0]]}\n"
         "map: {sensors: [], truth_within_m: 3, max_height_m: 1.2}\nsensors: []\n";
}

// distance from p to the segment [a, b]
double DistanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (p - (a + t * (b - a))).norm();
}

// distance from p to the axis-aligned rectangle [min, max]
double DistanceToBox(const Vec2& p, const Vec2& min, const Vec2& max) {
  return (p.cwiseMax(min).cwiseMin(max) - p).norm();
}

TEST(MapRoute, AWallAcrossTheWayIsWalkedAroundAtTheClearanceAsked) {
  // the wall: x in [1.45, 1.55], y in [-1, 1], 0.5 m high
  Simulation sim(LoadScenarioText(RouteWorldText("    - {name: wall, box: {size_m: [0.1, 2.0, 0.5]}, pose: {xyz_m: [1.5, 0, 0.25]}}\n"),
                                  "wall.yaml"),
                 1);
  sim.Step();
  const Vec2 from(0, 0), goal(2.8, 0), wall_min(1.45, -1.0), wall_max(1.55, 1.0);
  for (const double clearance_m : {0.25, 0.35, 0.5}) {
    const auto route = RouteAroundObstacles(*sim.terrain_map(), from, goal, clearance_m);
    ASSERT_TRUE(route.has_value()) << clearance_m;
    ASSERT_GE(route->size(), 2u) << "a straight line crosses the wall";
    EXPECT_EQ(route->back(), goal);
    // every leg keeps the clearance from the wall, less a planning cell and a map cell
    Vec2 a = from;
    double nearest_m = 1e9;
    for (const Vec2& b : *route) {
      for (double t = 0; t <= 1.0; t += 0.01) nearest_m = std::min(nearest_m, DistanceToBox(a + t * (b - a), wall_min, wall_max));
      a = b;
    }
    EXPECT_GE(nearest_m, clearance_m - kRouteCell_m - 0.02) << clearance_m;
    EXPECT_LE(nearest_m, clearance_m + 2 * kRouteCell_m) << "the route hugs the wall's corner: " << clearance_m;
    // it passes beyond one end of the wall
    const auto beyond = std::any_of(route->begin(), route->end(), [&](const Vec2& p) { return std::abs(p.y()) > 1.0 + clearance_m - 0.1; });
    EXPECT_TRUE(beyond) << clearance_m;
  }
  // no wall: the goal straight ahead
  const auto straight = RouteAroundObstacles(*sim.terrain_map(), from, Vec2(1.0, 0), 0.35);
  ASSERT_TRUE(straight.has_value());
  EXPECT_EQ(straight->size(), 1u);
}

TEST(MapRoute, AGoalWalledInHasNoRoute) {
  // four walls round (2.5, 0), 0.8 m high, 1 m square
  Simulation sim(LoadScenarioText(RouteWorldText(
                                      "    - {name: n, box: {size_m: [1.1, 0.1, 0.8]}, pose: {xyz_m: [2.5, 0.5, 0.4]}}\n"
                                      "    - {name: s, box: {size_m: [1.1, 0.1, 0.8]}, pose: {xyz_m: [2.5, -0.5, 0.4]}}\n"
                                      "    - {name: e, box: {size_m: [0.1, 1.1, 0.8]}, pose: {xyz_m: [3.0, 0, 0.4]}}\n"
                                      "    - {name: w, box: {size_m: [0.1, 1.1, 0.8]}, pose: {xyz_m: [2.0, 0, 0.4]}}\n"),
                                  "walled.yaml"),
                 1);
  sim.Step();
  EXPECT_FALSE(RouteAroundObstacles(*sim.terrain_map(), Vec2(0, 0), Vec2(2.5, 0), 0.25).has_value());
  // (the baseline: outside the box the goal has a route)
  EXPECT_TRUE(RouteAroundObstacles(*sim.terrain_map(), Vec2(0, 0), Vec2(2.5, 1.2), 0.25).has_value());
}

TEST(MapRoute, AStartBesideAnObstacleLeavesItByTheShortestWayOut) {
  // a post 0.2 m to the robot's left: inside the 0.35 m clearance
  Simulation sim(LoadScenarioText(RouteWorldText("    - {name: post, cylinder: {radius_m: 0.05, length_m: 0.8}, pose: {xyz_m: [0.5, 0.25, 0.4]}}\n"),
                                  "post.yaml"),
                 1);
  sim.Step();
  const auto route = RouteAroundObstacles(*sim.terrain_map(), Vec2(0.5, 0), Vec2(2.5, 0), 0.35);
  ASSERT_TRUE(route.has_value());
  // its first leg moves away from the post (to the right), never toward it
  EXPECT_LT(route->front().y(), 0.0);
  EXPECT_GE(DistanceToSegment(Vec2(0.5, 0.25), Vec2(0.5, 0), route->front()), 0.2);
}

TEST(MapRoute, AnLShapedWallsOutlineFollowsTheWallNotItsBoundingBox) {
  // two walls meeting at a corner, 1 m high: x in [1, 2.6] at y in [-1.05, -0.95], and y in [-1, 1] at x in [2.5, 2.6]
  Simulation sim(LoadScenarioText(RouteWorldText(
                                      "    - {name: a, box: {size_m: [1.6, 0.1, 1.0]}, pose: {xyz_m: [1.8, -1.0, 0.5]}}\n"
                                      "    - {name: b, box: {size_m: [0.1, 2.0, 1.0]}, pose: {xyz_m: [2.55, 0.0, 0.5]}}\n"),
                                  "corner.yaml"),
                 1);
  sim.Step();
  int points = 0;
  double farthest_m = 0;
  ForEachObstacleOutlinePoint(*sim.terrain_map(), [&](const Vec3& p_W) {
    ++points;
    const Vec2 p = p_W.head<2>();
    farthest_m = std::max(farthest_m, std::min(DistanceToBox(p, Vec2(1.0, -1.05), Vec2(2.6, -0.95)),
                                                DistanceToBox(p, Vec2(2.5, -1.0), Vec2(2.6, 1.0))));
  });
  EXPECT_GT(points, 100) << "the walls' outlines";
  // every point on a wall (within a map cell); the bounding box's edge would run 1.5 m from the walls
  EXPECT_LE(farthest_m, 0.03);
}

}  // namespace
}  // namespace proxsim
