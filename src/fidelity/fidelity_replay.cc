#include "fidelity/fidelity_replay.h"

#include "core/parallel.h"
#include "sensors/multizone.h"
#include "sim/sample_frame.h"
#include "sim/sensor_reader.h"
#include "sim/sensor_rig.h"
#include "sim/world.h"

namespace proxsim {

int ReportedZoneCount(const SensorConfig& sensor) { return sensor.spec.zones ? ZoneCount(*sensor.spec.zones) : 1; }

ReplayedReadings ReplayRecording(const Scenario& scenario, const Recording& recording, int threads) {
  World world(scenario, nullptr, threads);
  const SensorRig rig(scenario, nullptr);
  SensorReader reader(scenario, world, rig);
  ParallelRunner runner(threads);
  const auto zones = static_cast<std::size_t>(recording.zone_count);
  ReplayedReadings out;
  out.d_m.assign(recording.sample_count() * zones, 0.0);
  out.valid.assign(recording.sample_count() * zones, 0);
  out.status.assign(recording.sample_count() * zones, std::string());
  SampleFrame frame;
  for (std::size_t k = 0; k < recording.sample_count(); ++k) {
    // the scene as it stood at the sample's time, the sensor where it was
    if (world.has_moving_objects()) {
      world.MoveObjects(recording.t_s[k]);
      world.caster().Commit();
    }
    reader.SetMountPose_W(0, recording.X_WM[k]);
    frame.sample = static_cast<std::int64_t>(k);
    frame.t_s = recording.t_s[k];
    reader.Read(frame, runner);
    const SensorSample& sample = frame.sensors[0];
    const std::size_t base = k * zones;
    if (!scenario.sensors[0].spec.zones) {
      out.valid[base] = sample.reading.status == ReadingStatus::kOk;
      out.d_m[base] = sample.reading.d_m;
      out.status[base] = ReadingStatusName(sample.reading.status);
      continue;
    }
    // a zone's first target in the part's target order (a zone without one lists its status once)
    for (const Measurement& m : sample.measurements) {
      if (m.rank != 0 || m.group < 0 || static_cast<std::size_t>(m.group) >= zones) continue;
      out.valid[base + m.group] = m.detected();
      out.d_m[base + m.group] = m.d_m;
      out.status[base + m.group] = ZoneStatusName(m.code);
    }
  }
  return out;
}

}  // namespace proxsim
