// The gait's terrain (gait/terrain_query.h) answered by the world's ray
// caster: vertical rays down from the asked points, the robot's own links
// transparent, so that the feet stand on the scene's true surface.
//
// Frames: W world.
#pragma once

#include <vector>

#include "gait/terrain_query.h"
#include "raycast/ray_caster.h"

namespace proxsim {

class CasterTerrain : public TerrainQuery {
 public:
  /// `caster` must outlive this and be committed before the first query.
  explicit CasterTerrain(const RayCaster& caster) : caster_(caster) {}

  void HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const override;

 private:
  const RayCaster& caster_;
  // reused between queries (the gait asks from one thread at a time)
  mutable std::vector<Ray> rays_;
  mutable std::vector<Hit> hits_;
};

}  // namespace proxsim
