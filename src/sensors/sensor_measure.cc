#include "sensors/sensor_measure.h"

#include "sensors/beam_echoes.h"
#include "sensors/multizone.h"

namespace proxsim {

namespace {

// A zone grid: every zone's targets, and the nearest valid one of any zone as the headline.
void MeasureZoneGrid(const SensorSpec& spec, const SensorPlacement& at, std::span<const Echo> echoes,
                     std::span<const BeamRay> rays, const DrawOfRay& draw, SensorMeasurement& out) {
  thread_local ZoneReadings zones;
  MeasureZones(spec, echoes, rays, draw, zones);
  const auto per_zone = static_cast<std::size_t>(spec.zones->targets);
  const ZoneTarget* nearest = nullptr;
  Measurement nearest_measured;  // its measurement: the zone's axis and how its distance lies along it
  for (std::size_t zone = 0; zone < zones.target_count.size(); ++zone) {
    const ZoneTarget* targets = &zones.targets[zone * per_zone];
    Measurement m{.p_WS = at.p_WS, .dir_W = at.zone_dir_W[zone], .group = static_cast<std::int32_t>(zone)};
    const double cos_to_axis = spec.zones->perpendicular ? at.zone_dir_W[zone].dot(at.dir_W) : 1.0;
    // a zone without a target says why in its first slot (signal too low, or nothing)
    if (zones.target_count[zone] == 0) {
      m.d_m = spec.max_range_m;
      m.status = ReadingStatus::kNoEcho;
      m.code = targets[0].status;
      out.measured.push_back(m);
      out.truth.push_back(m);
      continue;
    }
    for (std::size_t j = 0; j < zones.target_count[zone]; ++j) {
      const ZoneTarget& target = targets[j];
      m.d_m = target.d_m;
      m.status = ReadingStatus::kOk;
      m.code = target.status;
      m.rank = static_cast<std::int32_t>(j);
      m.cos_to_axis = cos_to_axis;
      out.measured.push_back(m);
      m.d_m = target.truth_d_m;
      out.truth.push_back(m);
      if (nearest == nullptr || target.d_m < nearest->d_m) {
        nearest = &target;
        nearest_measured = out.measured.back();
      }
    }
  }
  if (nearest != nullptr) {
    out.headline = BeamReading{.reading = Reading{}, .ray = nearest->ray, .truth_ray = nearest->ray};
    out.headline.reading.status = ReadingStatus::kOk;
    out.headline.reading.d_m = nearest->d_m;
    // the reading's axis is its zone's, so that its point is the zone's point
    out.headline_dir_W = nearest_measured.dir_W;
    out.headline_cos_to_axis = nearest_measured.cos_to_axis;
    return;
  }
  // no zone has a target: the reading says why, as a beam of all its rays would
  out.headline = MeasureBeam(spec, echoes, rays, draw);
  out.headline.ray = -1;
}

// A beam's echoes as it reports them, nearest first.
void ListEchoes(const SensorSpec& spec, const SensorPlacement& at, std::span<const Echo> echoes,
                std::span<const BeamRay> rays, const DrawOfRay& draw, SensorMeasurement& out) {
  const std::vector<BeamEcho> reported = ReportedEchoes(spec, echoes, rays, draw);
  for (std::size_t k = 0; k < reported.size(); ++k) {
    Measurement m{.p_WS = at.p_WS, .dir_W = at.dir_W, .d_m = reported[k].d_m, .status = ReadingStatus::kOk,
                  .signal = reported[k].signal, .rank = static_cast<std::int32_t>(k)};
    out.measured.push_back(m);
    m.d_m = reported[k].truth_d_m;
    out.truth.push_back(m);
  }
}

}  // namespace

void MeasureSensorSample(const SensorSpec& spec, const SensorPlacement& at, std::span<const Echo> echoes,
                         std::span<const BeamRay> rays, const DrawOfRay& draw, SensorMeasurement& out) {
  out.measured.clear();
  out.truth.clear();
  out.headline_dir_W = at.dir_W;
  out.headline_cos_to_axis = 1.0;
  if (spec.zones) {
    MeasureZoneGrid(spec, at, echoes, rays, draw, out);
  } else if (echoes.size() == 1) {
    // the paper's single ray
    out.headline.reading = Measure(spec, echoes[0], draw);
    out.headline.truth_ray = 0;
    const ReadingStatus status = out.headline.reading.status;
    out.headline.ray = (status == ReadingStatus::kOk || status == ReadingStatus::kSelf) ? 0 : -1;
  } else {
    out.headline = MeasureBeam(spec, echoes, rays, draw);
    if (spec.echoes != EchoSelection::kFirst) ListEchoes(spec, at, echoes, rays, draw, out);
  }
}

}  // namespace proxsim
