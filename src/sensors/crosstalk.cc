#include "sensors/crosstalk.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace proxsim {

namespace {

// the angle between two unit vectors, degrees
double AngleDeg(const Vec3& a, const Vec3& b) { return RadToDeg(std::acos(std::clamp(a.dot(b), -1.0, 1.0))); }

}  // namespace

void EchoSourcesInto(const SensorSpec& emitter_spec, const PingRays& emitter, std::vector<EchoSource>& sources) {
  sources.clear();
  if (!emitter_spec.beam) return;
  for (std::size_t r = 0; r < emitter.hits.size(); ++r) {
    const Hit& hit = emitter.hits[r];
    const BeamRay& ray = emitter.beam_rays[r];
    if (!hit.is_hit() || ray.gain < emitter_spec.echo_threshold) continue;
    const double out_m = hit.distance_m;
    if (!BeamReaches(emitter_spec.beam, ray.off_axis_deg, out_m)) continue;
    const Vec3& d = emitter.dir_W[r];
    // the echo leaves H around the mirror direction
    const Vec3 n = hit.normal_W.cast<double>().normalized();
    sources.push_back({out_m, emitter.p_WS + out_m * d, d - 2.0 * d.dot(n) * n});
  }
}

MirrorWindow::MirrorWindow(const SensorSpec& listener_spec)
    : window_deg(2.0 * listener_spec.max_incidence_deg), cos_window(std::cos(DegToRad(std::min(window_deg, 180.0)))) {}

void CrossEchoPathsInto(std::span<const EchoSource> sources, const SensorSpec& listener_spec,
                        const MirrorWindow& window, const ListeningSensor& listener,
                        std::vector<CrossEchoPath>& paths, const Vec3& p_W_emitter, double longest_m) {
  paths.clear();
  if (!listener_spec.beam) return;
  // a path through a source `out` away is at least 2·out − |EL| long (ShortestCrossEchoPath_m)
  const double apart_m = (listener.p_WS - p_W_emitter).norm();
  // the mirror test by its cosine first: only a direction within 1e-9 of the
  // window's edge takes the exact angle (acos), so each decision is the
  // angle's, bit for bit, at a dot product's cost
  const double window_deg = window.window_deg;
  const double cos_window = window.cos_window;
  for (const EchoSource& source : sources) {
    if (2.0 * source.out_m - apart_m - 1e-9 > longest_m) continue;  // every path through it too long
    const Vec3 to_listener = listener.p_WS - source.p_WH;
    const double back_m = to_listener.norm();
    if (!(back_m > 0.0) || source.out_m + back_m > longest_m) continue;
    const double cos_mirror = source.mirror_W.dot(to_listener / back_m);
    if (window_deg < 180.0 && cos_mirror < cos_window - 1e-9) continue;  // surely beyond the window
    if (!(cos_mirror > cos_window + 1e-9) && AngleDeg(source.mirror_W, to_listener / back_m) > window_deg) continue;
    // and the listener's lobe reaches that far off its axis
    if (!BeamReaches(listener_spec.beam, AngleDeg(listener.axis_W, -to_listener / back_m), back_m)) continue;
    paths.push_back({source.out_m + back_m, source.p_WH});
  }
  std::sort(paths.begin(), paths.end(), [](const CrossEchoPath& a, const CrossEchoPath& b) { return a.path_m < b.path_m; });
}

double NearestEchoSource_m(std::span<const EchoSource> sources) {
  double nearest_m = std::numeric_limits<double>::infinity();
  for (const EchoSource& source : sources) nearest_m = std::min(nearest_m, source.out_m);
  return nearest_m;
}

}  // namespace proxsim
