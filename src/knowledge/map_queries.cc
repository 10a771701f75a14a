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

}  // namespace

const Hazard* ObstacleInCorridor(const TerrainMap& map, const Vec2& p_W_from, const Vec2& heading_W, double ahead_m,
                                 double half_width_m) {
  const Vec2 lateral(-heading_W.y(), heading_W.x());
  const std::array<Vec2, 4> corridor = {p_W_from - half_width_m * lateral, p_W_from + half_width_m * lateral,
                                        p_W_from + ahead_m * heading_W + half_width_m * lateral,
                                        p_W_from + ahead_m * heading_W - half_width_m * lateral};
  for (const Hazard& hazard : map.hazards()) {
    if (hazard.hazard_class != HazardClass::kObstacle) continue;
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
    if (!apart) return &hazard;
  }
  return nullptr;
}

void ForEachObstacleOutlinePoint(const TerrainMap& map, double spacing_m, const std::function<void(const Vec3&)>& point) {
  for (const Hazard& hazard : map.hazards()) {
    if (hazard.hazard_class != HazardClass::kObstacle) continue;
    const double z = hazard.ground_z_m + hazard.height_m;
    const Vec2 size = hazard.max_W - hazard.min_W;
    const int nx = std::max(1, static_cast<int>(std::ceil(size.x() / spacing_m)));
    const int ny = std::max(1, static_cast<int>(std::ceil(size.y() / spacing_m)));
    for (int i = 0; i <= nx; ++i) {
      const double x = hazard.min_W.x() + size.x() * i / nx;
      point(Vec3(x, hazard.min_W.y(), z));
      point(Vec3(x, hazard.max_W.y(), z));
    }
    for (int j = 1; j < ny; ++j) {
      const double y = hazard.min_W.y() + size.y() * j / ny;
      point(Vec3(hazard.min_W.x(), y, z));
      point(Vec3(hazard.max_W.x(), y, z));
    }
  }
}

}  // namespace proxsim
