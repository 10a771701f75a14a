#include "knowledge/hazards.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace proxsim {

namespace {

std::uint64_t Key(CellIndex c) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.ix)) << 32) | static_cast<std::uint32_t>(c.iy);
}

// One cluster's cells into a classified hazard.
Hazard Classify(const std::vector<CellIndex>& cells, CellLabel label,
                const std::function<CellSurface(CellIndex)>& surface_at, double ground_z_m, double r,
                const TerrainMapConfig& config) {
  Hazard hazard;
  hazard.ground_z_m = ground_z_m;
  hazard.cell_count = static_cast<int>(cells.size());
  Vec2 sum = Vec2::Zero();
  double top_m = -std::numeric_limits<double>::infinity();
  double least_bound_m = -std::numeric_limits<double>::infinity();  // of the never-measured cells
  std::vector<double> floors_m;                                       // measured heights of a dropped cluster
  for (const CellIndex& c : cells) {
    hazard.cells.Expand(c);
    sum += Vec2((c.ix + 0.5) * r, (c.iy + 0.5) * r);
    const CellSurface s = surface_at(c);
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

// Whether two cells of one label hold one surface (see hazards.h).
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

}  // namespace

const char* HazardClassName(HazardClass hazard_class) {
  switch (hazard_class) {
    case HazardClass::kObstacle: return "obstacle";
    case HazardClass::kStepUp: return "step_up";
    case HazardClass::kStepDown: return "step_down";
    case HazardClass::kHole: return "hole";
  }
  return "?";
}

CellLabel LabelCell(const CellSurface& surface, double ground_z_m, const TerrainMapConfig& config) {
  if (!std::isnan(surface.height_m)) {
    if (surface.height_m > ground_z_m + config.obstacle_min_m) return CellLabel::kRaised;
    if (surface.height_m < ground_z_m - config.drop_min_m) return CellLabel::kDropped;
    return CellLabel::kNone;
  }
  // never measured: only free space speaks, and it can only say "lower than"
  if (surface.upper_bound_m < ground_z_m - config.drop_min_m) return CellLabel::kDropped;
  return CellLabel::kNone;
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
  std::vector<Hazard> hazards;
  std::unordered_set<std::uint64_t> visited;
  visited.reserve(2 * seeds.size());  // (no rehash as the fill grows: the same cells, found faster)
  std::vector<CellIndex> stack, cluster;
  for (const CellIndex& seed : seeds) {
    const CellLabel label = label_at(seed);
    if (label == CellLabel::kNone || !visited.insert(Key(seed)).second) continue;
    // flood fill over the cells of the same label up to two cells away whose
    // surfaces continue each other: a cluster holds across one unknown cell
    // (a sparse scan leaves such gaps), and stops at a riser
    cluster.clear();
    stack.assign(1, seed);
    while (!stack.empty()) {
      const CellIndex c = stack.back();
      stack.pop_back();
      cluster.push_back(c);
      const CellSurface here = surface_at(c);
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          const CellIndex n{c.ix + dx, c.iy + dy};
          if ((dx == 0 && dy == 0) || label_at(n) != label || visited.contains(Key(n)) ||
              !Continuous(here, surface_at(n), label, config)) {
            continue;
          }
          visited.insert(Key(n));
          stack.push_back(n);
        }
      }
    }
    hazards.push_back(Classify(cluster, label, surface_at, ground_z_m, resolution_m, config));
    if (cluster_cells != nullptr) cluster_cells->push_back(cluster);
  }
  return hazards;
}

}  // namespace proxsim
