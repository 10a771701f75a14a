#include "gait/felt_ground.h"

namespace proxsim {

namespace {

// A point this close outside a sole's outline is under it: the profile's side
// lines run exactly along the sole's edges, m.
constexpr double kOutlineSlack_m = 1e-6;

}  // namespace

bool Footprint::Covers(const Vec3& p_W) const {
  const Vec2 heel = p_W_heel.head<2>(), along = (p_W_toe - p_W_heel).head<2>();
  const double length_m = along.norm();
  if (length_m <= 0) return false;
  const Vec2 unit = along / length_m, d = p_W.head<2>() - heel;
  const double s = d.dot(unit), across = unit.x() * d.y() - unit.y() * d.x();
  return s >= -kOutlineSlack_m && s <= length_m + kOutlineSlack_m &&
         std::abs(across) <= half_width_m + kOutlineSlack_m;
}

void FeltGround::HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const {
  map_.HeightsBelow(from_W, depth_m, z_W);
  for (std::size_t i = 0; i < from_W.size(); ++i) {
    for (const Footprint& foot : footprints_) {
      if (!foot.Covers(from_W[i])) continue;
      const double top = from_W[i].z();
      z_W[i] = foot.z_m > top ? kBlockedGround : foot.z_m < top - depth_m ? kNoGround : foot.z_m;
      break;
    }
  }
}

}  // namespace proxsim
