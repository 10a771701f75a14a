#include "sim/caster_terrain.h"

#include <cassert>

namespace proxsim {

namespace {

// A surface whose normal points this far down was met from below: the line
// started inside an object or under an overhang.
constexpr float kDownwardNormal = -0.5f;

}  // namespace

void CasterTerrain::HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const {
  assert(z_W.size() == from_W.size());
  rays_.resize(from_W.size());
  hits_.resize(from_W.size());
  for (std::size_t i = 0; i < from_W.size(); ++i) {
    rays_[i] = Ray{.origin_W = from_W[i].cast<float>(),
                   .direction_W = -Vec3f::UnitZ(),
                   .max_range_m = static_cast<float>(depth_m),
                   .see_robot = false};
  }
  caster_.Cast(rays_, hits_);
  for (std::size_t i = 0; i < from_W.size(); ++i) {
    const Hit& hit = hits_[i];
    if (!hit.is_hit()) {
      z_W[i] = kNoGround;
    } else if (hit.normal_W.z() < kDownwardNormal) {
      z_W[i] = kBlockedGround;
    } else {
      // the hit in double from the float distance: exact to Embree's float precision
      z_W[i] = from_W[i].z() - static_cast<double>(hit.distance_m);
    }
  }
}

}  // namespace proxsim
