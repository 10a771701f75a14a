// The VL53L1X's region of interest (`roi: [w, h]`, SPADs) and timing budget
// (`timing_budget_ms`): what each changes of the part, from ST's documents
// (docs/sensors.md cites every figure).
//
// ROI. The receiver is a 16x16 SPAD array; a smaller ROI (4x4 at least)
// narrows the field of view and shortens the range. ST tabulates three
// square ROIs, centred, in long mode in the dark (VL53L1X datasheet
// DocID031281 Rev 3, Table 9): 16x16 27°, 8x8 20°, 4x4 15° diagonal field
// of view; white 88 % 360 / 308 / 170 cm, grey 54 % 340 / 254 / 143 cm,
// grey 17 % 170 / 119 / 45 cm; ranging error ± 20 mm at each. Between and
// for other shapes the model interpolates linearly in the ROI's side
// s = √(w·h) (the square of the same SPAD count) and, for the range, in the
// reflectance; it scales every row of the mode's range table (any light) by
// Table 9's fraction of the full-array range at that reflectance. These
// interpolations and the fraction's use beyond long mode in the dark are
// the model's assumptions. The cone keeps its circular shape: its full
// angle is the diagonal field of view (as the preset's 27°).
//
// Timing budget. ST allows 20 to 1000 ms, 20 ms only in short mode and 33
// ms at least in medium and long mode (ST's STEVAL-BCN002V1 user manual,
// its VL53L1X section: "The measurement timing budget can be set from 20 to
// 1000ms ... 20ms is the minimum timing budget, can be used only in short
// distance mode; 33ms is the timing budget that can be used for all distance
// modes"; ST's ULD also offers 15 ms in short mode, beyond the datasheet's
// "up to 50 Hz": not taken). The datasheet's tables hold at 100 ms;
// its only other point is long mode's white target, 360 cm at 100 ms and
// 400 cm "with TB = 140 ms" (Table 6). The model scales the medium and long
// modes' ranges by (T / 100 ms)^k with k = ln(400/360) / ln(140/100) ≈ 0.313
// (through both points; the shot-noise law alone would give 1/4), capped at
// 400 cm ("up to 400 cm", the part's ceiling) in long mode and at the mode's
// own range in medium mode: an extrapolation below 100 ms and above 140 ms.
// Short mode's range is not scaled: its table reads 130 cm for 88 % and 17 %
// targets alike, so it is held by the mode's window, not by signal (the
// 5x less signal of the grey target costs it nothing, as a 5x shorter budget
// is taken to). σ is the datasheet's ± 20 / 25 mm at every budget: ST says a
// longer budget reduces the repeatability error but gives no figure. The
// part ranges once per timing budget: a rate above 1000 / T Hz is refused
// (ST's ULD: "Intermeasurement period must be >/= timing budget").
#pragma once

#include <array>
#include <string>
#include <vector>

#include "sensors/sensor_spec.h"

namespace proxsim {

/// The full array and the smallest ROI a side may have, SPADs.
inline constexpr int kVl53l1xFullRoi = 16;
inline constexpr int kVl53l1xMinRoi = 4;
inline constexpr const char* kVl53l1xRoiSource =
    "VL53L1X datasheet DocID031281 Rev 3: \"a custom FoV from 4x4 SPADs (minimum size) up to 16x16 SPADs (full "
    "FoV)\", Table 9";
/// The default timing budget, ms: the datasheet's tables hold at it.
inline constexpr double kVl53l1xDefaultBudget_ms = 100.0;
inline constexpr const char* kVl53l1xBudgetSource =
    "ST STEVAL-BCN002V1 user manual, VL53L1X section: 20 to 1000 ms, \"20ms ... can be used only in short distance "
    "mode\", \"33ms is the timing budget that can be used for all distance modes\"";

/// The diagonal field of view of a w x h SPAD ROI, degrees (Table 9's 15 / 20 / 27° at 4 / 8 / 16).
double RoiFieldOfView_deg(const std::array<int, 2>& roi_spads);

/// The fraction of the full array's range that a w x h ROI keeps for a
/// target of reflectance ρ (Table 9 against its 16x16 column).
double RoiRangeFraction(const std::array<int, 2>& roi_spads, double reflectance);

/// The shortest and longest timing budget ST allows in a distance mode, ms.
std::array<double, 2> TimingBudgetLimits_ms(const std::string& distance_mode);

/// The factor a timing budget applies to a mode's ranges (1 at 100 ms; 1 in short mode).
double TimingBudgetRangeFactor(const std::string& distance_mode, double timing_budget_ms);

/// The longest range the part reaches in a mode at any budget, m (long: 4 m).
double ModeCeiling_m(const std::string& distance_mode, double mode_max_range_m);

/// The problems of a spec's roi and timing_budget_ms, worded after the keys.
void ValidateVl53l1xSettings(const SensorSpec& spec, std::vector<std::string>& problems);

}  // namespace proxsim
