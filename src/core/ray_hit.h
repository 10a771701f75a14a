// A ray's first hit as the ray caster reports it (raycast/ray_caster.h):
// the vocabulary the caster and the sensor models share, so that what reads
// a beam's hits (sensors/: crosstalk, zones) needs no ray-tracing library.
//
// Frames: W world.
#pragma once

#include <cstdint>
#include <limits>

#include "core/geometry.h"

namespace proxsim {

/// The first hit of a ray, or a miss.
struct Hit {
  float distance_m = std::numeric_limits<float>::infinity();  ///< +inf on a miss
  Vec3f normal_W = Vec3f::Zero();  ///< unit geometric normal, as the surface has it (either side)
  std::int32_t object_id = -1;     ///< the BodyShape's object_id; -1 on a miss

  bool is_hit() const { return object_id >= 0; }
};

}  // namespace proxsim
