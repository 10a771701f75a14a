#include "gait/terrain_profile.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace proxsim {

namespace {

// Two heights on one level: within the tolerance, or the same kind of "none".
bool SameLevel(double a, double b) {
  if (!std::isfinite(a) || !std::isfinite(b)) return a == b;
  return std::abs(a - b) <= kLevelTolerance_m;
}

// The terrain's answers, with what it does not know taken as `unknown_z_m`.
template <class Heights>
void FillUnknown(Heights& z, double unknown_z_m) {
  for (double& h : z)
    if (std::isnan(h)) h = unknown_z_m;
}

}  // namespace

TerrainProfile::TerrainProfile(const TerrainQuery& terrain, const ProfileLine& line) : line_(line) {
  const double length = std::max(0.0, line.s_end_m - line.s_begin_m);
  const int n = static_cast<int>(std::ceil(length / kProfileStep_m - 1e-9)) + 1;
  const double step = n > 1 ? length / (n - 1) : 0.0;

  // the coarse samples, three lines across the sole in one batch
  const Vec2 left(-line.direction_W.y(), line.direction_W.x());
  std::vector<Vec3> from_W;
  from_W.reserve(3 * n);
  for (int i = 0; i < n; ++i) {
    const Vec2 p = line.origin_W + (line.s_begin_m + i * step) * line.direction_W;
    for (const double side : {-1.0, 0.0, 1.0}) {
      const Vec2 q = p + side * line.half_width_m * left;
      from_W.emplace_back(q.x(), q.y(), line.z_top_m);
    }
  }
  std::vector<double> z(from_W.size());
  terrain.HeightsBelow(from_W, line.depth_m, z);
  FillUnknown(z, line.unknown_z_m);
  lines_cast_ += static_cast<int>(from_W.size());
  const auto envelope = [&](int i) { return std::max({z[3 * i], z[3 * i + 1], z[3 * i + 2]}); };
  const auto support = [&](int i) { return std::min({z[3 * i], z[3 * i + 1], z[3 * i + 2]}); };

  // level segments; each change of level located by bisection
  GroundSegment current{.s_begin_m = line.s_begin_m, .s_end_m = line.s_begin_m, .z_m = envelope(0)};
  double first_z = current.z_m, lowest_support = support(0);
  const auto close = [&](double s_end) {
    current.s_end_m = s_end;
    current.full_width = std::isfinite(current.z_m) && lowest_support >= current.z_m - kLevelTolerance_m;
    segments_.push_back(current);
  };
  for (int i = 1; i < n; ++i) {
    const double hi = envelope(i);
    if (SameLevel(hi, first_z)) {
      current.z_m = std::max(current.z_m, hi);
      lowest_support = std::min(lowest_support, support(i));
      continue;
    }
    double a = line.s_begin_m + (i - 1) * step, b = line.s_begin_m + i * step;
    while (b - a > kEdgeResolution_m) {
      const double mid = 0.5 * (a + b);
      (SameLevel(Sample(terrain, mid).first, first_z) ? a : b) = mid;
    }
    const double edge = 0.5 * (a + b);
    close(edge);
    current = GroundSegment{.s_begin_m = edge, .s_end_m = edge, .z_m = hi};
    first_z = hi;
    lowest_support = support(i);
  }
  close(line.s_begin_m + length);
}

std::pair<double, double> TerrainProfile::Sample(const TerrainQuery& terrain, double s_m) {
  const Vec2 left(-line_.direction_W.y(), line_.direction_W.x());
  const Vec2 p = line_.origin_W + s_m * line_.direction_W;
  std::array<Vec3, 3> from_W;
  for (int k = 0; k < 3; ++k) {
    const Vec2 q = p + (k - 1) * line_.half_width_m * left;
    from_W[k] = Vec3(q.x(), q.y(), line_.z_top_m);
  }
  std::array<double, 3> z{};
  terrain.HeightsBelow(from_W, line_.depth_m, z);
  FillUnknown(z, line_.unknown_z_m);
  lines_cast_ += 3;
  return {std::max({z[0], z[1], z[2]}), std::min({z[0], z[1], z[2]})};
}

std::size_t TerrainProfile::SegmentAt(double s_m) const {
  const auto it = std::upper_bound(segments_.begin(), segments_.end(), s_m,
                                   [](double s, const GroundSegment& g) { return s < g.s_end_m; });
  return it == segments_.end() ? segments_.size() - 1 : static_cast<std::size_t>(it - segments_.begin());
}

Vec3 TerrainProfile::PointW(double s_m, double z_m) const {
  const Vec2 p = line_.origin_W + s_m * line_.direction_W;
  return Vec3(p.x(), p.y(), z_m);
}

}  // namespace proxsim
