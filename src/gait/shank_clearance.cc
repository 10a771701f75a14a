#include "gait/shank_clearance.h"

#include <algorithm>
#include <limits>

#include "gait/terrain_query.h"

namespace proxsim {

namespace {

// z-component of (b − a) × (c − a): > 0 when a → b → c turns counter-clockwise.
double Cross(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// The polygon's lower boundary at x (x within its span): the lowest of its
// edges' heights there.
double LowestAt(const std::vector<Vec2>& hull, double x) {
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2& a = hull[i];
    const Vec2& b = hull[(i + 1) % hull.size()];
    const double x0 = std::min(a.x(), b.x()), x1 = std::max(a.x(), b.x());
    if (x < x0 || x > x1) continue;
    const double z = x1 > x0 ? a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x()) : std::min(a.y(), b.y());
    lowest = std::min(lowest, z);
  }
  return lowest;
}

}  // namespace

std::vector<Vec2> ConvexHull2(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  // Andrew's monotone chain: the lower chain left to right, the upper right to left
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (const Vec2& p : points) {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point is the first
  return hull;
}

double ShankDeficit(const TerrainProfile& profile, const std::vector<Vec2>& hull_H, double clearance_m) {
  double deficit = -std::numeric_limits<double>::infinity();
  if (hull_H.empty()) return deficit;
  double x_lo = hull_H.front().x(), x_hi = x_lo;
  for (const Vec2& p : hull_H) {
    x_lo = std::min(x_lo, p.x());
    x_hi = std::max(x_hi, p.x());
  }
  const auto& segments = profile.segments();
  for (std::size_t i = profile.SegmentAt(x_lo); i < segments.size(); ++i) {
    const GroundSegment& g = segments[i];
    if (g.s_begin_m > x_hi) break;
    if (g.z_m == kNoGround) continue;
    // the polygon's lowest point over the part of this segment under it
    const double a = std::max(g.s_begin_m, x_lo), b = std::min(g.s_end_m, x_hi);
    if (a > b) continue;
    double lowest = std::min(LowestAt(hull_H, a), LowestAt(hull_H, b));
    for (const Vec2& p : hull_H)
      if (p.x() > a && p.x() < b) lowest = std::min(lowest, LowestAt(hull_H, p.x()));
    deficit = std::max(deficit, g.z_m + clearance_m - lowest);
  }
  return deficit;
}

}  // namespace proxsim
