#include "knowledge/map_queries.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace proxsim {

namespace {

// the interval of a set of points projected on an axis
template <std::size_t N>
std::pair<double, double> Project(const std::array<Vec2, N>& points, const Vec2& axis) {
  double lo = points[0].dot(axis), hi = lo;
  for (const Vec2& p : points) {
    lo = std::min(lo, p.dot(axis));
    hi = std::max(hi, p.dot(axis));
  }
  return {lo, hi};
}

// whether two hazards' extents touch (overlap, or lie within `gap_m` of each other)
bool Touch(const Hazard& a, const Hazard& b, double gap_m) {
  return a.min_W.x() <= b.max_W.x() + gap_m && b.min_W.x() <= a.max_W.x() + gap_m &&
         a.min_W.y() <= b.max_W.y() + gap_m && b.min_W.y() <= a.max_W.y() + gap_m;
}

double TopOf(const Hazard& hazard) { return hazard.ground_z_m + hazard.height_m; }

// whether the map's cell stands more than obstacle_min_m above the ground the hazard was classified against
bool RaisedAbove(const TerrainMap& map, const Hazard& hazard, CellIndex index) {
  const TerrainCell* surface = map.grid().Find(index);
  return surface != nullptr && surface->has_elevation() &&
         surface->elevation_m > hazard.ground_z_m + map.config().obstacle_min_m;
}

// whether one of the hazard's raised cells lies in the corridor (its square
// meets the rectangle): the cells, not their cluster's bounding box, which
// for a drum or a table seen at an angle reaches into a corridor its cells
// stay out of
bool RaisedCellInCorridor(const TerrainMap& map, const Hazard& hazard, const std::array<Vec2, 4>& corridor,
                          const Vec2& lateral, const Vec2& heading_W) {
  const double half_cell_m = 0.5 * map.grid().resolution_m();
  // a square's half extent along a unit axis: the corridor grown by it
  const auto grown = [&](const Vec2& axis) { return half_cell_m * (std::abs(axis.x()) + std::abs(axis.y())); };
  const auto [along_lo, along_hi] = Project(corridor, heading_W);
  const auto [across_lo, across_hi] = Project(corridor, lateral);
  const double grow_along_m = grown(heading_W), grow_across_m = grown(lateral);
  bool inside = false;
  ForEachRaisedCellOf(map, hazard, [&](const Vec2& centre_W, CellIndex) {
    const double along = centre_W.dot(heading_W), across = centre_W.dot(lateral);
    inside = inside || (along >= along_lo - grow_along_m && along <= along_hi + grow_along_m &&
                        across >= across_lo - grow_across_m && across <= across_hi + grow_across_m);
  });
  return inside;
}

}  // namespace

void ForEachRaisedCellOf(const TerrainMap& map, const Hazard& hazard,
                         const std::function<void(const Vec2& centre_W, CellIndex index)>& cell) {
  for (std::int32_t iy = hazard.cells.iy_min; iy <= hazard.cells.iy_max; ++iy) {
    for (std::int32_t ix = hazard.cells.ix_min; ix <= hazard.cells.ix_max; ++ix) {
      const CellIndex index{ix, iy};
      if (RaisedAbove(map, hazard, index)) cell(map.grid().CellCentre(index), index);
    }
  }
}

std::vector<bool> ObstaclesToWalkAround(const TerrainMap& map) {
  const std::vector<Hazard>& hazards = map.hazards();
  const TerrainMapConfig& config = map.config();
  std::vector<bool> avoid(hazards.size()), step(hazards.size());
  for (std::size_t i = 0; i < hazards.size(); ++i) {
    avoid[i] = hazards[i].hazard_class == HazardClass::kObstacle;
    step[i] = hazards[i].hazard_class == HazardClass::kStepUp;
  }
  // a staircase: an obstacle only by its height above the ground the robot
  // stands on, a foot's size, and within a step's rise of a step it touches,
  // is the next tread (a few hazards: a fixed point in a few rounds)
  const double gap_m = 1.5 * config.resolution_m;
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t i = 0; i < hazards.size(); ++i) {
      if (!avoid[i]) continue;
      const Vec2 size = hazards[i].max_W - hazards[i].min_W;
      if (std::min(size.x(), size.y()) < config.step_min_size_m - 1e-9) continue;
      for (std::size_t j = 0; j < hazards.size(); ++j) {
        if (!step[j] || std::abs(TopOf(hazards[i]) - TopOf(hazards[j])) > config.step_max_m) continue;
        if (!Touch(hazards[i], hazards[j], gap_m)) continue;
        avoid[i] = false;
        step[i] = true;
        grew = true;
        break;
      }
    }
  }
  return avoid;
}

const Hazard* ObstacleInCorridor(const TerrainMap& map, const Vec2& p_W_from, const Vec2& heading_W, double ahead_m,
                                 double half_width_m) {
  const Vec2 lateral(-heading_W.y(), heading_W.x());
  const std::array<Vec2, 4> corridor = {p_W_from - half_width_m * lateral, p_W_from + half_width_m * lateral,
                                        p_W_from + ahead_m * heading_W + half_width_m * lateral,
                                        p_W_from + ahead_m * heading_W - half_width_m * lateral};
  const std::vector<bool> avoid = ObstaclesToWalkAround(map);
  for (std::size_t i = 0; i < map.hazards().size(); ++i) {
    if (!avoid[i]) continue;
    const Hazard& hazard = map.hazards()[i];
    const std::array<Vec2, 4> box = {hazard.min_W, Vec2(hazard.max_W.x(), hazard.min_W.y()), hazard.max_W,
                                     Vec2(hazard.min_W.x(), hazard.max_W.y())};
    // two rectangles are apart when one of their four edge directions separates them
    bool apart = false;
    for (const Vec2& axis : {Vec2(Vec2::UnitX()), Vec2(Vec2::UnitY()), heading_W, lateral}) {
      const auto [a_lo, a_hi] = Project(corridor, axis);
      const auto [b_lo, b_hi] = Project(box, axis);
      if (a_hi < b_lo || b_hi < a_lo) {
        apart = true;
        break;
      }
    }
    if (!apart && RaisedCellInCorridor(map, hazard, corridor, lateral, heading_W)) return &hazard;
  }
  return nullptr;
}

void ForEachObstacleOutlinePoint(const TerrainMap& map, const std::function<void(const Vec3&)>& point) {
  const std::vector<bool> avoid = ObstaclesToWalkAround(map);
  for (std::size_t i = 0; i < map.hazards().size(); ++i) {
    if (!avoid[i]) continue;
    const Hazard& hazard = map.hazards()[i];
    const double z = TopOf(hazard);
    const auto raised = [&](std::int32_t ix, std::int32_t iy) { return RaisedAbove(map, hazard, CellIndex{ix, iy}); };
    // a raised cell with a side that is not: on the outline (an L-shaped
    // wall's outline follows the wall, not its bounding box across the room)
    ForEachRaisedCellOf(map, hazard, [&](const Vec2& centre_W, CellIndex c) {
      if (!raised(c.ix - 1, c.iy) || !raised(c.ix + 1, c.iy) || !raised(c.ix, c.iy - 1) || !raised(c.ix, c.iy + 1))
        point(Vec3(centre_W.x(), centre_W.y(), z));
    });
  }
}

}  // namespace proxsim
