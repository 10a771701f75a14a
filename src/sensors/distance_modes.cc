#include "sensors/distance_modes.h"

#include <algorithm>
#include <sstream>

#include "sensors/vl53l1x_settings.h"

namespace proxsim {

namespace {

// ST gives the VL53L1X's ambient light as a SPAD count rate, not in lux:
// "dark" (no IR), 50 kcps/SPAD ("lighting on a sunny day from behind a
// window") and 200 kcps/SPAD (the same "with direct illumination on the
// sensor"). They are put on scene.ambient_klux's scale with the VL53L0X
// datasheet's equivalence, 10 kcps/SPAD ≈ 5 klux of daylight (DocID029104,
// Table 11's note) — an assumption, not a VL53L1X figure: 25 and 100 klux.
constexpr double kWindowKlux = 50.0 * 5.0 / 10.0;   // 50 kcps/SPAD
constexpr double kDirectKlux = 200.0 * 5.0 / 10.0;  // 200 kcps/SPAD

// The ranging error ("± 20 mm" in the dark, "± 25 mm" at 50 and 200
// kcps/SPAD, Tables 6-8) taken as σ; the datasheet's figure is a bound on
// accuracy plus repeatability, so this is conservative. It does not depend
// on the target in the tables: one row (white) per light level.
const std::vector<std::array<double, 3>> kSigma = {{0.88, 0.0, 0.020}, {0.88, kWindowKlux, 0.025}, {0.88, kDirectKlux, 0.025}};

const std::vector<DistanceMode>& Modes() {
  static const std::vector<DistanceMode> modes = {
      // Table 8 (short mode): 130 cm for white and 54 % grey, dark and 200 kcps/SPAD;
      // 17 % grey 130 cm dark, 120 cm at 200 kcps/SPAD (Table 4 gives 136/135 cm for white)
      {"vl53l1x", "short", 1.30,
       {{0.88, 0.0, 1.30}, {0.54, 0.0, 1.30}, {0.17, 0.0, 1.30},
        {0.88, kDirectKlux, 1.30}, {0.54, kDirectKlux, 1.30}, {0.17, kDirectKlux, 1.20}},
       kSigma},
      // Table 4 (white 88 % only): 290 cm dark, 76 cm at 200 kcps/SPAD; no
      // table by target: darker targets follow range_table's √ρ law
      {"vl53l1x", "medium", 2.90, {{0.88, 0.0, 2.90}, {0.88, kDirectKlux, 0.76}}, kSigma},
      // Tables 6 and 7 (long mode, typical): white 360 / 166 / 73 cm, grey 54 %
      // 340 / 154 / 69 cm, grey 17 % 170 / 114 / 68 cm (dark / 50 / 200 kcps/SPAD)
      {"vl53l1x", "long", 3.60,
       {{0.88, 0.0, 3.60}, {0.54, 0.0, 3.40}, {0.17, 0.0, 1.70},
        {0.88, kWindowKlux, 1.66}, {0.54, kWindowKlux, 1.54}, {0.17, kWindowKlux, 1.14},
        {0.88, kDirectKlux, 0.73}, {0.54, kDirectKlux, 0.69}, {0.17, kDirectKlux, 0.68}},
       kSigma},
  };
  return modes;
}

}  // namespace

std::span<const DistanceMode> DistanceModes() { return Modes(); }

const DistanceMode* FindDistanceMode(const std::string& part, const std::string& name) {
  for (const DistanceMode& mode : Modes()) {
    if (part == mode.part && name == mode.name) return &mode;
  }
  return nullptr;
}

std::string DistanceModeNames(const std::string& part) {
  std::string names;
  for (const DistanceMode& mode : Modes()) {
    if (part == mode.part) names += (names.empty() ? "" : ", ") + std::string(mode.name);
  }
  return names;
}

// long: the default mode (ESPHome's VL53L1X documentation: "Long mode: up to about 4m in the dark (default)")
std::string DefaultDistanceMode(const std::string& part) { return part == "vl53l1x" ? "long" : ""; }

void ApplyDistanceMode(const DistanceMode& mode, SensorSpec& spec) {
  spec.distance_mode = mode.name;
  spec.sigma_table = mode.sigma_table;
  // the region of interest and the timing budget scale the mode's ranges (vl53l1x_settings.h)
  const std::array<int, 2> roi = spec.roi_spads[0] > 0 ? spec.roi_spads : std::array<int, 2>{kVl53l1xFullRoi, kVl53l1xFullRoi};
  const double budget_ms = spec.timing_budget_ms > 0 ? spec.timing_budget_ms : kVl53l1xDefaultBudget_ms;
  const double budget_factor = TimingBudgetRangeFactor(mode.name, budget_ms);
  const double ceiling_m = ModeCeiling_m(mode.name, mode.max_range_m);
  spec.range_table = mode.range_table;
  spec.max_range_m = 0.0;
  for (auto& [rho, klux, range_m] : spec.range_table) {
    range_m = std::min(range_m * RoiRangeFraction(roi, rho) * budget_factor, ceiling_m);
    spec.max_range_m = std::max(spec.max_range_m, range_m);
  }
  if (spec.range_table.empty()) spec.max_range_m = mode.max_range_m;
  if (spec.beam) spec.beam->aperture_deg = RoiFieldOfView_deg(roi);
  // one ranging per timing budget
  spec.max_rate_hz = 1000.0 / budget_ms;
  std::ostringstream source;
  source << "one ranging per timing budget of " << budget_ms
         << " ms (ST's VL53L1X ULD: \"Intermeasurement period must be >/= timing budget\")";
  spec.max_rate_source = source.str();
}

}  // namespace proxsim
