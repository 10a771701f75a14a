#include "knowledge/ray_evidence.h"

#include <algorithm>
#include <cmath>

#include "knowledge/echo_cone.h"
#include "sensors/multizone.h"
#include "sensors/range_inverse.h"
#include "sensors/range_table.h"

namespace proxsim {

namespace {

// A surface at the end of a ray is this far at least from where the ray's
// empty part stops (beyond the noise's 3σ): float rounding in the caster.
constexpr double kFreeMargin_m = 0.001;

}  // namespace

EvidenceModel::EvidenceModel(const SensorSpec& spec, bool with_zones)
    : tan_half_aperture(std::tan(SpreadHalfAngleRad(spec))),
      half_aperture_rad(SpreadHalfAngleRad(spec)),
      floor_echo_min_dir_z(std::cos(DegToRad(EchoIncidenceLimitDeg(spec))) - 1e-12),
      silence_range_m(SilenceRange_m(spec)) {
  if (!spec.zones || !with_zones) return;
  // a part whose range depends on the target vouches only for its darkest target's range
  // (a multi-zone sensor's corner zones see less far than its centre ones)
  for (int zone = 0; zone < spec.zones->nx * spec.zones->ny; ++zone) {
    zone_silence_range_m.push_back(ZoneSilenceRange_m(spec, zone));
  }
}

RayEvidence InterpretReading(const SensorSpec& spec, const SensorOutput& output) {
  return InterpretMeasurement(spec, EvidenceModel(spec, false), output.headline());
}

RayEvidence InterpretMeasurement(const SensorSpec& spec, const EvidenceModel& model, const Measurement& output) {
  // a zone's silence vouches for that zone's range
  const int zone = spec.zones && output.group >= 0 ? output.group : -1;
  RayEvidence evidence;
  evidence.p_WS = output.p_WS;
  evidence.dir_W = output.dir_W.normalized();
  evidence.detected = output.detected();
  // a beam's echo may have come from anywhere in its cone: the point is
  // put where the cone's lowest direction meets the distance, the lowest
  // it can be (knowledge/echo_cone.h) — a floor that echoed at the cone's
  // lower edge is floor, not a point above it on the axis; anything else
  // stands at least that high. The cone is empty up to the echo in every
  // direction, this one too.
  if (evidence.detected && model.tan_half_aperture > 0) {
    evidence.dir_W = LowestEchoDirection_W(evidence.dir_W, model.half_aperture_rad);
  }
  const double dir_z = evidence.dir_W.z();
  if (evidence.detected) {
    const double d_m = UnbiasedDistance_m(spec, output.ray_d_m());
    const double sigma_d = RangeSigma_m(spec, d_m);
    const double sigma_lat = d_m * model.tan_half_aperture / 2;
    evidence.d_m = d_m;
    evidence.variance_z_m2 = sigma_d * sigma_d * dir_z * dir_z + sigma_lat * sigma_lat * (1 - dir_z * dir_z);
    evidence.free_begin_m = 0.0;
    evidence.free_end_m = d_m - 3.0 * std::hypot(sigma_d, sigma_lat) - kFreeMargin_m;
    evidence.bounds_height = evidence.proves_empty = evidence.free_end_m > 0;
    return evidence;
  }
  // no echo over [d_min, d_m]; meaningful for the height only where a flat floor would have answered
  evidence.d_m = output.d_m;
  evidence.free_begin_m = spec.min_range_m;
  const bool zoned = zone >= 0 && static_cast<std::size_t>(zone) < model.zone_silence_range_m.size();
  evidence.free_end_m = std::min(output.d_m, zoned ? model.zone_silence_range_m[zone]
                                                   : (zone >= 0 ? ZoneSilenceRange_m(spec, zone) : model.silence_range_m));
  const bool floor_would_echo = std::abs(dir_z) >= model.floor_echo_min_dir_z;
  evidence.bounds_height = floor_would_echo && spec.noise.dropout == 0 && evidence.free_end_m > evidence.free_begin_m;
  evidence.proves_empty = false;
  return evidence;
}

}  // namespace proxsim
