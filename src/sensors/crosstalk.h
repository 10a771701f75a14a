// Ultrasonic crosstalk's geometry: the ways one sensor's ping reaches another
// sensor's receiver after one reflection. A ray of the emitter's beam that
// counts (its gain reaches the emitter's echo threshold, its reach holds at
// that distance) hits a surface at H; the echo leaves H around the mirror
// direction and is heard by the listener when that direction is within twice
// the listener's incidence window of the way to it — the paper's window read
// for two sensors: for one sensor it is "incidence α <= α*", the mirror
// direction within 2α* of the way back — and the listener's beam reaches H's
// direction at that distance. Sensors without a beam (one ray) neither send
// nor hear off their axis, so they take no part. The listener's line of sight
// to H and the timing of the pings are the caller's (sim/sensor_reader.cc).
//
// Frames: W world.
#pragma once

#include <algorithm>
#include <limits>
#include <span>
#include <vector>

#include "core/geometry.h"
#include "core/ray_hit.h"
#include "sensors/beam.h"
#include "sensors/sensor_spec.h"

namespace proxsim {

/// One ping as cast: the emitter's origin and, per ray, its direction, hit and beam ray.
struct PingRays {
  Vec3 p_WS = Vec3::Zero();
  std::span<const Vec3> dir_W;
  std::span<const Hit> hits;
  std::span<const BeamRay> beam_rays;
};

/// The listener's receiver: its origin and axis (unit).
struct ListeningSensor {
  Vec3 p_WS = Vec3::Zero();
  Vec3 axis_W = Vec3::UnitX();
};

/// One way from the emitter to the listener: its length (emitter to H to
/// listener) and the reflecting point H.
struct CrossEchoPath {
  double path_m = 0.0;
  Vec3 p_WH = Vec3::Zero();
};

/// What of an emitter's ping does not depend on who listens: each ray that
/// counts, its distance out, its hit point H and the mirror direction there,
/// in ray order. n sonars hear each other in n(n − 1) pairs: these are
/// computed once per ping, not once per pair (64 sonars of 32 rays at 1 kHz:
/// 2 048 a sample instead of 129 024).
struct EchoSource {
  double out_m = 0.0;
  Vec3 p_WH = Vec3::Zero();
  Vec3 mirror_W = Vec3::UnitX();
};

/// The emitter's echo sources into `sources` (cleared first; its capacity is
/// kept, so a caller that reuses it allocates nothing once warm).
void EchoSourcesInto(const SensorSpec& emitter_spec, const PingRays& emitter, std::vector<EchoSource>& sources);

/// The listener's mirror window — twice its incidence window — and that
/// angle's cosine, found once per listener rather than once per emitter.
struct MirrorWindow {
  explicit MirrorWindow(const SensorSpec& listener_spec);
  double window_deg = 0.0;
  double cos_window = 0.0;
};

/// Every way the emitter's ping (its echo sources) reaches the listener after
/// one reflection, no longer than `longest_m`, shortest first, into `paths`
/// (cleared first); none when the listener has no beam. A caller that can
/// use no path beyond some length (it would arrive after the listening window
/// or after the first echo heard) passes it: a source whose every path is
/// longer (2·out − |EL| > longest_m, E the emitter at `p_W_emitter`) is passed
/// over before its way back is found.
void CrossEchoPathsInto(std::span<const EchoSource> sources, const SensorSpec& listener_spec,
                        const MirrorWindow& window, const ListeningSensor& listener,
                        std::vector<CrossEchoPath>& paths, const Vec3& p_W_emitter,
                        double longest_m = std::numeric_limits<double>::infinity());

/// The distance out to the nearest of an emitter's echo sources (+inf for none).
double NearestEchoSource_m(std::span<const EchoSource> sources);

/// The shortest any of those paths can be, from where the emitter and the
/// listener are and the nearest source's distance alone (the triangle
/// inequality, less 1 nm for rounding): no path is shorter, so a caller can
/// skip an emitter whose every path would arrive too late without finding them.
/// (Inline: it is asked for every pair of sonars every sample.)
inline double ShortestCrossEchoPath_m(double nearest_source_m, const Vec3& p_W_emitter, const Vec3& p_W_listener) {
  // a path E -> H -> L with |EH| = out is at least |EL| (E, H, L a triangle)
  // and at least 2 out - |EL| (|HL| >= |EH| - |EL|)
  const double apart_m = (p_W_listener - p_W_emitter).norm();
  return std::max(apart_m, 2.0 * nearest_source_m - apart_m) - 1e-9;
}

}  // namespace proxsim
