#include "sensors/noise_table.h"

#include <algorithm>

#include "sensors/range_table.h"

namespace proxsim {

namespace {

// σ at reflectance ρ among one level's rows: linear between the rows around
// it, the end row's beyond them (a scan, no allocation: it runs per echo)
double SigmaAtLevel(const std::vector<std::array<double, 3>>& table, double level, double rho) {
  const LevelRows rows = RowsAround(table, level, rho);
  if (rho <= (*rows.front)[0]) return (*rows.front)[2];
  if (rho >= (*rows.back)[0]) return (*rows.back)[2];
  const auto& a = *rows.below;
  const auto& b = *rows.at_or_above;
  if (b[0] == rho) return b[2];  // on a row: its σ
  return a[2] + (rho - a[0]) / (b[0] - a[0]) * (b[2] - a[2]);
}

}  // namespace

double SigmaAt(const SensorSpec& spec, double reflectance) {
  if (spec.sigma_table.empty()) return spec.noise.sigma;
  const AmbientBracket bracket = BracketAmbient(spec.sigma_table, spec.ambient_klux);
  switch (bracket.kind) {
    case AmbientBracket::kAtLevel:
    case AmbientBracket::kBrighter:  // beyond the brightest level: its σ
      return SigmaAtLevel(spec.sigma_table, bracket.level, reflectance);
    case AmbientBracket::kBetween:
      return (1 - bracket.u) * SigmaAtLevel(spec.sigma_table, bracket.below, reflectance) +
             bracket.u * SigmaAtLevel(spec.sigma_table, bracket.level, reflectance);
  }
  return spec.noise.sigma;
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
