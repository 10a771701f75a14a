#include "sensors/vl53l1x_settings.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace proxsim {

namespace {

// Table 9 (dark, long mode, ROI centred), by the ROI's side in SPADs: the
// diagonal field of view and the range for white 88 %, grey 54 % and grey
// 17 % targets, cm.
struct RoiColumn {
  double side;
  double fov_deg;
  std::array<double, 3> range_cm;  // at kTable9Reflectance
};
constexpr std::array<double, 3> kTable9Reflectance = {0.17, 0.54, 0.88};
constexpr std::array<RoiColumn, 3> kTable9 = {{
    {4, 15.0, {45, 143, 170}},
    {8, 20.0, {119, 254, 308}},
    {16, 27.0, {170, 340, 360}},
}};

// long mode's white target: 360 cm at the tables' 100 ms, 400 cm "with TB = 140 ms" (Table 6)
const double kBudgetExponent = std::log(400.0 / 360.0) / std::log(140.0 / 100.0);
constexpr double kLongModeCeiling_m = 4.0;

// the ROI's side: the square of the same SPAD count, within the array
double RoiSide(const std::array<int, 2>& roi_spads) {
  const double side = std::sqrt(static_cast<double>(roi_spads[0]) * static_cast<double>(roi_spads[1]));
  return std::clamp(side, static_cast<double>(kVl53l1xMinRoi), static_cast<double>(kVl53l1xFullRoi));
}

// a column's value at the side, linear between Table 9's columns
template <class F>
double AcrossColumns(double side, F value) {
  for (std::size_t i = 1; i < kTable9.size(); ++i) {
    if (side > kTable9[i].side) continue;
    const double u = (side - kTable9[i - 1].side) / (kTable9[i].side - kTable9[i - 1].side);
    return (1 - u) * value(kTable9[i - 1]) + u * value(kTable9[i]);
  }
  return value(kTable9.back());
}

// a column's range fraction of the full array at reflectance ρ: linear between Table 9's targets, held beyond
double FractionAt(const RoiColumn& column, double rho) {
  const auto fraction = [&](std::size_t k) { return column.range_cm[k] / kTable9.back().range_cm[k]; };
  if (rho <= kTable9Reflectance.front()) return fraction(0);
  for (std::size_t k = 1; k < kTable9Reflectance.size(); ++k) {
    if (rho > kTable9Reflectance[k]) continue;
    const double u = (rho - kTable9Reflectance[k - 1]) / (kTable9Reflectance[k] - kTable9Reflectance[k - 1]);
    return (1 - u) * fraction(k - 1) + u * fraction(k);
  }
  return fraction(kTable9Reflectance.size() - 1);
}

}  // namespace

double RoiFieldOfView_deg(const std::array<int, 2>& roi_spads) {
  return AcrossColumns(RoiSide(roi_spads), [](const RoiColumn& c) { return c.fov_deg; });
}

double RoiRangeFraction(const std::array<int, 2>& roi_spads, double reflectance) {
  return AcrossColumns(RoiSide(roi_spads), [&](const RoiColumn& c) { return FractionAt(c, reflectance); });
}

std::array<double, 2> TimingBudgetLimits_ms(const std::string& distance_mode) {
  return {distance_mode == "short" ? 20.0 : 33.0, 1000.0};
}

double TimingBudgetRangeFactor(const std::string& distance_mode, double timing_budget_ms) {
  if (distance_mode == "short" || !(timing_budget_ms > 0)) return 1.0;
  return std::pow(timing_budget_ms / kVl53l1xDefaultBudget_ms, kBudgetExponent);
}

double ModeCeiling_m(const std::string& distance_mode, double mode_max_range_m) {
  return distance_mode == "long" ? kLongModeCeiling_m : mode_max_range_m;
}

void ValidateVl53l1xSettings(const SensorSpec& spec, std::vector<std::string>& problems) {
  const bool given = spec.roi_spads[0] != 0 || spec.roi_spads[1] != 0 || spec.timing_budget_ms != 0;
  if (spec.part != "vl53l1x") {
    if (given) {
      problems.push_back(std::string(spec.roi_spads[0] != 0 || spec.roi_spads[1] != 0 ? "roi" : "timing_budget_ms") +
                         ": expected only for a vl53l1x (its region of interest and timing budget), got it for a " +
                         (spec.part.empty() ? SensorTypeName(spec.type) : spec.part) + " sensor");
    }
    return;
  }
  for (int axis = 0; axis < 2; ++axis) {
    const int spads = spec.roi_spads[static_cast<std::size_t>(axis)];
    if (spads < kVl53l1xMinRoi || spads > kVl53l1xFullRoi) {
      std::ostringstream message;
      message << "roi[" << axis << "]: expected a region of interest of " << kVl53l1xMinRoi << " to "
              << kVl53l1xFullRoi << " SPADs a side (" << kVl53l1xRoiSource << "), got " << spads;
      problems.push_back(message.str());
    }
  }
  const auto [lo_ms, hi_ms] = TimingBudgetLimits_ms(spec.distance_mode);
  if (!std::isfinite(spec.timing_budget_ms) || spec.timing_budget_ms < lo_ms || spec.timing_budget_ms > hi_ms) {
    std::ostringstream message;
    message << "timing_budget_ms: expected " << lo_ms << " to " << hi_ms << " ms in " << spec.distance_mode
            << " distance mode (" << kVl53l1xBudgetSource << "), got " << spec.timing_budget_ms;
    problems.push_back(message.str());
  }
}

}  // namespace proxsim
