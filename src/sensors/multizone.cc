#include "sensors/multizone.h"

#include <algorithm>
#include <cmath>

#include "sensors/echo_groups.h"
#include "sensors/noise_table.h"

namespace proxsim {

namespace {

// The parts' figures (docs/sensors.md cites each):
//  - field of view: VL53L5CX 45° × 45° (63° diagonal), VL53L7CX 60° × 60° (90°
//    diagonal, ST data brief of STSW-IMG036), VL53L8CX 45° × 45° (UM3109);
//  - longest range: 400 cm (L5CX, L8CX: UM3109), 350 cm (L7CX: STSW-IMG036);
//  - ranging frequency: at most 60 Hz at 4×4 and 15 Hz at 8×8 (ST's ULD
//    limits as the SparkFun VL53L5CX library documents them, "Using 4x4 ... max
//    is 60Hz, Using 8x8 ... max is 15Hz"; the same for the L7CX in espp's
//    driver notes). For the L8CX ST gives "60 Hz" (UM3109); its 8×8 limit is
//    taken as the family's 15 Hz.
constexpr MultizonePart kParts[] = {
    {"vl53l5cx", 45.0, 4.0, 60.0, 15.0, "ST UM2884 / SparkFun VL53L5CX library: 4x4 up to 60 Hz, 8x8 up to 15 Hz"},
    {"vl53l7cx", 60.0, 3.5, 60.0, 15.0, "ST STSW-IMG036 data brief, UM3038: 4x4 up to 60 Hz, 8x8 up to 15 Hz"},
    {"vl53l8cx", 45.0, 4.0, 60.0, 15.0, "ST UM3109: up to 60 Hz (4x4); 8x8 taken as the family's 15 Hz"},
};

}  // namespace

const char* ZoneStatusName(std::uint8_t code) {
  switch (code) {
    case kZoneNotUpdated: return "ranging_data_not_updated";
    case kZoneRangeValid: return "range_valid";
    case kZoneSignalTooLow: return "signal_rate_too_low_for_target";
    case kZoneNoTarget: return "no_target_detected";
  }
  return "?";
}

const std::vector<std::uint8_t>& ZoneStatusCodes() {
  static const std::vector<std::uint8_t> codes = {kZoneNotUpdated, kZoneRangeValid, kZoneSignalTooLow, kZoneNoTarget};
  return codes;
}

std::span<const MultizonePart> MultizoneParts() { return kParts; }

const MultizonePart* FindMultizonePart(const std::string& name) {
  for (const MultizonePart& part : kParts) {
    if (name == part.name) return &part;
  }
  return nullptr;
}

namespace {

// the half-extent of the image plane along one axis, tan(fov/2)
double HalfTan(double fov_deg) { return std::tan(DegToRad(0.5 * fov_deg)); }

// the point (u, v) on the image plane x = 1 of sub-cell (a, b) of zone (column, row), k sub-cells a side
Vec3 ImagePoint_S(const ZoneSpec& zones, int column, int row, double a, double b, int k) {
  const double tu = HalfTan(zones.fov_h_deg), tv = HalfTan(zones.fov_v_deg);
  const double cell_u = 2.0 * tu / zones.nx, cell_v = 2.0 * tv / zones.ny;
  // column 0 on the left (+y), row 0 at the top (+z)
  const double u = tu - (column + (a + 0.5) / k) * cell_u;
  const double v = tv - (row + (b + 0.5) / k) * cell_v;
  return Vec3(1.0, u, v);
}

}  // namespace

Vec3 ZoneAxis_S(const ZoneSpec& zones, int zone) {
  return ImagePoint_S(zones, zone % zones.nx, zone / zones.nx, 0.0, 0.0, 1).normalized();
}

std::vector<BeamRay> MakeZoneRays(const ZoneSpec& zones) {
  const int k = static_cast<int>(std::lround(std::sqrt(zones.rays_per_zone)));
  const int count = ZoneCount(zones) * k * k;
  std::vector<BeamRay> rays;
  rays.reserve(count);
  for (int zone = 0; zone < ZoneCount(zones); ++zone) {
    for (int b = 0; b < k; ++b) {
      for (int a = 0; a < k; ++a) {
        const Vec3 dir_S = ImagePoint_S(zones, zone % zones.nx, zone / zones.nx, a, b, k).normalized();
        // off_axis_deg > 0 for every ray, so BeamRayDir_W rotates it (even one on the axis, harmlessly)
        const double off_axis_deg = std::max(RadToDeg(std::acos(std::clamp(dir_S.x(), -1.0, 1.0))), 1e-9);
        rays.push_back({dir_S, off_axis_deg, 1.0, 1.0 / count});
      }
    }
  }
  return rays;
}

std::vector<BeamRay> MakeSensorRays(const SensorSpec& spec) {
  return spec.zones ? MakeZoneRays(*spec.zones) : MakeBeamRays(spec.beam);
}

void MeasureZones(const SensorSpec& spec, std::span<const Echo> echoes, const DrawOfRay& draw, ZoneReadings& out) {
  const ZoneSpec& zones = *spec.zones;
  const int zone_count = ZoneCount(zones);
  const int per_zone = zones.rays_per_zone;
  out.targets.assign(static_cast<std::size_t>(zone_count * zones.targets), ZoneTarget{});
  out.target_count.assign(static_cast<std::size_t>(zone_count), 0);
  std::vector<RangedRay> counted;
  std::vector<EchoGroup> groups, strongest;
  std::vector<double> signal;
  std::vector<std::size_t> order;
  counted.reserve(per_zone);
  for (int zone = 0; zone < zone_count; ++zone) {
    // the zone's rays whose echo counts, and whether a surface lay within range at all
    counted.clear();
    bool surface_in_range = false;
    for (int i = zone * per_zone; i < (zone + 1) * per_zone; ++i) {
      const Echo& echo = echoes[static_cast<std::size_t>(i)];
      const ReadingStatus status = EchoStatus(spec, echo, 1.0);
      if (echo.distance_m <= spec.max_range_m && !echo.from_robot) surface_in_range = true;
      if (status == ReadingStatus::kOk) counted.push_back({echo.distance_m + echo.flight_shift_m, i});
    }
    ZoneTarget* targets = &out.targets[static_cast<std::size_t>(zone * zones.targets)];
    if (counted.empty()) {
      targets[0].status = surface_in_range ? kZoneSignalTooLow : kZoneNoTarget;
      continue;
    }
    // nearest first; a gap of the part's separation or more starts a new target
    SplitEchoes(counted, zones.target_separation_m, zones.strongest_first ? zone_count * per_zone : zones.targets,
                groups);
    if (zones.strongest_first) {
      // ST's strongest order: the targets by the signal their rays return
      // (each ray an equal part of the zone), a tie keeping the nearer first
      signal.assign(groups.size(), 0.0);
      for (std::size_t g = 0; g < groups.size(); ++g)
        for (std::size_t k = groups[g].begin; k < groups[g].end; ++k)
          signal[g] += ReturnedEnergy(spec, echoes[static_cast<std::size_t>(counted[k].ray)]);
      order.resize(groups.size());
      for (std::size_t g = 0; g < groups.size(); ++g) order[g] = g;
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return signal[a] > signal[b]; });
      strongest.clear();
      for (std::size_t g = 0; g < order.size() && g < static_cast<std::size_t>(zones.targets); ++g)
        strongest.push_back(groups[order[g]]);
      groups.swap(strongest);
    }
    for (std::size_t found = 0; found < groups.size(); ++found) {
      const EchoGroup& group = groups[found];
      double sum_m = 0.0;
      for (std::size_t k = group.begin; k < group.end; ++k) sum_m += counted[k].d_m;
      const double mean_m = sum_m / static_cast<double>(group.end - group.begin);
      const int ray = counted[group.begin].ray;
      const NoiseSpec noise = NoiseAt(spec, echoes[static_cast<std::size_t>(ray)].ir_albedo);
      targets[found] = {TimeOfFlightReading_m(noise, mean_m, draw(ray).gaussian_g), kZoneRangeValid, ray};
    }
    out.target_count[static_cast<std::size_t>(zone)] = static_cast<std::uint8_t>(groups.size());
  }
}

std::vector<std::array<double, 3>> MultizonePartRangeTable(const SensorSpec& spec) {
  if (spec.part != "vl53l5cx" || !spec.zones) return {};
  // ST VL53L5CX datasheet DS13754 Rev 5: maximum ranging distance at a 90 %
  // detection rate, target filling the field of view, inner zones, typical;
  // "5 klux" is ST's 2 W/m² of 940 nm irradiance on the target. Table 17
  // (4x4, 30 Hz): white 88 % 4000 mm dark, 1700 mm at 5 klux; grey 17 %
  // 2400 and 1000 mm. Table 18 (8x8, 15 Hz): white 3500 and 1100 mm; grey
  // 1300 and 800 mm. The corner zones' shorter figures are not modelled.
  if (spec.zones->nx == 4) return {{0.88, 0.0, 4.0}, {0.17, 0.0, 2.4}, {0.88, 5.0, 1.7}, {0.17, 5.0, 1.0}};
  return {{0.88, 0.0, 3.5}, {0.17, 0.0, 1.3}, {0.88, 5.0, 1.1}, {0.17, 5.0, 0.8}};
}

double MultizoneMaxRate_hz(const SensorSpec& spec) {
  const MultizonePart* part = FindMultizonePart(spec.part);
  if (part == nullptr || !spec.zones) return 0.0;
  return spec.zones->nx == 4 ? part->max_rate_4x4_hz : part->max_rate_8x8_hz;
}

}  // namespace proxsim
