// The robot's track over the whole walk, read a point at a time: a walk's
// track can be longer than memory should hold (a point per centimetre
// walked, 64 bytes each), so it is kept in a scratch file (terrain_archive.h)
// and whoever needs it (the corridor, the score) streams it in order.
#pragma once

#include <functional>

#include "knowledge/terrain_map.h"

namespace proxsim {

class TrackReader {
 public:
  virtual ~TrackReader() = default;
  /// Calls `visit` with every point of the track, oldest first (t_s never decreases).
  virtual void ForEachTrackPoint(const std::function<void(const TrackPoint&)>& visit) const = 0;
};

}  // namespace proxsim
