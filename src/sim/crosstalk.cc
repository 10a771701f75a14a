#include "sim/crosstalk.h"

#include <algorithm>
#include <cmath>

namespace proxsim {

namespace {

// the angle between two unit vectors, degrees
double AngleDeg(const Vec3& a, const Vec3& b) { return RadToDeg(std::acos(std::clamp(a.dot(b), -1.0, 1.0))); }

}  // namespace

std::vector<CrossEchoPath> CrossEchoPaths(const SensorSpec& emitter_spec, const PingRays& emitter,
                                          const SensorSpec& listener_spec, const ListeningSensor& listener) {
  std::vector<CrossEchoPath> paths;
  if (!emitter_spec.beam || !listener_spec.beam) return paths;
  for (std::size_t r = 0; r < emitter.hits.size(); ++r) {
    const Hit& hit = emitter.hits[r];
    const BeamRay& ray = emitter.beam_rays[r];
    if (!hit.is_hit() || ray.gain < emitter_spec.echo_threshold) continue;
    const double out_m = hit.distance_m;
    if (!BeamReaches(emitter_spec.beam, ray.off_axis_deg, out_m)) continue;
    const Vec3& d = emitter.dir_W[r];
    const Vec3 p_WH = emitter.p_WS + out_m * d;
    const Vec3 to_listener = listener.p_WS - p_WH;
    const double back_m = to_listener.norm();
    if (!(back_m > 0.0)) continue;
    // the echo leaves H around the mirror direction
    const Vec3 n = hit.normal_W.cast<double>().normalized();
    const Vec3 mirror = d - 2.0 * d.dot(n) * n;
    if (AngleDeg(mirror, to_listener / back_m) > 2.0 * listener_spec.max_incidence_deg) continue;
    // and the listener's lobe reaches that far off its axis
    if (!BeamReaches(listener_spec.beam, AngleDeg(listener.axis_W, -to_listener / back_m), back_m)) continue;
    paths.push_back({out_m + back_m, p_WH});
  }
  std::sort(paths.begin(), paths.end(), [](const CrossEchoPath& a, const CrossEchoPath& b) { return a.path_m < b.path_m; });
  return paths;
}

}  // namespace proxsim
