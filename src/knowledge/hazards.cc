#include "knowledge/hazards.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace proxsim {

namespace hazards_internal {

Hazard Classify(const std::vector<CellIndex>& cells, const std::vector<CellSurface>& surfaces, CellLabel label,
                double ground_z_m, double r, const TerrainMapConfig& config) {
  Hazard hazard;
  hazard.ground_z_m = ground_z_m;
  hazard.cell_count = static_cast<int>(cells.size());
  Vec2 sum = Vec2::Zero();
  double top_m = -std::numeric_limits<double>::infinity();
  double least_bound_m = -std::numeric_limits<double>::infinity();  // of the never-measured cells
  std::vector<double> floors_m;                                       // measured heights of a dropped cluster
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const CellIndex& c = cells[k];
    hazard.cells.Expand(c);
    sum += Vec2((c.ix + 0.5) * r, (c.iy + 0.5) * r);
    const CellSurface& s = surfaces[k];
    if (!std::isnan(s.height_m)) {
      top_m = std::max(top_m, static_cast<double>(s.height_m));
      floors_m.push_back(s.height_m);
    } else if (!std::isnan(s.upper_bound_m)) {
      least_bound_m = std::max(least_bound_m, static_cast<double>(s.upper_bound_m));
    }
  }
  hazard.centroid_W = sum / static_cast<double>(cells.size());
  hazard.min_W = Vec2(hazard.cells.ix_min * r, hazard.cells.iy_min * r);
  hazard.max_W = Vec2((hazard.cells.ix_max + 1) * r, (hazard.cells.iy_max + 1) * r);
  const Vec2 size = hazard.max_W - hazard.min_W;
  const bool foot_fits = std::min(size.x(), size.y()) >= config.step_min_size_m - 1e-9;
  if (label == CellLabel::kRaised) {
    hazard.height_m = top_m - ground_z_m;
    hazard.hazard_class = hazard.height_m <= config.step_max_m && foot_fits ? HazardClass::kStepUp : HazardClass::kObstacle;
    return hazard;
  }
  // dropped: the depth of the measured floor (its median: edge cells hold
  // the faces' upper parts), else the least depth free space proves
  if (!floors_m.empty()) {
    auto mid = floors_m.begin() + static_cast<std::ptrdiff_t>(floors_m.size() / 2);
    std::nth_element(floors_m.begin(), mid, floors_m.end());
    hazard.height_m = *mid - ground_z_m;
  } else {
    hazard.height_m = least_bound_m - ground_z_m;
  }
  hazard.hazard_class = !floors_m.empty() && -hazard.height_m <= config.step_max_m && foot_fits
                            ? HazardClass::kStepDown
                            : HazardClass::kHole;
  return hazard;
}

bool Continuous(const CellSurface& a, const CellSurface& b, CellLabel label, const TerrainMapConfig& config) {
  const bool a_measured = !std::isnan(a.height_m), b_measured = !std::isnan(b.height_m);
  if (label == CellLabel::kRaised) {
    // a riser up cuts: each tread a cluster
    return !a_measured || !b_measured || std::abs(static_cast<double>(a.height_m) - b.height_m) <= config.obstacle_min_m;
  }
  // dropped: a pit's walls and floor are one hole (its wall cells hold
  // heights between the two); a measured floor joins a never-measured cell
  // only below that cell's bound
  if (a_measured && !b_measured) return a.height_m <= b.upper_bound_m + config.drop_min_m;
  if (b_measured && !a_measured) return b.height_m <= a.upper_bound_m + config.drop_min_m;
  return true;
}

}  // namespace hazards_internal

const char* HazardClassName(HazardClass hazard_class) {
  switch (hazard_class) {
    case HazardClass::kObstacle: return "obstacle";
    case HazardClass::kStepUp: return "step_up";
    case HazardClass::kStepDown: return "step_down";
    case HazardClass::kHole: return "hole";
  }
  return "?";
}

double Hazard::DistanceTo(const Vec2& p_W) const {
  const double dx = std::max({min_W.x() - p_W.x(), 0.0, p_W.x() - max_W.x()});
  const double dy = std::max({min_W.y() - p_W.y(), 0.0, p_W.y() - max_W.y()});
  return std::hypot(dx, dy);
}

std::vector<Hazard> FindHazards(const std::vector<CellIndex>& seeds,
                                const std::function<CellLabel(CellIndex)>& label_at,
                                const std::function<CellSurface(CellIndex)>& surface_at, double ground_z_m,
                                double resolution_m, const TerrainMapConfig& config,
                                std::vector<std::vector<CellIndex>>* cluster_cells) {
  // the visited cells: a hash set, for storages without marks of their own
  struct VisitedSet {
    std::unordered_set<std::uint64_t> keys;
    bool Test(CellIndex c) const { return keys.contains(TileKey(c.ix, c.iy)); }  // (a pair's key: here a cell's)
    void Mark(CellIndex c) { keys.insert(TileKey(c.ix, c.iy)); }
  } visited;
  visited.keys.reserve(2 * seeds.size());  // (no rehash as the fill grows: the same cells, found faster)
  std::vector<Hazard> hazards;
  FillClusters(seeds, label_at, surface_at, visited, config,
               [&](CellLabel label, const std::vector<CellIndex>& cells, const std::vector<CellSurface>& surfaces) {
                 hazards.push_back(hazards_internal::Classify(cells, surfaces, label, ground_z_m, resolution_m, config));
                 if (cluster_cells != nullptr) cluster_cells->push_back(cells);
               });
  return hazards;
}

}  // namespace proxsim
