#include "sim/sensor_rig.h"

#include "core/input_error.h"
#include "core/nearest_key.h"
#include "sensors/multizone.h"

namespace proxsim {

namespace {

// "scenario.yaml:12: sensors.NAME.link: unknown link ..." with the nearest name suggested
std::string UnknownLinkProblem(const Scenario& scenario, const SensorConfig& sensor, const RobotModel* model) {
  std::string known;
  std::vector<std::string> names;
  for (int i = 0; model != nullptr && i < model->link_count(); ++i) {
    names.push_back(model->link_name(i));
    known += (i ? ", " : "") + names.back();
  }
  const auto nearest = NearestKey(sensor.link, names);
  // appended piece by piece: GCC 12 takes `":" + std::to_string(...)` for an
  // overlapping memcpy (a false -Wrestrict at -O3)
  std::string where = scenario.source;
  if (sensor.link_line > 0) {
    where += ':';
    where += std::to_string(sensor.link_line);
  }
  return where + ": sensors." + sensor.name + ".link: unknown link '" + sensor.link + "'" +
         (nearest ? " (did you mean '" + *nearest + "'?)" : "") + "; expected world" +
         (known.empty() ? "" : " or one of " + known);
}

}  // namespace

SensorRig::SensorRig(const Scenario& scenario, const RobotModel* robot_model) {
  // every sensor's link must exist
  std::vector<std::string> problems;
  for (const SensorConfig& sensor : scenario.sensors) {
    int link = sensor.link == "world" || robot_model == nullptr ? -1 : robot_model->LinkIndex(sensor.link);
    // `root`: the robot's root link, whatever its name (unless a link is called so)
    if (link < 0 && robot_model != nullptr && sensor.link == "root") link = robot_model->root_link();
    if (sensor.link != "world" && link < 0) problems.push_back(UnknownLinkProblem(scenario, sensor, robot_model));
    sensor_link_.push_back(link);
  }
  if (!problems.empty()) throw InputError(problems);

  // the beams or zones, sensor after sensor: one ray for the paper's sensors
  ray_begin_.push_back(0);
  for (const SensorConfig& sensor : scenario.sensors) {
    const std::vector<BeamRay> beam = MakeSensorRays(sensor.spec);
    beam_rays_.insert(beam_rays_.end(), beam.begin(), beam.end());
    ray_begin_.push_back(beam_rays_.size());
  }
}

}  // namespace proxsim
