// The swing shank against the ground: the sole clears every edge on its way
// (swing_arc.h), but a shank leaning back over the edge of the tread it
// leaves can still strike that edge (the built-in biped stepping down the
// stairs course at 0.35 m strides: its tibia struck the landing's nose). The
// shank is its links' outline in the sagittal plane — a convex polygon,
// rigid with the knee → ankle segment — and the planner keeps it a clearance
// above the ground's profile as it keeps the sole.
#pragma once

#include <vector>

#include "core/geometry.h"
#include "gait/terrain_profile.h"

namespace proxsim {

/// The shank's outline in H (s, z) for the planner: kept this far above the ground, m.
constexpr double kShankClearance_m = 0.005;

/// The convex hull of sagittal points (x, z), counter-clockwise from the
/// lowest-x point; fewer than three distinct points give what there is.
std::vector<Vec2> ConvexHull2(std::vector<Vec2> points);

/// How far the convex polygon `hull_H` (counter-clockwise, in H) lies below
/// the ground of `profile` plus `clearance_m`, m (≤ 0: it clears): the
/// largest over the ground's segments under it of the segment's height plus
/// the clearance minus the polygon's lowest point over that segment's span.
/// Exact for a step-shaped profile: the polygon's lower boundary is convex,
/// so its lowest point over a span lies at the span's ends or a vertex.
double ShankDeficit(const TerrainProfile& profile, const std::vector<Vec2>& hull_H, double clearance_m);

}  // namespace proxsim
