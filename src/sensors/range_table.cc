#include "sensors/range_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace proxsim {

namespace {

// the range at reflectance ρ among the rows of one ambient level (ρ ascending)
double RangeAtLevel(const std::vector<std::array<double, 2>>& rows, double rho) {
  if (rows.size() == 1 || rho <= rows.front()[0]) {
    const auto& row = rows.front();
    return row[1] * std::sqrt(std::max(rho, 0.0) / row[0]);
  }
  if (rho >= rows.back()[0]) return rows.back()[1] * std::sqrt(rho / rows.back()[0]);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rho > rows[i][0]) continue;
    const auto& a = rows[i - 1];
    const auto& b = rows[i];
    const double u = (rho - a[0]) / (b[0] - a[0]);
    return std::sqrt(std::max(0.0, a[1] * a[1] + u * (b[1] * b[1] - a[1] * a[1])));
  }
  return rows.back()[1];
}

}  // namespace

AmbientLevels RowsByAmbient(const std::vector<std::array<double, 3>>& table) {
  AmbientLevels levels;
  for (const auto& [rho, klux, value] : table) levels[klux].push_back({rho, value});
  for (auto& [klux, rows] : levels) std::sort(rows.begin(), rows.end());
  return levels;
}

double ReflectanceMaxRange_m(const SensorSpec& spec, double reflectance) {
  if (spec.range_table.empty()) return spec.max_range_m;
  const auto levels = RowsByAmbient(spec.range_table);
  const double a = std::max(spec.ambient_klux, 0.0);
  double d_m = 0;
  const auto above = levels.lower_bound(a);
  if (above == levels.begin()) {
    d_m = RangeAtLevel(above->second, reflectance);  // at or below the lowest level: its range
  } else if (above == levels.end()) {
    // brighter than the table: background-limited, d ∝ A^(−1/4)
    const auto& [top_klux, rows] = *levels.rbegin();
    d_m = RangeAtLevel(rows, reflectance) * (top_klux > 0 ? std::pow(top_klux / a, 0.25) : 1.0);
  } else {
    const auto below = std::prev(above);
    const double u = (a - below->first) / (above->first - below->first);
    d_m = (1 - u) * RangeAtLevel(below->second, reflectance) + u * RangeAtLevel(above->second, reflectance);
  }
  return std::min(d_m, spec.max_range_m);
}

double SilenceRange_m(const SensorSpec& spec) {
  if (spec.range_table.empty()) return spec.max_range_m;
  double darkest = std::numeric_limits<double>::infinity();
  for (const auto& row : spec.range_table) darkest = std::min(darkest, row[0]);
  return ReflectanceMaxRange_m(spec, darkest);
}

void ValidateAmbientTable(const std::string& key, const std::vector<std::array<double, 3>>& table,
                          const char* value_expected, bool value_may_be_zero, std::vector<std::string>& problems) {
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& [rho, klux, value] = table[i];
    const auto fail = [&](int column, const char* expected, double got) {
      std::ostringstream message;
      message << key << "[" << i << "][" << column << "]: expected " << expected << ", got " << got;
      problems.push_back(message.str());
    };
    if (!std::isfinite(rho) || rho <= 0 || rho > 1) fail(0, "a reflectance in (0, 1]", rho);
    if (!std::isfinite(klux) || klux < 0) fail(1, "an ambient light >= 0 klux", klux);
    if (!std::isfinite(value) || value < 0 || (value == 0 && !value_may_be_zero)) fail(2, value_expected, value);
    for (std::size_t j = 0; j < i; ++j) {
      if (table[j][0] == rho && table[j][1] == klux) fail(0, "one row per reflectance and ambient light", rho);
    }
  }
}

void ValidateRangeTable(const SensorSpec& spec, std::vector<std::string>& problems) {
  if (spec.range_table.empty()) return;
  if (!(spec.type == SensorType::kLaser || spec.type == SensorType::kMultizone)) {
    problems.push_back(std::string("range_table: expected only for an optical time-of-flight sensor (laser, "
                                   "multizone), got a table for a ") +
                       SensorTypeName(spec.type) + " sensor");
  }
  ValidateAmbientTable("range_table", spec.range_table, "a range > 0 m", false, problems);
}

}  // namespace proxsim
