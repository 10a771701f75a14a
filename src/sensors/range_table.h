// An optical time-of-flight part's longest range as a function of the
// target's reflectance ρ (the surface's IR albedo) and the ambient light A,
// from the points its datasheet tabulates (e.g. the VL53L0X's Table 11: white
// 88 % and grey 17 % targets, indoor and outdoor overcast).
//
// Between the table's points:
//  - in ρ, at one ambient level: d² is linear in ρ between two rows (the
//    returned signal goes as ρ/d², so at the detection threshold d² ∝ ρ; the
//    table's own points need not follow that law, the interpolation passes
//    through them); beyond the rows, d = d_row·√(ρ/ρ_row) from the nearest;
//  - in A: linear between two tabulated levels; beyond the highest, the
//    background-limited law d ∝ A^(−1/4) (SNR = S/√B with S ∝ ρ/d² and the
//    background B ∝ A) from it. These laws are the model's, not the datasheet's.
//
// A hit farther than this range gives no echo (status no_echo; a multi-zone
// zone's "signal rate too low"). The terrain map reads a silence only up to
// the range of the table's darkest target (SilenceRange_m): the robot does
// not know what it would have seen.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "sensors/sensor_spec.h"

namespace proxsim {

/// Where an ambient light falls among a [reflectance, ambient_klux, value]
/// table's levels: at or below its lowest level (that level's rows), between
/// two levels (`below` and `level`, weight u of the upper), or brighter than
/// its brightest (`level`). Found by a scan, without allocating: it runs for
/// every ray's echo.
struct AmbientBracket {
  enum Kind { kAtLevel, kBetween, kBrighter } kind = kAtLevel;
  double level = 0.0;
  double below = 0.0;
  double u = 0.0;
};
AmbientBracket BracketAmbient(const std::vector<std::array<double, 3>>& table, double ambient_klux);

/// The rows of one ambient level of such a table around reflectance ρ,
/// found by a scan (no allocation: this runs for every ray's echo): the
/// level's darkest and brightest rows, the brightest below ρ and the darkest
/// at or above it.
struct LevelRows {
  const std::array<double, 3>* front = nullptr;
  const std::array<double, 3>* back = nullptr;
  const std::array<double, 3>* below = nullptr;
  const std::array<double, 3>* at_or_above = nullptr;
};
LevelRows RowsAround(const std::vector<std::array<double, 3>>& table, double level, double rho);

/// The longest range a [reflectance, ambient_klux, max_range_m] table gives
/// for a target of reflectance ρ in `ambient_klux`, by the laws above (uncapped).
double TableMaxRange_m(const std::vector<std::array<double, 3>>& table, double ambient_klux, double reflectance);

/// The longest range for a target of reflectance ρ in the spec's ambient
/// light, m, never beyond max_range_m (+inf... max_range_m without a table).
double ReflectanceMaxRange_m(const SensorSpec& spec, double reflectance);

/// How far a silence of the sensor says that nothing is: max_range_m, or
/// with a range table the range of its darkest tabulated target.
double SilenceRange_m(const SensorSpec& spec);

/// The problems of the rows of a [reflectance, ambient_klux, value] table, worded after `key`.
void ValidateAmbientTable(const std::string& key, const std::vector<std::array<double, 3>>& table,
                          const char* value_expected, bool value_may_be_zero, std::vector<std::string>& problems);

/// The problems of a range table, worded after the key `range_table`.
void ValidateRangeTable(const SensorSpec& spec, std::vector<std::string>& problems);

}  // namespace proxsim
