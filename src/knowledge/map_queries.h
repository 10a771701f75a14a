// What the built-in strategies ask of the terrain map (terrain_map.h), one
// query each, so that every strategy reads the map the same way:
//  - the obstacles: hazards of class `obstacle` (raised, too high or too
//    small to step on), as the map has found them — a step up or down the
//    legs can take, and a hole the gait plans over on its own map
//    (gait.footholds: map), are not obstacles to walk around; nor is a
//    staircase's later tread, an obstacle only by its height above the
//    ground the robot stands on: one a foot fits on, touching a step (or
//    such a tread) within a step's rise of it;
//  - the first obstacle in a corridor ahead: a rectangle from a point along
//    a heading, by the separating-axis test against each obstacle's extent;
//  - an obstacle's outline, as the centres of its raised cells with a side
//    that is not raised, at its top's height, for a strategy that plans
//    around points; and each raised cell of a hazard.
//
// Frames: W world.
#pragma once

#include <functional>
#include <vector>

#include "core/geometry.h"
#include "knowledge/hazards.h"
#include "knowledge/terrain_map.h"

namespace proxsim {

/// Per hazard of map.hazards(): whether it is an obstacle to walk around (above).
std::vector<bool> ObstaclesToWalkAround(const TerrainMap& map);

/// The first obstacle (in the map's order) one of whose raised cells meets
/// the corridor [0, ahead_m] along `heading_W` (unit, horizontal) from
/// `p_W_from`, within ±half_width_m across it; null when none does.
const Hazard* ObstacleInCorridor(const TerrainMap& map, const Vec2& p_W_from, const Vec2& heading_W, double ahead_m,
                                 double half_width_m);

/// Calls `point` with the centre of each obstacle's outline cells — its
/// raised cells with a side that is not raised (a cell of the map's
/// resolution) — at the obstacle's top's height (world z).
void ForEachObstacleOutlinePoint(const TerrainMap& map, const std::function<void(const Vec3&)>& point);

/// Calls `cell` with each of the hazard's raised cells (above its ground by
/// more than obstacle_min_m) within its bounding box: its centre and index.
void ForEachRaisedCellOf(const TerrainMap& map, const Hazard& hazard,
                         const std::function<void(const Vec2& centre_W, CellIndex index)>& cell);

}  // namespace proxsim
