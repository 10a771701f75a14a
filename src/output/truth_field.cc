#include "output/truth_field.h"

#include <limits>

namespace proxsim {

std::vector<float> TrueHeights(const RayCaster& caster, const CellBox& box, double resolution_m, double ceiling_z_m,
                               bool see_moving) {
  const std::size_t nx = static_cast<std::size_t>(box.nx()), ny = static_cast<std::size_t>(box.ny());
  std::vector<float> heights(nx * ny, std::numeric_limits<float>::quiet_NaN());
  std::vector<Ray> rays(nx), up_rays(nx);
  std::vector<Hit> hits(nx), up_hits(nx);
  const auto ceiling = static_cast<float>(ceiling_z_m);
  // one row of columns per cast
  for (std::size_t row = 0; row < ny; ++row) {
    const double y = (box.iy_min + static_cast<double>(row) + 0.5) * resolution_m;
    for (std::size_t col = 0; col < nx; ++col) {
      const double x = (box.ix_min + static_cast<double>(col) + 0.5) * resolution_m;
      const Vec3f origin(static_cast<float>(x), static_cast<float>(y), ceiling);
      rays[col] = Ray{.origin_W = origin, .direction_W = -Vec3f::UnitZ(), .max_range_m = static_cast<float>(kTruthDepth_m), .see_robot = false, .see_moving = see_moving};
      up_rays[col] = Ray{.origin_W = origin, .direction_W = Vec3f::UnitZ(), .max_range_m = static_cast<float>(kTruthDepth_m), .see_robot = false, .see_moving = see_moving};
    }
    caster.Cast(rays, hits);
    caster.Cast(up_rays, up_hits);
    for (std::size_t col = 0; col < nx; ++col) {
      // the ceiling inside a solid: looking up, the first surface faces up
      // (its outside); the column is full to the ceiling
      const Hit& up = up_hits[col];
      if (up.is_hit() && up.normal_W.z() > 0) {
        heights[row * nx + col] = ceiling;
        continue;
      }
      const Hit& hit = hits[col];
      // in float, as the ray was cast: a floor at 0 reads 0 exactly
      if (hit.is_hit()) heights[row * nx + col] = ceiling - hit.distance_m;
    }
  }
  return heights;
}

}  // namespace proxsim
