#include "sensors/range_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace proxsim {

namespace {

// the range at reflectance ρ among the rows of one ambient level
double RangeAtLevel(const std::vector<std::array<double, 3>>& table, double level, double rho) {
  const LevelRows rows = RowsAround(table, level, rho);
  if (rows.front == rows.back || rho <= (*rows.front)[0]) {
    const auto& row = *rows.front;
    return row[2] * std::sqrt(std::max(rho, 0.0) / row[0]);
  }
  if (rho >= (*rows.back)[0]) return (*rows.back)[2] * std::sqrt(rho / (*rows.back)[0]);
  // d² linear in ρ between the two rows around it
  const auto& a = *rows.below;
  const auto& b = *rows.at_or_above;
  const double u = (rho - a[0]) / (b[0] - a[0]);
  return std::sqrt(std::max(0.0, a[2] * a[2] + u * (b[2] * b[2] - a[2] * a[2])));
}

}  // namespace

LevelRows RowsAround(const std::vector<std::array<double, 3>>& table, double level, double rho) {
  LevelRows rows;
  for (const auto& row : table) {
    if (row[1] != level) continue;
    if (rows.front == nullptr || row[0] < (*rows.front)[0]) rows.front = &row;
    if (rows.back == nullptr || row[0] > (*rows.back)[0]) rows.back = &row;
    if (row[0] < rho && (rows.below == nullptr || row[0] > (*rows.below)[0])) rows.below = &row;
    if (row[0] >= rho && (rows.at_or_above == nullptr || row[0] < (*rows.at_or_above)[0])) rows.at_or_above = &row;
  }
  return rows;
}

AmbientBracket BracketAmbient(const std::vector<std::array<double, 3>>& table, double ambient_klux) {
  const double a = std::max(ambient_klux, 0.0);
  AmbientBracket bracket;
  bool any_below = false, any_at_or_above = false;
  double below = 0, at_or_above = 0, top = 0;
  for (const auto& row : table) {
    const double level = row[1];
    top = std::max(top, level);
    if (level < a && (!any_below || level > below)) below = level, any_below = true;
    if (level >= a && (!any_at_or_above || level < at_or_above)) at_or_above = level, any_at_or_above = true;
  }
  if (!any_at_or_above) {
    bracket.kind = AmbientBracket::kBrighter;
    bracket.level = top;
  } else if (!any_below) {
    bracket.kind = AmbientBracket::kAtLevel;  // at or below the lowest level: that level's
    bracket.level = at_or_above;
  } else {
    bracket.kind = AmbientBracket::kBetween;
    bracket.below = below;
    bracket.level = at_or_above;
    bracket.u = (a - below) / (at_or_above - below);
  }
  return bracket;
}

double TableMaxRange_m(const std::vector<std::array<double, 3>>& table, double ambient_klux, double reflectance) {
  const AmbientBracket bracket = BracketAmbient(table, ambient_klux);
  switch (bracket.kind) {
    case AmbientBracket::kAtLevel:
      return RangeAtLevel(table, bracket.level, reflectance);
    case AmbientBracket::kBrighter: {
      // brighter than the table: background-limited, d ∝ A^(−1/4)
      const double a = std::max(ambient_klux, 0.0);
      const double top_klux = bracket.level;
      return RangeAtLevel(table, top_klux, reflectance) * (top_klux > 0 ? std::pow(top_klux / a, 0.25) : 1.0);
    }
    case AmbientBracket::kBetween:
      return (1 - bracket.u) * RangeAtLevel(table, bracket.below, reflectance) +
             bracket.u * RangeAtLevel(table, bracket.level, reflectance);
  }
  return 0.0;
}

double ReflectanceMaxRange_m(const SensorSpec& spec, double reflectance) {
  if (spec.range_table.empty()) return spec.max_range_m;
  return std::min(TableMaxRange_m(spec.range_table, spec.ambient_klux, reflectance), spec.max_range_m);
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
  if (!spec.range_table.empty() && !(spec.type == SensorType::kLaser || spec.type == SensorType::kMultizone)) {
    problems.push_back(std::string("range_table: expected only for an optical time-of-flight sensor (laser, "
                                   "multizone), got a table for a ") +
                       SensorTypeName(spec.type) + " sensor");
  }
  ValidateAmbientTable("range_table", spec.range_table, "a range > 0 m", false, problems);
  if (!spec.corner_range_table.empty() && spec.type != SensorType::kMultizone) {
    problems.push_back(std::string("corner_range_table: expected only for a multizone sensor (its corner zones' "
                                   "range), got a table for a ") +
                       SensorTypeName(spec.type) + " sensor");
  }
  ValidateAmbientTable("corner_range_table", spec.corner_range_table, "a range > 0 m", false, problems);
}

}  // namespace proxsim
