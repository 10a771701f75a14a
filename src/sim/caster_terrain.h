// The gait's terrain (gait/terrain_query.h) answered by a ray caster of the
// scene's ground: vertical rays down from the asked points, so that the feet
// stand on the scene's true ground. Only the objects flagged `ground` are in
// that caster (World builds it): a line over an obstacle, a chair or a table
// meets the ground below it, so a foot is never planned on one (walking into
// it is a collision).
//
// Frames: W world.
#pragma once

#include <vector>

#include "gait/terrain_query.h"
#include "raycast/ray_caster.h"

namespace proxsim {

class CasterTerrain : public TerrainQuery {
 public:
  /// `caster` holds the ground (and nothing else the feet may not stand on);
  /// it must outlive this and be committed before the first query.
  explicit CasterTerrain(const RayCaster& caster) : caster_(caster) {}

  void HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const override;

 private:
  const RayCaster& caster_;
  // reused between queries (the gait asks from one thread at a time)
  mutable std::vector<Ray> rays_;
  mutable std::vector<Hit> hits_;
};

}  // namespace proxsim
