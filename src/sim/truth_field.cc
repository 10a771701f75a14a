#include "sim/truth_field.h"

#include <limits>

namespace proxsim {

std::vector<float> TrueHeightsAt(const RayCaster& caster, std::span<const Vec2> xy_W, double ceiling_z_m,
                                 bool see_moving) {
  const std::size_t n = xy_W.size();
  std::vector<float> heights(n, std::numeric_limits<float>::quiet_NaN());
  std::vector<Ray> rays(n), up_rays(n);
  std::vector<Hit> hits(n), up_hits(n);
  const auto ceiling = static_cast<float>(ceiling_z_m);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3f origin(static_cast<float>(xy_W[i].x()), static_cast<float>(xy_W[i].y()), ceiling);
    rays[i] = Ray{.origin_W = origin, .direction_W = -Vec3f::UnitZ(), .max_range_m = static_cast<float>(kTruthDepth_m), .see_robot = false, .see_moving = see_moving};
    up_rays[i] = Ray{.origin_W = origin, .direction_W = Vec3f::UnitZ(), .max_range_m = static_cast<float>(kTruthDepth_m), .see_robot = false, .see_moving = see_moving};
  }
  caster.Cast(rays, hits);
  caster.Cast(up_rays, up_hits);
  for (std::size_t i = 0; i < n; ++i) {
    // the ceiling inside a solid: looking up, the first surface faces up
    // (its outside), or looking down, the first faces down (its underside,
    // seen from within); the column is full to the ceiling
    const Hit& up = up_hits[i];
    const Hit& down = hits[i];
    if ((up.is_hit() && up.normal_W.z() > 0) || (down.is_hit() && down.normal_W.z() < 0)) {
      heights[i] = ceiling;
      continue;
    }
    const Hit& hit = hits[i];
    // in float, as the ray was cast: a floor at 0 reads 0 exactly
    if (hit.is_hit()) heights[i] = ceiling - hit.distance_m;
  }
  return heights;
}

std::vector<float> TrueHeights(const RayCaster& caster, const CellBox& box, double resolution_m, double ceiling_z_m,
                               bool see_moving) {
  const std::size_t nx = static_cast<std::size_t>(box.nx()), ny = static_cast<std::size_t>(box.ny());
  std::vector<float> heights;
  heights.reserve(nx * ny);
  std::vector<Vec2> row_xy(nx);
  // one row of columns per cast
  for (std::size_t row = 0; row < ny; ++row) {
    const double y = (box.iy_min + static_cast<double>(row) + 0.5) * resolution_m;
    for (std::size_t col = 0; col < nx; ++col) row_xy[col] = Vec2((box.ix_min + static_cast<double>(col) + 0.5) * resolution_m, y);
    const std::vector<float> row_heights = TrueHeightsAt(caster, row_xy, ceiling_z_m, see_moving);
    heights.insert(heights.end(), row_heights.begin(), row_heights.end());
  }
  return heights;
}

}  // namespace proxsim
