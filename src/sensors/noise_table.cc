#include "sensors/noise_table.h"

#include <algorithm>

#include "sensors/range_table.h"

namespace proxsim {

namespace {

// σ at reflectance ρ among one level's [ρ, σ] rows (ρ ascending): linear between rows, held beyond
double SigmaAtLevel(const std::vector<std::array<double, 2>>& rows, double rho) {
  if (rho <= rows.front()[0]) return rows.front()[1];
  if (rho >= rows.back()[0]) return rows.back()[1];
  const auto upper = std::upper_bound(rows.begin(), rows.end(), rho,
                                      [](double r, const std::array<double, 2>& row) { return r < row[0]; });
  const auto& a = *(upper - 1);
  const auto& b = *upper;
  return a[1] + (rho - a[0]) / (b[0] - a[0]) * (b[1] - a[1]);
}

}  // namespace

double SigmaAt(const SensorSpec& spec, double reflectance) {
  if (spec.sigma_table.empty()) return spec.noise.sigma;
  const AmbientLevels levels = RowsByAmbient(spec.sigma_table);
  const double a = std::max(spec.ambient_klux, 0.0);
  const auto above = levels.lower_bound(a);
  if (above == levels.begin()) return SigmaAtLevel(above->second, reflectance);
  if (above == levels.end()) return SigmaAtLevel(levels.rbegin()->second, reflectance);
  const auto below = std::prev(above);
  const double u = (a - below->first) / (above->first - below->first);
  return (1 - u) * SigmaAtLevel(below->second, reflectance) + u * SigmaAtLevel(above->second, reflectance);
}

NoiseSpec NoiseAt(const SensorSpec& spec, double reflectance) {
  NoiseSpec noise = spec.noise;
  noise.sigma = SigmaAt(spec, reflectance);
  return noise;
}

double LargestSigma(const SensorSpec& spec) {
  double largest = spec.sigma_table.empty() ? spec.noise.sigma : 0.0;
  for (const auto& row : spec.sigma_table) largest = std::max(largest, row[2]);
  return largest;
}

void ValidateSigmaTable(const SensorSpec& spec, std::vector<std::string>& problems) {
  if (spec.sigma_table.empty()) return;
  if (!(spec.type == SensorType::kLaser || spec.type == SensorType::kMultizone)) {
    problems.push_back(std::string("noise.sigma_table: expected only for an optical time-of-flight sensor (laser, "
                                   "multizone), got a table for a ") +
                       SensorTypeName(spec.type) + " sensor");
  }
  ValidateAmbientTable("noise.sigma_table", spec.sigma_table, "a standard deviation >= 0 in the noise model's unit",
                       true, problems);
}

}  // namespace proxsim
