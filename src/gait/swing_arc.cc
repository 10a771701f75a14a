#include "gait/swing_arc.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace proxsim {

namespace {

// The start rate's term lasts this long: g(u) = u·(1 − u/τ)², slope 1 at 0, gone by τ.
constexpr double kStartRateSpan = 0.2;
// Points sampled along the sole, heel to toe.
constexpr int kSolePoints = 7;

double Smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

double StartRateTerm(double u) {
  if (u >= kStartRateSpan) return 0;
  const double r = 1 - u / kStartRateSpan;
  return u * r * r;
}

}  // namespace

double SwingArc::LiftShape(double u) {
  return Smoothstep(u / kArcLiftRise) * Smoothstep((1 - u) / (1 - kArcLowerStart));
}

double SwingArc::CarryShape(double u) const {
  return Smoothstep((u - carry_start) / (kArcCarryEnd - carry_start));
}

Vec2 SwingArc::At(double u) const {
  u = std::clamp(u, 0.0, 1.0);
  const double carry = CarryShape(u);
  // climbing, the height is gained early; descending, it is lost late
  const double height = end.y() >= start.y() ? Smoothstep(u / height_span)
                                             : Smoothstep((u - (1 - height_span)) / height_span);
  const double g = StartRateTerm(u);
  return {start.x() + (end.x() - start.x()) * carry + start_rate.x() * g,
          start.y() + (end.y() - start.y()) * height + start_rate.y() * g + lift_m * LiftShape(u)};
}

std::pair<Vec2, Vec2> SoleEnds(const Vec2& ankle_H, double pitch_rad, const SoleShape& sole) {
  const double c = std::cos(pitch_rad), s = std::sin(pitch_rad);
  const auto turn = [&](const Vec2& v) { return Vec2(v.x() * c - v.y() * s, v.x() * s + v.y() * c); };
  return {ankle_H + turn(sole.heel_from_ankle), ankle_H + turn(sole.toe_from_ankle)};
}

double SoleDeficit(const TerrainProfile& profile, const Vec2& ankle_H, double pitch_rad, const SoleShape& sole,
                   double clearance_m, std::size_t own_a, std::size_t own_b, double edge_reach_m) {
  const auto [heel, toe] = SoleEnds(ankle_H, pitch_rad, sole);
  const auto& segments = profile.segments();
  double deficit = -std::numeric_limits<double>::infinity();

  // the sole's points above the ground (a clearance everywhere but on its own treads)
  for (int k = 0; k < kSolePoints; ++k) {
    const Vec2 q = heel + (toe - heel) * (static_cast<double>(k) / (kSolePoints - 1));
    const std::size_t i = profile.SegmentAt(q.x());
    const double z = segments[i].z_m;
    if (z == kNoGround) continue;
    const double needed = z + (i == own_a || i == own_b ? 0.0 : clearance_m);
    deficit = std::max(deficit, needed - q.y());
  }
  // the points of the front and back faces, above the ground the same way
  const double c = std::cos(pitch_rad), sn = std::sin(pitch_rad);
  const Vec2 up(-sn, c);  // the foot's up in H
  for (const auto& [end, top] : {std::pair{toe, sole.toe_top_m}, std::pair{heel, sole.heel_top_m}}) {
    for (int k = 1; k < kSolePoints && top > 0; ++k) {
      const Vec2 q = end + up * (top * k / (kSolePoints - 1));
      const std::size_t i = profile.SegmentAt(q.x());
      const double z = segments[i].z_m;
      if (z == kNoGround) continue;
      deficit = std::max(deficit, z + (i == own_a || i == own_b ? 0.0 : clearance_m) - q.y());
    }
  }
  // every edge under the sole (or within reach of its ends), by the clearance
  const double s_lo = std::min(heel.x(), toe.x()), s_hi = std::max(heel.x(), toe.x());
  for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
    const double s_edge = segments[i].s_end_m;
    if (s_edge < s_lo - edge_reach_m || s_edge > s_hi + edge_reach_m) continue;
    const double z_edge = std::max(segments[i].z_m, segments[i + 1].z_m);
    if (z_edge == kNoGround) continue;
    const double t = s_hi > s_lo ? std::clamp((s_edge - heel.x()) / (toe.x() - heel.x()), 0.0, 1.0) : 0.0;
    const double z_sole = heel.y() + t * (toe.y() - heel.y());
    deficit = std::max(deficit, z_edge + clearance_m - z_sole);
  }
  return deficit;
}

}  // namespace proxsim
