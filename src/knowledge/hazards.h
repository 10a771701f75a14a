// Hazards: where the terrain departs from the ground the robot stands on, by
// more than it can walk over. Each cell is labelled from its surface and the
// ground height z_g:
//   raised   its height > z_g + obstacle_min_m
//   dropped  its floor < z_g − drop_min_m, the floor being its measured
//            height, or, never measured, its upper bound from free space
// and cells of one label at most two cells apart (8-connected across one
// unknown or unlabelled cell: a sparse scan leaves gaps) whose surfaces
// continue each other form a cluster: raised cells whose heights are within
// obstacle_min_m of each other (a riser cuts: each tread of a staircase is a
// cluster of its own); dropped cells always, but a measured floor joins a
// never-measured cell only below that cell's free-space bound (a hole's floor
// is not the void beside a walkway; a pit's wall cells, which hold heights
// between its rim and its floor, stay with it). Clusters are classified:
//   raised:  step_up when its top is at most step_max_m above the ground and
//            it is at least step_min_size_m long and wide (a foot fits);
//            otherwise obstacle (too small or too high to step on);
//   dropped: step_down when it has a measured floor at most step_max_m down
//            and is at least step_min_size_m long and wide; otherwise hole.
// The same rules classify the map's cells (terrain_map.h) and the truth's
// (terrain_score.h), so that the score compares like with like.
//
// Frames: W world.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "knowledge/elevation_grid.h"
#include "knowledge/terrain_config.h"

namespace proxsim {

enum class HazardClass : std::uint8_t { kObstacle, kStepUp, kStepDown, kHole };
constexpr int kHazardClassCount = 4;

/// "obstacle", "step_up", "step_down", "hole".
const char* HazardClassName(HazardClass hazard_class);

/// A cell's label for the classifier (stored in ElevationGrid::Tile::labels).
enum class CellLabel : std::uint8_t { kNone = 0, kRaised = 1, kDropped = 2 };

/// What the classifier reads of one cell. NaN: unknown.
struct CellSurface {
  float height_m = std::numeric_limits<float>::quiet_NaN();       ///< measured (or true) height
  float upper_bound_m = std::numeric_limits<float>::quiet_NaN();  ///< free space's bound, for a cell never measured
};

/// The surface the map knows in a cell.
inline CellSurface SurfaceOf(const TerrainCell& cell) {
  return {cell.has_elevation() ? cell.elevation_m : std::numeric_limits<float>::quiet_NaN(),
          cell.upper_bound_m};
}

/// The label of one cell relative to the ground height (inline: the map
/// relabels every cell of a changed tile at each hazard pass).
inline CellLabel LabelCell(const CellSurface& surface, double ground_z_m, const TerrainMapConfig& config) {
  if (!std::isnan(surface.height_m)) {
    if (surface.height_m > ground_z_m + config.obstacle_min_m) return CellLabel::kRaised;
    if (surface.height_m < ground_z_m - config.drop_min_m) return CellLabel::kDropped;
    return CellLabel::kNone;
  }
  // never measured: only free space speaks, and it can only say "lower than"
  if (surface.upper_bound_m < ground_z_m - config.drop_min_m) return CellLabel::kDropped;
  return CellLabel::kNone;
}

/// A classified cluster of cells.
struct Hazard {
  HazardClass hazard_class = HazardClass::kObstacle;
  CellBox cells;                 ///< the cells' bounding box
  int cell_count = 0;
  Vec2 centroid_W = Vec2::Zero();  ///< mean of the cells' centres
  Vec2 min_W = Vec2::Zero();       ///< extent: the bounding box's outer edges
  Vec2 max_W = Vec2::Zero();
  /// relative to the ground: the top's height (raised, > 0) or minus the depth
  /// (dropped, < 0; for a hole seen only through free space, the depth it has at least)
  double height_m = 0.0;
  double ground_z_m = 0.0;       ///< the ground it was classified against
  double first_detection_t_s = std::numeric_limits<double>::quiet_NaN();
  double distance_at_detection_m = std::numeric_limits<double>::quiet_NaN();  ///< leading toe to the extent, then

  bool raised() const { return hazard_class == HazardClass::kObstacle || hazard_class == HazardClass::kStepUp; }
  /// Horizontal distance from p to the extent (0 inside).
  double DistanceTo(const Vec2& p_W) const;
};

namespace hazards_internal {
// Whether two cells of one label hold one surface (the clusters' rule above).
bool Continuous(const CellSurface& a, const CellSurface& b, CellLabel label, const TerrainMapConfig& config);
// One cluster's cells, and their surfaces in the same order, into a classified hazard.
Hazard Classify(const std::vector<CellIndex>& cells, const std::vector<CellSurface>& surfaces, CellLabel label,
                double ground_z_m, double resolution_m, const TerrainMapConfig& config);
}  // namespace hazards_internal

/// The flood fill behind FindHazards, over any storage of labels and marks:
/// for each seed in order not yet visited, the cluster it starts (same label,
/// cells at most two apart, surfaces continuing each other), depth first.
/// label_at(c), surface_at(c) as for FindHazards; visited.Test(c) and
/// visited.Mark(c) the fill's set of visited cells (marks persist between
/// calls: cells already marked are neither seeds nor reached);
/// on_cluster(label, cells, surfaces) receives each cluster, its cells in the
/// order visited (the first is its seed) and their surfaces.
template <class LabelAt, class SurfaceAt, class Visited, class OnCluster>
void FillClusters(const std::vector<CellIndex>& seeds, LabelAt&& label_at, SurfaceAt&& surface_at, Visited& visited,
                  const TerrainMapConfig& config, OnCluster&& on_cluster) {
  std::vector<CellIndex> stack, cluster;
  std::vector<CellSurface> surfaces;
  for (const CellIndex& seed : seeds) {
    const CellLabel label = label_at(seed);
    if (label == CellLabel::kNone || visited.Test(seed)) continue;
    visited.Mark(seed);
    // flood fill over the cells of the same label up to two cells away whose
    // surfaces continue each other: a cluster holds across one unknown cell
    // (a sparse scan leaves such gaps), and stops at a riser
    cluster.clear();
    surfaces.clear();
    stack.assign(1, seed);
    while (!stack.empty()) {
      const CellIndex c = stack.back();
      stack.pop_back();
      const CellSurface here = surface_at(c);
      cluster.push_back(c);
      surfaces.push_back(here);
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          const CellIndex n{c.ix + dx, c.iy + dy};
          if ((dx == 0 && dy == 0) || label_at(n) != label || visited.Test(n) ||
              !hazards_internal::Continuous(here, surface_at(n), label, config)) {
            continue;
          }
          visited.Mark(n);
          stack.push_back(n);
        }
      }
    }
    on_cluster(label, cluster, surfaces);
  }
}

/// Every cluster of labelled cells reachable from `seeds` (one label per
/// cluster, cells at most two apart), classified. label_at(c) gives a cell's label (kNone
/// outside what is known), surface_at(c) its surface. `cluster_cells`, when
/// given, receives each hazard's cells.
std::vector<Hazard> FindHazards(const std::vector<CellIndex>& seeds,
                                const std::function<CellLabel(CellIndex)>& label_at,
                                const std::function<CellSurface(CellIndex)>& surface_at, double ground_z_m,
                                double resolution_m, const TerrainMapConfig& config,
                                std::vector<std::vector<CellIndex>>* cluster_cells = nullptr);

}  // namespace proxsim
