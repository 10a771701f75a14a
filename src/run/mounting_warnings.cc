#include "run/mounting_warnings.h"

#include <cmath>
#include <cstdio>

#include "core/geometry.h"

namespace proxsim {

MountingWatch::MountingWatch(const Scenario& scenario, const std::vector<std::string>& object_names)
    : scenario_(scenario), object_names_(object_names), tallies_(scenario.sensors.size()) {}

void MountingWatch::Add(const SampleFrame& frame) {
  for (std::size_t s = 0; s < tallies_.size() && s < frame.sensors.size(); ++s) {
    const SensorSample& sample = frame.sensors[s];
    if (sample.reading.status == ReadingStatus::kNotSampled) continue;
    Tally& tally = tallies_[s];
    ++tally.sampled;
    if (sample.reading.detected()) ++tally.detected;
    if (sample.reading.status != ReadingStatus::kSelf) continue;
    if (tally.self == 0 || sample.echo.distance_m < tally.nearest_self_m) {
      tally.nearest_self_m = sample.echo.distance_m;
      tally.self_object = sample.object_id;
    }
    ++tally.self;
  }
}

std::vector<std::string> MountingWatch::Warnings() const {
  std::vector<std::string> warnings;
  for (std::size_t s = 0; s < tallies_.size(); ++s) {
    const Tally& tally = tallies_[s];
    const SensorConfig& sensor = scenario_.sensors[s];
    const std::string name = scenario_.source + ": sensor '" + sensor.name + "'";
    if (tally.sampled > 0 && tally.self == tally.sampled) {
      const bool named = tally.self_object >= 0 && static_cast<std::size_t>(tally.self_object) < object_names_.size();
      char line[200];
      std::snprintf(line, sizeof line, " saw only the robot's own body: all %lld of its readings were `self`, the nearest "
                    "'%s' at %.2f mm; check its pose (docs/scenario.md)",
                    static_cast<long long>(tally.sampled), named ? object_names_[tally.self_object].c_str() : "?",
                    1000.0 * tally.nearest_self_m);
      warnings.push_back(name + line);
    }
    // radians where degrees were meant: every angle within ±2π, one not 0, and nothing seen
    // (the mounting's angles as given: small angles come back from the rotation exactly enough)
    const Vec3 rpy_deg = RpyFromRotation(sensor.X_LS.linear()) * (180.0 / M_PI);
    const bool small_angles = rpy_deg.cwiseAbs().maxCoeff() < 2 * M_PI && rpy_deg.cwiseAbs().maxCoeff() > 0;
    if (tally.sampled > 0 && tally.detected == 0 && small_angles) {
      char line[240];
      std::snprintf(line, sizeof line, " detected nothing, and its rpy_deg [%g, %g, %g] are all below 2π: radians typed "
                    "as degrees? (rpy_deg is in degrees)", rpy_deg.x(), rpy_deg.y(), rpy_deg.z());
      warnings.push_back(name + line);
    }
  }
  return warnings;
}

}  // namespace proxsim
