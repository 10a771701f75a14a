// One sample's sensing: place every sensor in the world (X_WS) from its link's
// pose, cast its rays, and turn each sensor's hits into a reading with the
// paper's model (sensors/). A sensor with a beam owns a contiguous range of
// rays and is read with MeasureBeam. A sensor with its own rate_hz is read
// only at the first run sample of each of its periods (status not_sampled
// otherwise); with flight_time the receive point is the sensor's origin at the
// echo's return, extrapolated at the velocity it had between the last two
// samples. A sensor's periods start at its `fire_offset_s`. Ultrasonic
// sensors with beams hear each other's pings (sensors/crosstalk.h): a reading is
// the first echo of any ping that reaches it within its listening window
// (`echo_timeout_s` after its own ping), status `crosstalk` when it was
// another sensor's. The other sensor's ping is taken as cast at this sample
// (its rays are cast at every sample): within a 38 ms window the robot moves
// a few centimetres at most.
//
// Frames: W world, L the link a sensor is fixed on, S a sensor.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/parallel.h"
#include "scenario/scenario.h"
#include "sensors/sensor_measure.h"
#include "sensors/crosstalk.h"
#include "sim/sample_frame.h"
#include "sim/sensor_rig.h"
#include "sim/world.h"

namespace proxsim {

class SensorReader {
 public:
  /// `scenario`, `world` and `rig` (the scenario's sensors) must outlive the
  /// reader; the scenario's seed is read at every sample.
  SensorReader(const Scenario& scenario, World& world, const SensorRig& rig);

  /// Reads every sensor into frame.sensors (sized to the sensor count) at
  /// frame.sample / frame.t_s, with the world's bodies as last committed;
  /// `runner` shares a sample with many rays out over its threads.
  void Read(SampleFrame& frame, ParallelRunner& runner);

  /// A new episode: the sensors have no previous position.
  void Reset();

  /// From the next Read on, sensor `sensor` stands at X_WM·X_LS, its
  /// mounting X_LS on a frame M whose pose X_WM the caller gives (a recorded
  /// pose: `proxsim fidelity` replays a user's recording through this reader),
  /// instead of on its link. Its rays, echoes, noise keys and model are the run's.
  void SetMountPose_W(std::size_t sensor, const Pose& X_WM);

 private:
  // place a sensor where its link is and, with `rays`, fill its rays and zone axes
  void PlaceSensor(std::size_t sensor, SampleFrame& frame, bool rays);
  // whether the sensor's rays are cast at this sample: at its own samples,
  // and always for a sonar that others may hear (crosstalk reads its rays then)
  bool CastsAt(std::size_t sensor, std::int64_t sample) const;
  // one sensor's hits into its reading
  void MeasureSensor(std::size_t sensor, SampleFrame& frame);
  // whether sample k is one of the sensor's own samples (its pings)
  bool IsSensorSample(std::size_t sensor, std::int64_t sample) const;
  // before the sensors are read: each emitter's next ping, and whether any
  // sonar listens at this sample (crosstalk's echo sources are then found)
  void PrepareCrosstalk(std::int64_t sample);
  // after `sensor` is read, within its read task: its ping's echo sources,
  // when some listener may hear a ping of it at this sample
  void FindEchoSources(std::size_t sensor, const SampleFrame& frame);
  // the listeners' readings replaced by an earlier echo of another sensor's
  // ping; listeners are independent, so they are shared out over the threads
  void ApplyCrosstalk(SampleFrame& frame, ParallelRunner& runner);
  // one listener's reading (ApplyCrosstalk)
  void ListenForCrosstalk(std::size_t listener, SampleFrame& frame);
  // the emitter's pings within the listener's window around its ping at this
  // sample, s from it: its last ping and its next one, at most (no heap: it is
  // asked for every pair of sonars every sample)
  struct PingOffsets {
    std::array<double, 2> s{};
    std::size_t count = 0;
    const double* begin() const { return s.data(); }
    const double* end() const { return s.data() + count; }
  };
  // (relative to the listener's ping at this sample: the emitter's last ping,
  // this sample's included, and its next one, the first after this sample: a
  // later one is never nearer; inline: it is asked for every pair)
  PingOffsets PingOffsets_s(std::size_t emitter, double listener_window_s) const {
    PingOffsets offsets;
    const double last_s = last_ping_offset_s_[emitter];  // −inf: none (never within the window)
    if (-last_s < listener_window_s) offsets.s[offsets.count++] = last_s;
    if (next_ping_offset_s_[emitter] <= listener_window_s) offsets.s[offsets.count++] = next_ping_offset_s_[emitter];
    return offsets;
  }
  // each emitter's first ping after this sample, s from it, when within the
  // longest listening window (else +inf): found once per sample, not per pair
  void FindNextPings(std::int64_t sample);
  // how long `sensor` listens after its ping, s
  double ListeningWindow_s(std::size_t sensor) const;
  // below this many rays a sample is read on one thread (a fork costs more)
  static constexpr std::size_t kParallelReadRays = 512;
  // sensors read by one task: enough rays to outweigh the task's cost
  static constexpr std::size_t kSensorsPerTask = 4;
  // listeners whose crosstalk one task takes; fewer sonars than this are heard on one thread
  static constexpr std::size_t kListenersPerTask = 4;

  const Scenario& scenario_;
  World& world_;
  const SensorRig& rig_;
  // per-ray buffers, sized once and overwritten every sample
  std::vector<Ray> rays_;
  std::vector<Vec3> ray_dir_W_;  // each ray's direction in double precision
  std::vector<Hit> hits_;
  std::vector<Echo> echoes_;
  std::vector<Vec3> p_WS_previous_;  // each sensor's origin at the previous sample, for flight_time
  std::vector<std::size_t> sonars_;    // ultrasonic sensors with a beam: they ping and hear each other
  std::vector<std::vector<Vec3>> zone_axes_S_;  // each multizone sensor's zone axes in its frame (multizone.h)
  std::vector<std::vector<Vec3>> zone_axes_W_;  // the same in W where the sensor last measured
  std::vector<SensorMeasurement> measured_;     // by sensor: its sample's buffers, swapped with the frame's
  // ApplyCrosstalk's per-emitter echo sources (sensors/crosstalk.h), by sensor;
  // found in the emitter's read task when a listener may need them (buffers
  // kept across samples; one slot per sensor, so tasks never share one)
  std::vector<std::vector<EchoSource>> echo_sources_;
  std::vector<std::vector<CrossEchoPath>> cross_paths_;  // by listener: one pair's paths, the buffer reused
  std::vector<double> nearest_source_m_;     // each emitter's NearestEchoSource_m, found with its sources
  bool sonar_listens_now_ = false;           // PrepareCrosstalk: some sonar with crosstalk reads at this sample
  std::vector<double> next_ping_offset_s_;   // FindNextPings' answer, by sensor
  std::vector<double> last_ping_offset_s_;   // each sonar's last ping, s from this sample (ApplyCrosstalk)
  double longest_window_s_ = 0.0;            // the longest listening window of any sonar
  std::vector<bool> heard_by_others_;        // by sensor: a sonar that another sonar may hear
  std::vector<double> last_ping_t_s_;  // each sensor's last ping, s (NaN before the first)
  std::vector<std::optional<Pose>> mount_X_WM_;  // SetMountPose_W's poses, by sensor; none: on its link
};

}  // namespace proxsim
