#include "sim/map_terrain.h"

#include <cassert>

namespace proxsim {

void MapTerrain::HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const {
  assert(z_W.size() == from_W.size());
  for (std::size_t i = 0; i < from_W.size(); ++i) {
    const Vec3& p = from_W[i];
    const TerrainCell* cell = map_.CellAt(p.x(), p.y());
    if (cell == nullptr || !cell->has_elevation()) {
      z_W[i] = kUnknownGround;
      continue;
    }
    const double z = cell->elevation_m;
    // a surface above the line's start: the line starts inside what the map holds
    z_W[i] = z > p.z() ? kBlockedGround : z < p.z() - depth_m ? kNoGround : z;
  }
}

}  // namespace proxsim
