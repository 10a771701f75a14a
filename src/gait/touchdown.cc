#include "gait/touchdown.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace proxsim {

namespace {

// The lines reach this far below the planned tread beyond their start height, m.
constexpr double kFeelDepthBelow_m = 3.0;

}  // namespace

Touchdown FeelTouchdown(const TerrainQuery& ground, const LandedSole& sole, double planned_z_m, double tolerance_m,
                        double reach_m) {
  // three lines across the sole at its heel, middle and toe
  std::array<Vec3, 9> from_W;
  for (int along = 0; along < 3; ++along)
    for (int across = 0; across < 3; ++across) {
      Vec3 p = sole.p_W[along] + (across - 1) * sole.half_width_m * sole.across_W;
      p.z() = planned_z_m + reach_m;
      from_W[3 * along + across] = p;
    }
  std::array<double, 9> z{};
  ground.HeightsBelow(from_W, reach_m + kFeelDepthBelow_m, z);
  // the highest surface at each of heel, middle and toe (a line that starts
  // inside something says nothing: the contact check sees that)
  std::array<double, 3> highest;
  highest.fill(kNoGround);
  for (int along = 0; along < 3; ++along)
    for (int across = 0; across < 3; ++across) {
      const double h = z[3 * along + across];
      if (std::isfinite(h)) highest[along] = std::max(highest[along], h);
    }
  const double rest_z_m = *std::max_element(highest.begin(), highest.end());
  const Vec3& heel = sole.p_W[0];
  char text[300];
  Touchdown touchdown;
  if (!std::isfinite(rest_z_m)) {
    std::snprintf(text, sizeof text, "the %s foot landed on nothing at (%.2f, %.2f): it was planned on a tread at "
                  "z = %.3f m", sole.side, heel.x(), heel.y(), planned_z_m);
  } else if (rest_z_m < planned_z_m - tolerance_m) {
    std::snprintf(text, sizeof text, "the %s foot landed %.3f m lower than planned at (%.2f, %.2f): planned on a "
                  "tread at z = %.3f m, the ground is at %.3f m (touchdown_tolerance_m %.3f)", sole.side,
                  planned_z_m - rest_z_m, heel.x(), heel.y(), planned_z_m, rest_z_m, tolerance_m);
  } else if (highest[0] < rest_z_m - tolerance_m && highest[1] < rest_z_m - tolerance_m) {
    std::snprintf(text, sizeof text, "the %s foot landed on its toe alone at (%.2f, %.2f), its heel over an edge: "
                  "the ground under its heel is %s", sole.side, heel.x(), heel.y(),
                  std::isfinite(highest[0]) ? "lower than under its toe" : "missing");
  } else {
    touchdown.rest_z_m = rest_z_m;
    return touchdown;
  }
  touchdown.fell = true;
  touchdown.reason = text;
  return touchdown;
}

}  // namespace proxsim
