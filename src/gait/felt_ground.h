// What a robot planning its footholds on its own map (`gait.footholds: map`)
// plans on: the map, except under its planted feet, whose soles rest where
// the legs felt the true ground (gait/touchdown.h). A foot that settled a
// centimetre below what the map holds there stands on that lower ground; the
// swing leaving it, and the next foothold planned beside it, start from
// there, not from inside the map's surface.
//
// Frames: W world.
#pragma once

#include <vector>

#include "core/geometry.h"
#include "gait/terrain_query.h"

namespace proxsim {

/// A planted sole on the ground: heel to toe along a horizontal line.
struct Footprint {
  Vec3 p_W_heel = Vec3::Zero();  ///< x, y used
  Vec3 p_W_toe = Vec3::UnitX();  ///< x, y used
  double half_width_m = 0;
  double z_m = 0;                ///< the height the legs felt it rest on

  /// Whether world point (x, y) lies under the sole.
  bool Covers(const Vec3& p_W) const;
};

class FeltGround : public TerrainQuery {
 public:
  /// `map` (what the footholds are planned on) must outlive this.
  explicit FeltGround(const TerrainQuery& map) : map_(map) {}

  /// The planted feet from now on.
  void set_footprints(std::vector<Footprint> footprints) { footprints_ = std::move(footprints); }
  const std::vector<Footprint>& footprints() const { return footprints_; }

  void HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const override;

 private:
  const TerrainQuery& map_;
  std::vector<Footprint> footprints_;
};

}  // namespace proxsim
