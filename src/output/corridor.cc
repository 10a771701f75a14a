#include "output/corridor.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace proxsim {

namespace {

// The track is followed in chords this long: the pelvis's path bends slowly.
constexpr double kChord_m = 0.1;

double DistanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

}  // namespace

Corridor::Corridor(const TrackReader& track, const TrackPoint& last, double resolution_m,
                   double half_width_m, double ahead_m)
    : resolution_m_(resolution_m), half_width_m_(half_width_m) {
  // the path walked, in chords
  std::optional<Vec2> from;
  track.ForEachTrackPoint([&](const TrackPoint& point) {
    if (!from) {
      from = point.p_W_pelvis;
      MarkSegment(*from, *from);
    }
    if ((point.p_W_pelvis - *from).norm() < kChord_m) return;
    MarkSegment(*from, point.p_W_pelvis);
    from = point.p_W_pelvis;
  });
  if (!from) return;  // no track
  MarkSegment(*from, last.p_W_pelvis);
  // and the stretch ahead
  MarkSegment(last.p_W_pelvis, last.p_W_pelvis + ahead_m * last.heading_W);
}

void Corridor::MarkSegment(const Vec2& a, const Vec2& b) {
  const double r = resolution_m_, w = half_width_m_;
  const CellIndex lo = CellOf(std::min(a.x(), b.x()) - w, std::min(a.y(), b.y()) - w, r);
  const CellIndex hi = CellOf(std::max(a.x(), b.x()) + w, std::max(a.y(), b.y()) + w, r);
  for (std::int32_t iy = lo.iy; iy <= hi.iy; ++iy) {
    for (std::int32_t ix = lo.ix; ix <= hi.ix; ++ix) {
      const Vec2 centre((ix + 0.5) * r, (iy + 0.5) * r);
      if (DistanceToSegment(centre, a, b) > w) continue;
      const CellIndex c{ix, iy};
      auto& bits = tiles_[TileKey(TileCoord(ix), TileCoord(iy))];
      const int i = CellInTile(c);
      if (bits.test(static_cast<std::size_t>(i))) continue;
      bits.set(static_cast<std::size_t>(i));
      ++count_;
      bounds_.Expand(c);
    }
  }
}

bool Corridor::Contains(CellIndex c) const {
  const auto it = tiles_.find(TileKey(TileCoord(c.ix), TileCoord(c.iy)));
  return it != tiles_.end() && it->second.test(static_cast<std::size_t>(CellInTile(c)));
}

}  // namespace proxsim
