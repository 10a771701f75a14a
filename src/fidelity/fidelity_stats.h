// The statistics of `proxsim fidelity`: each recorded reading beside the
// model's reading at the same pose, summarised by zone, by ring of zones, by
// range band and by ring × band (docs/fidelity.md says what each means).
//
// Error = simulated − recorded distance (positive: the model reads farther),
// over the readings both call valid. The median is the middle value (the
// mean of the middle two for an even count), p90 the 90th percentile of
// |error|, both linear between order statistics as numpy's default; bias is
// the mean error. Validity agreement is the fraction of readings where both
// say valid or both say invalid; the confusion counts split them.
// A reading's range band is that of the recorded distance: [0, e0),
// [e0, e1), …, [e_last, ∞); a reading the recording calls invalid has no
// distance and falls in band −1.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace proxsim {

/// One recorded reading and the model's beside it.
struct ComparedReading {
  int zone = 0;
  int ring = 0;                ///< ZoneRing of the zone
  int band = -1;               ///< RangeBand of the recorded distance; −1 where the recording says invalid
  double recorded_d_m = 0.0;   ///< NaN where the recording says invalid
  bool recorded_valid = false;
  double simulated_d_m = 0.0;  ///< the model's reading (its maximum range where it says invalid)
  bool simulated_valid = false;
};

/// The statistics of a set of compared readings (NaN where undefined: no reading both call valid).
struct FidelityStats {
  std::size_t count = 0;           ///< readings compared
  std::size_t both_valid = 0;      ///< confusion: both say valid (the errors are theirs)
  std::size_t recorded_only = 0;   ///< valid in the recording only
  std::size_t simulated_only = 0;  ///< valid in the model only
  std::size_t both_invalid = 0;
  double validity_agreement = 0.0;  ///< (both_valid + both_invalid) / count
  double median_error_m = 0.0;
  double p90_abs_error_m = 0.0;
  double bias_m = 0.0;             ///< mean error
  double median_rel_error = 0.0;   ///< the same as fractions of the recorded distance
  double p90_abs_rel_error = 0.0;
};

/// The statistics of `readings`.
FidelityStats StatsOf(std::span<const ComparedReading> readings);

/// The q-quantile (q in [0, 1]) of ascending `sorted`, linear between order statistics; NaN when empty.
double SortedQuantile(std::span<const double> sorted, double q);

/// The ring of a zone in an nx × ny grid: 0 for the centre zones (the middle
/// 2 × 2 of an even grid, the middle zone of an odd one), one more per ring
/// outwards (an 8 × 8 grid's border zones are ring 3); 0 for a single zone.
int ZoneRing(int nx, int ny, int zone);

/// The band of a distance: the number of edges at or below it.
int RangeBand(std::span<const double> edges_m, double d_m);

/// A band's name: "0-0.5 m", "2-3 m", ">= 4 m"; "invalid" for −1.
std::string RangeBandName(std::span<const double> edges_m, int band);

/// One row of the report's tables.
struct FidelityRow {
  std::string table;  ///< "all", "zone", "ring", "band" or "ring_band"
  int zone = -1;      ///< −1 where the table is not by zone
  int ring = -1;      ///< −1 where the table is not by ring
  int band = -2;      ///< −2 where the table is not by band (−1: the recording's invalid readings)
  FidelityStats stats;
};

/// Every table: all readings, each zone, each ring, each band, each ring × band
/// (rows only for groups that hold readings), in that order.
std::vector<FidelityRow> FidelityTables(std::span<const ComparedReading> readings);

}  // namespace proxsim
