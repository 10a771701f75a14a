// The scene's true height field on the map's lattice: at each cell's centre,
// a vertical ray from a ceiling down through the scene (the robot's own
// links transparent) finds the highest surface below the ceiling in that
// column. The ceiling is the map's (TerrainMap::truth_ceiling_z_m():
// max_height_m above the highest ground the robot stood on). A column that
// starts inside a solid (a wall, a cupboard taller than the ceiling) is full
// up to it: its height is the ceiling, which is also the most the map can
// hold there. NaN where the ray meets nothing.
// The scene's moving objects are left out (the truth is the still scene);
// with them where they stand at the end, the same rays tell which raised
// cells of the map something still stands on (the score's ghost cells).
// The scoring and the output files use it, and the oracle's map feed
// (truth_map_feed.h: the outcome study's perfect-perception baseline); a
// robot's own map never does.
//
// Frames: W world.
#pragma once

#include <span>
#include <vector>

#include "raycast/ray_caster.h"
#include "knowledge/elevation_grid.h"

namespace proxsim {

/// Deepest the vertical rays look below the ceiling.
constexpr double kTruthDepth_m = 100.0;

/// The true heights of the columns at `xy_W` (float32, NaN where there is no
/// surface), as TrueHeights finds each cell's.
std::vector<float> TrueHeightsAt(const RayCaster& caster, std::span<const Vec2> xy_W, double ceiling_z_m,
                                 bool see_moving);

/// The true heights of the cells of `box`, row after row (index
/// (iy − iy_min)·nx + (ix − ix_min)), float32 with NaN where there is no surface.
/// `see_moving`: with the scene's moving objects where they are now; without
/// them (the default), the still scene, which is what the map is scored against.
std::vector<float> TrueHeights(const RayCaster& caster, const CellBox& box, double resolution_m, double ceiling_z_m,
                               bool see_moving = false);

}  // namespace proxsim
