#include "knowledge/terrain_config.h"

#include <cmath>
#include <sstream>

namespace proxsim {

namespace {

std::string Text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

std::vector<std::string> TerrainMapConfig::Validate() const {
  std::vector<std::string> problems;
  const auto positive = [&](double value, const char* key) {
    if (!(value > 0) || !std::isfinite(value)) {
      problems.push_back(std::string(key) + ": expected a finite number > 0 m, got " + Text(value));
      return false;
    }
    return true;
  };
  if (!(resolution_m >= 0.005 && resolution_m <= 1.0)) {
    problems.push_back("resolution_m: expected a cell side in [0.005, 1] m, got " + Text(resolution_m));
  }
  if (!std::isfinite(max_height_m)) problems.push_back("max_height_m: expected a finite height in m, got " + Text(max_height_m));
  const bool rise_ok = positive(obstacle_min_m, "obstacle_min_m");
  const bool drop_ok = positive(drop_min_m, "drop_min_m");
  if (positive(step_max_m, "step_max_m") && rise_ok && drop_ok &&
      (step_max_m < obstacle_min_m || step_max_m < drop_min_m)) {
    problems.push_back("step_max_m: expected at least obstacle_min_m (" + Text(obstacle_min_m) + ") and drop_min_m (" +
                       Text(drop_min_m) + "), got " + Text(step_max_m));
  }
  positive(step_min_size_m, "step_min_size_m");
  if (!(truth_within_m >= 0.0 && truth_within_m <= 20.0)) {
    problems.push_back("truth_within_m: expected a distance in [0, 20] m (0: off), got " + Text(truth_within_m));
  }
  if (!(window_m >= 1.0) || !std::isfinite(window_m)) {
    problems.push_back("window_m: expected a finite half-side >= 1 m, got " + Text(window_m));
  }
  return problems;
}

}  // namespace proxsim
