#include "terrain/truth_field.h"

#include <limits>

namespace proxsim {

std::vector<float> TrueHeights(const RayCaster& caster, const CellBox& box, double resolution_m, double max_height_m) {
  const std::size_t nx = static_cast<std::size_t>(box.nx()), ny = static_cast<std::size_t>(box.ny());
  std::vector<float> heights(nx * ny, std::numeric_limits<float>::quiet_NaN());
  std::vector<Ray> rays(nx);
  std::vector<Hit> hits(nx);
  // one row of columns per cast
  for (std::size_t row = 0; row < ny; ++row) {
    const double y = (box.iy_min + static_cast<double>(row) + 0.5) * resolution_m;
    for (std::size_t col = 0; col < nx; ++col) {
      const double x = (box.ix_min + static_cast<double>(col) + 0.5) * resolution_m;
      rays[col] = Ray{.origin_W = Vec3f(static_cast<float>(x), static_cast<float>(y), static_cast<float>(max_height_m)),
                      .direction_W = -Vec3f::UnitZ(),
                      .max_range_m = static_cast<float>(kTruthDepth_m),
                      .see_robot = false};
    }
    caster.Cast(rays, hits);
    for (std::size_t col = 0; col < nx; ++col) {
      const Hit& hit = hits[col];
      if (!hit.is_hit()) continue;
      // the first surface seen from inside faces down: the column is full to the ceiling
      const bool inside = hit.normal_W.z() < 0 && hit.distance_m > 0;
      heights[row * nx + col] = inside ? static_cast<float>(max_height_m)
                                       : static_cast<float>(max_height_m - static_cast<double>(hit.distance_m));
    }
  }
  return heights;
}

}  // namespace proxsim
