#include "fidelity/fidelity_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <utility>

namespace proxsim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The median, p90 of |x| and mean of `values` into the three outputs (NaN for none).
void SummariseErrors(std::vector<double> values, double* median, double* p90_abs, double* mean) {
  std::sort(values.begin(), values.end());
  *median = SortedQuantile(values, 0.5);
  double sum = 0.0;
  for (double& value : values) {
    sum += value;
    value = std::abs(value);
  }
  if (mean != nullptr) *mean = values.empty() ? kNaN : sum / static_cast<double>(values.size());
  std::sort(values.begin(), values.end());
  *p90_abs = SortedQuantile(values, 0.9);
}

// "0.5" for 0.5, "2" for 2.0: a band edge as a person writes it
std::string EdgeText(double edge_m) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", edge_m);
  return text;
}

}  // namespace

double SortedQuantile(std::span<const double> sorted, double q) {
  if (sorted.empty()) return kNaN;
  const double at = q * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(at));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (at - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

FidelityStats StatsOf(std::span<const ComparedReading> readings) {
  FidelityStats stats;
  stats.count = readings.size();
  std::vector<double> errors_m, rel_errors;
  for (const ComparedReading& r : readings) {
    if (r.recorded_valid && r.simulated_valid) {
      ++stats.both_valid;
      const double error_m = r.simulated_d_m - r.recorded_d_m;
      errors_m.push_back(error_m);
      // a relative error needs a distance to be relative to
      if (r.recorded_d_m > 0) rel_errors.push_back(error_m / r.recorded_d_m);
    } else if (r.recorded_valid) {
      ++stats.recorded_only;
    } else if (r.simulated_valid) {
      ++stats.simulated_only;
    } else {
      ++stats.both_invalid;
    }
  }
  stats.validity_agreement =
      stats.count == 0 ? kNaN : static_cast<double>(stats.both_valid + stats.both_invalid) / static_cast<double>(stats.count);
  SummariseErrors(std::move(errors_m), &stats.median_error_m, &stats.p90_abs_error_m, &stats.bias_m);
  SummariseErrors(std::move(rel_errors), &stats.median_rel_error, &stats.p90_abs_rel_error, nullptr);
  return stats;
}

int ZoneRing(int nx, int ny, int zone) {
  const int row = zone / nx, column = zone % nx;
  // twice the offset from the grid's centre, in cells: odd for an even grid, even for an odd one
  return std::max(std::abs(2 * column - (nx - 1)), std::abs(2 * row - (ny - 1))) / 2;
}

int RangeBand(std::span<const double> edges_m, double d_m) {
  return static_cast<int>(std::upper_bound(edges_m.begin(), edges_m.end(), d_m) - edges_m.begin());
}

std::string RangeBandName(std::span<const double> edges_m, int band) {
  if (band < 0) return "invalid";
  if (edges_m.empty()) return "all";
  if (band >= static_cast<int>(edges_m.size())) return ">= " + EdgeText(edges_m.back()) + " m";
  return (band == 0 ? std::string("0") : EdgeText(edges_m[band - 1])) + "-" + EdgeText(edges_m[band]) + " m";
}

std::vector<FidelityRow> FidelityTables(std::span<const ComparedReading> readings) {
  std::vector<FidelityRow> rows;
  rows.push_back({.table = "all", .stats = StatsOf(readings)});
  // one table: the readings grouped by `key` (ascending), a row per group
  const auto table = [&](const char* name, const std::function<std::pair<int, int>(const ComparedReading&)>& key,
                         const std::function<void(FidelityRow&, std::pair<int, int>)>& label) {
    std::map<std::pair<int, int>, std::vector<ComparedReading>> groups;
    for (const ComparedReading& r : readings) groups[key(r)].push_back(r);
    for (const auto& [group, members] : groups) {
      FidelityRow row{.table = name, .stats = StatsOf(members)};
      label(row, group);
      rows.push_back(std::move(row));
    }
  };
  table("zone", [](const ComparedReading& r) { return std::pair(r.zone, 0); },
        [](FidelityRow& row, std::pair<int, int> g) { row.zone = g.first; });
  table("ring", [](const ComparedReading& r) { return std::pair(r.ring, 0); },
        [](FidelityRow& row, std::pair<int, int> g) { row.ring = g.first; });
  table("band", [](const ComparedReading& r) { return std::pair(r.band, 0); },
        [](FidelityRow& row, std::pair<int, int> g) { row.band = g.first; });
  table("ring_band", [](const ComparedReading& r) { return std::pair(r.ring, r.band); },
        [](FidelityRow& row, std::pair<int, int> g) {
          row.ring = g.first;
          row.band = g.second;
        });
  return rows;
}

}  // namespace proxsim
