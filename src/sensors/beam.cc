#include "sensors/beam.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace proxsim {

namespace {

// y(x) through [x, y] rows (x ascending, at least one row), held beyond the ends
double PiecewiseLinear(const std::vector<std::array<double, 2>>& rows, double x) {
  if (x <= rows.front()[0]) return rows.front()[1];
  if (x >= rows.back()[0]) return rows.back()[1];
  const auto upper = std::upper_bound(rows.begin(), rows.end(), x,
                                      [](double value, const std::array<double, 2>& row) { return value < row[0]; });
  const auto& [x1, y1] = *upper;
  const auto& [x0, y0] = *(upper - 1);
  return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

}  // namespace

double BeamReachDeg(const BeamSpec& beam, double d_m) {
  const double half_aperture_deg = 0.5 * beam.aperture_deg;
  return beam.reach.empty() ? half_aperture_deg : std::min(half_aperture_deg, PiecewiseLinear(beam.reach, d_m));
}

bool BeamReaches(const std::optional<BeamSpec>& beam, double off_axis_deg, double d_m) {
  // the axis ray is always heard: a reach table narrows the lobe, it does not close it
  return !beam || off_axis_deg == 0.0 || off_axis_deg <= BeamReachDeg(*beam, d_m);
}

double BeamGain(const BeamSpec& beam, double off_axis_deg) {
  switch (beam.pattern) {
    case BeamPattern::kUniform:
      return 1.0;
    case BeamPattern::kGaussian: {
      const double x = off_axis_deg / beam.width_deg;
      return std::exp(-0.5 * x * x);
    }
    case BeamPattern::kTable: {
      double peak = 0;
      for (const auto& row : beam.table) peak = std::max(peak, row[1]);
      if (beam.table.empty() || !(peak > 0)) return 0.0;
      return PiecewiseLinear(beam.table, off_axis_deg) / peak;
    }
  }
  return 1.0;
}

std::vector<BeamRay> MakeBeamRays(const std::optional<BeamSpec>& beam) {
  // the paper's single ray
  if (!beam || beam->rays <= 1) return {BeamRay{}};

  // K rings for the rays around the axis, about 3·K·(K+1) of them
  const int around = beam->rays - 1;
  int rings = std::max(1, static_cast<int>(std::lround(std::sqrt(around / 3.0))));
  rings = std::min(rings, around);
  const double half_rad = DegToRad(0.5 * beam->aperture_deg);
  const double step_rad = half_rad / rings;

  // ring k holds a share of the rays proportional to k; the remainder goes to the outer rings
  std::vector<int> per_ring(rings);
  const int triangle = rings * (rings + 1) / 2;
  int given = 0;
  for (int k = 1; k <= rings; ++k) given += per_ring[k - 1] = std::max(1, around * k / triangle);
  // (the floor of each share is >= 1 for every K this picks, so `given` never exceeds `around`)
  for (int k = rings; given < around; k = k > 1 ? k - 1 : rings) {
    ++per_ring[k - 1];
    ++given;
  }

  // the axis ray stands for the cap [0, step/2]; ring k for the band around θ_k, cut at the cone's edge
  std::vector<BeamRay> rays;
  rays.reserve(beam->rays);
  const auto cap = [](double a, double b) { return 2.0 * std::numbers::pi * (std::cos(a) - std::cos(b)); };
  rays.push_back({Vec3::UnitX(), 0.0, BeamGain(*beam, 0.0), cap(0.0, 0.5 * step_rad)});
  for (int k = 1; k <= rings; ++k) {
    const double theta = k * step_rad;
    const double solid_angle = cap(theta - 0.5 * step_rad, std::min(theta + 0.5 * step_rad, half_rad)) / per_ring[k - 1];
    const double gain = BeamGain(*beam, RadToDeg(theta));
    for (int j = 0; j < per_ring[k - 1]; ++j) {
      // φ = 0 lies along the sensor's +y, so every ring has a ray in the x-y plane
      const double phi = 2.0 * std::numbers::pi * j / per_ring[k - 1];
      rays.push_back({Vec3(std::cos(theta), std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi)),
                      RadToDeg(theta), gain, solid_angle * gain});
    }
  }

  // weights to Σw = 1 (a pattern that is zero everywhere leaves them zero)
  double total = 0;
  for (const BeamRay& ray : rays) total += ray.weight;
  for (BeamRay& ray : rays) ray.weight = total > 0 ? ray.weight / total : 0.0;
  return rays;
}

Vec3 BeamRayDir_W(const Pose& X_WS, const BeamRay& ray) {
  return ray.off_axis_deg == 0.0 ? Vec3(X_WS.linear().col(0)) : Vec3(X_WS.linear() * ray.dir_S);
}

}  // namespace proxsim
