// A route around the terrain map's obstacles: what a strategy reading the map
// asks to walk past everything it has mapped, not around one obstacle at a
// time. The map's obstacles (map_queries.h: raised, not a step the legs take)
// are drawn on a planning grid of kRouteCell_m, grown by the clearance the
// robot keeps (its half-width and a margin); cells never seen are free (the
// route is replanned as the map fills). A* over the 8-connected grid finds the
// shortest route, which is then cut to the waypoints a straight line between
// them keeps clear (each turn a corner of the grown obstacles).
//
// Frames: W world (x-y on the floor).
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "core/geometry.h"
#include "knowledge/terrain_map.h"

namespace proxsim {

/// Side of the planning grid's cells, m.
inline constexpr double kRouteCell_m = 0.05;
/// How far beyond the box holding the start and the goal the grid reaches, m.
inline constexpr double kRouteReach_m = 2.0;

/// The waypoints from `p_W_from` (excluded) to `p_W_goal` (last) whose
/// straight legs stay at least `clearance_m` from every obstacle cell of the
/// map within `reach_m` of `p_W_from` (farther ones are left for a later
/// plan: a tread seen in part at the edge of what is mapped is too small to
/// step on until it is seen whole); nullopt when no route exists within the
/// grid. A start inside the grown obstacles (the robot standing close beside
/// one) may leave them by the shortest way out; a goal inside them has no route.
std::optional<std::vector<Vec2>> RouteAroundObstacles(const TerrainMap& map, const Vec2& p_W_from,
                                                      const Vec2& p_W_goal, double clearance_m,
                                                      double reach_m = std::numeric_limits<double>::infinity());

}  // namespace proxsim
