#include "sensors/multizone.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sensors/echo_groups.h"
#include "sensors/noise_table.h"
#include "sensors/range_table.h"

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
//    taken as the family's 15 Hz. Their presets: 8x8 zones of 4 rays, one
//    target per zone (the ULD's NB_TARGET_PER_ZONE default), perpendicular.
//  - VL53L4CX (ST's single-zone part with histogram processing and
//    multi-target detection): one zone; "18° FoV" and "very accurate distance
//    measurements up to 6 m" (ST's STSW-IMG029 page, the part's API); up to 4
//    objects per measurement (VL53L4CX_MAX_RANGE_RESULTS = 4 in ST's driver as
//    stm32duino/VL53L4CX ships it; ST's UM2778 for the VL53L3CX, the same
//    VL53LX bare driver: "by default equal to 4"). Its 18° cone is taken as
//    the square zone of 18° a side sampled by 4×4 rays, whose outer rays lie
//    6.75° off the axis along a side and 9.5° along the diagonal, about the
//    cone's 9° half-angle. Its distance is radial: ST's statement that the
//    conversion to perpendicular is done on the chip is about the multi-zone
//    parts, and a single-zone part times its photons along their paths.
//    **No datasheet limit on the ranging rate was found**: its driver's
//    default timing budget, 33.3 ms (VL53L4CX_DataInit sets 33333 µs), is
//    taken as its cycle, 30 Hz, conservative against the shorter budgets the
//    driver accepts (a budget is not modelled: the range does not change with it).
constexpr MultizonePart kParts[] = {
    {"vl53l4cx", 18.0, 6.0, {1, 0}, {30.0, 0.0}, 16, 4, false,
     "ST STSW-IMG029 (18° FoV, up to 6 m); one measurement per the driver's default 33.3 ms timing budget "
     "(stm32duino/VL53L4CX VL53L4CX_DataInit), the datasheet's limit not found"},
    {"vl53l5cx", 45.0, 4.0, {8, 4}, {15.0, 60.0}, 4, 1, true,
     "ST UM2884 / SparkFun VL53L5CX library: 4x4 up to 60 Hz, 8x8 up to 15 Hz"},
    {"vl53l7cx", 60.0, 3.5, {8, 4}, {15.0, 60.0}, 4, 1, true,
     "ST STSW-IMG036 data brief, UM3038: 4x4 up to 60 Hz, 8x8 up to 15 Hz"},
    {"vl53l8cx", 45.0, 4.0, {8, 4}, {15.0, 60.0}, 4, 1, true,
     "ST UM3109: up to 60 Hz (4x4); 8x8 taken as the family's 15 Hz"},
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

std::string MultizonePartGrids(const MultizonePart& part) {
  // the grids in ascending size, as the messages always named them
  std::array<int, 2> grids = part.grids_across;
  std::sort(grids.begin(), grids.end());
  std::string text;
  for (int across : grids) {
    if (across <= 0) continue;
    const std::string n = std::to_string(across);
    text += (text.empty() ? "" : " or ") + ("[" + n + ", " + n + "]");
  }
  return text;
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

namespace {

// a target's longest range in the inner and in the corner zones (the corner's: the inner's without a corner table)
struct ZoneRangeEnds {
  double inner_m = 0.0, corner_m = 0.0;
  double At(double corner_weight) const {
    return corner_weight <= 0 ? inner_m : inner_m + corner_weight * (corner_m - inner_m);
  }
};

ZoneRangeEnds ZoneRangeEndsFor(const SensorSpec& spec, double reflectance) {
  const double inner_m = ReflectanceMaxRange_m(spec, reflectance);
  if (spec.corner_range_table.empty()) return {inner_m, inner_m};
  return {inner_m, std::min(TableMaxRange_m(spec.corner_range_table, spec.ambient_klux, reflectance), spec.max_range_m)};
}

}  // namespace

void MeasureZones(const SensorSpec& spec, std::span<const Echo> echoes, std::span<const BeamRay> rays,
                  const DrawOfRay& draw, ZoneReadings& out) {
  const ZoneSpec& zones = *spec.zones;
  const int zone_count = ZoneCount(zones);
  const int per_zone = zones.rays_per_zone;
  out.targets.assign(static_cast<std::size_t>(zone_count * zones.targets), ZoneTarget{});
  out.target_count.assign(static_cast<std::size_t>(zone_count), 0);
  std::vector<RangedRay> counted;
  std::vector<ResolvedTarget> found_targets, strongest;
  std::vector<double> signal;
  std::vector<std::size_t> order;
  counted.reserve(per_zone);
  const bool by_target = !spec.range_table.empty() || !spec.corner_range_table.empty();
  // the floor and walls repeat one reflectance: its ranges are found once
  double ends_reflectance = std::numeric_limits<double>::quiet_NaN();
  ZoneRangeEnds ends;
  for (int zone = 0; zone < zone_count; ++zone) {
    // the zone's rays whose echo counts, and whether a surface lay within range at all
    counted.clear();
    bool surface_in_range = false;
    // the zone's longest range by the target, between the inner and the corner zones' by its place
    const double corner_weight = by_target ? ZoneCornerWeight(zones, zone) : 0.0;
    for (int i = zone * per_zone; i < (zone + 1) * per_zone; ++i) {
      const Echo& echo = echoes[static_cast<std::size_t>(i)];
      double target_range_m = std::numeric_limits<double>::infinity();
      // the signal falls with incidence (Lambert): a grazing floor's range is
      // the range of a darker target, so it falls silent first. The
      // datasheets' ranges are for a flat target facing the sensor, met by
      // this ray at its own angle off the axis: relative to that, the surface
      // returns E(θ)/E(θ_facing) of the light its reflectance would
      const std::size_t ray = static_cast<std::size_t>(i);
      const double energy = PhysicalEchoEnergy(spec, echo);
      const double reflectance = IncidentReflectance(spec, echo, rays[ray].off_axis_deg);
      if (by_target && echo.distance_m <= spec.max_range_m) {
        if (!(reflectance == ends_reflectance)) ends = ZoneRangeEndsFor(spec, ends_reflectance = reflectance);
        target_range_m = ends.At(corner_weight);
      }
      const ReadingStatus status = EchoStatusWithin(spec, echo, 1.0, target_range_m);
      if (echo.distance_m <= spec.max_range_m && !echo.from_robot) surface_in_range = true;
      if (status != ReadingStatus::kOk) continue;
      const double arrival_m = echo.distance_m + echo.flight_shift_m;
      // the part's distance: projected on the sensor's axis (ST's chips), or along the ray;
      // its return as the zone's histogram weighs it: the signal a diffuse
      // target sends back, E / d² (E = ρ·cos θ for a matte surface: PhysicalEchoEnergy)
      const double d_m = zones.perpendicular ? arrival_m * rays[ray].dir_S.x() : arrival_m;
      counted.push_back({d_m, i, energy / (arrival_m * arrival_m)});
    }
    ZoneTarget* targets = &out.targets[static_cast<std::size_t>(zone * zones.targets)];
    if (counted.empty()) {
      targets[0].status = surface_in_range ? kZoneSignalTooLow : kZoneNoTarget;
      continue;
    }
    // nearest first, each at its returns' signal-weighted centre; a gap of
    // the part's separation or more starts a new target (echo_groups.h)
    ResolveTargets(counted, zones.target_separation_m, zones.strongest_first ? zone_count * per_zone : zones.targets,
                   found_targets);
    if (zones.strongest_first) {
      // ST's strongest order: the targets by the signal their rays return
      // (each ray an equal part of the zone), a tie keeping the nearer first
      signal.assign(found_targets.size(), 0.0);
      for (std::size_t g = 0; g < found_targets.size(); ++g)
        for (std::size_t k = found_targets[g].rays.begin; k < found_targets[g].rays.end; ++k)
          signal[g] += ReturnedEnergy(spec, echoes[static_cast<std::size_t>(counted[k].ray)]);
      order.resize(found_targets.size());
      for (std::size_t g = 0; g < found_targets.size(); ++g) order[g] = g;
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return signal[a] > signal[b]; });
      strongest.clear();
      for (std::size_t g = 0; g < order.size() && g < static_cast<std::size_t>(zones.targets); ++g)
        strongest.push_back(found_targets[order[g]]);
      found_targets.swap(strongest);
    }
    for (std::size_t found = 0; found < found_targets.size(); ++found) {
      // the sensor's noise once per target, with the draw of its nearest ray
      const ResolvedTarget& target = found_targets[found];
      const int ray = counted[target.rays.begin].ray;
      const NoiseSpec noise = NoiseAt(spec, echoes[static_cast<std::size_t>(ray)].ir_albedo);
      targets[found] = {TimeOfFlightReading_m(noise, target.d_m, draw(ray).gaussian_g), kZoneRangeValid, ray, target.d_m};
    }
    out.target_count[static_cast<std::size_t>(zone)] = static_cast<std::uint8_t>(found_targets.size());
  }
}

namespace {

using Rows = std::vector<std::array<double, 3>>;

// ST's datasheets' maximum ranging distance (typical, 90 % detection rate,
// target filling the field of view; "5 klux" is ST's 2 W/m² of 940 nm on
// the target), inner and corner zones apart, and their ranging accuracy
// ("±x %" of the distance from 200 to 4000 mm, taken as σ as the VL53L1X's
// "± 20 mm" is). Rows [reflectance, ambient_klux, value]. Every figure as
// the datasheets' text is quoted in a public research note on ST's
// multi-zone parts (2026-09; docs/sensors.md cites each table).
struct PartTables {
  const char* part;
  int zones_across;  // 4 or 8
  Rows inner, corner, sigma;
};

const std::vector<PartTables>& AllPartTables() {
  // VL53L5CX, DS13754 Rev 5, accuracy Table 19 (201-4000 mm): 4x4 white 4 %
  // dark / 7 % at 5 klux, grey 5 % / 8 %; 8x8 white 5 % / 8 %, grey 5 % / 11 %
  static const Rows vl53l5cx_sigma_4x4 = {{0.88, 0, 0.04}, {0.17, 0, 0.05}, {0.88, 5, 0.07}, {0.17, 5, 0.08}};
  static const Rows vl53l5cx_sigma_8x8 = {{0.88, 0, 0.05}, {0.17, 0, 0.05}, {0.88, 5, 0.08}, {0.17, 5, 0.11}};
  static const std::vector<PartTables> tables = {
      // VL53L5CX, DS13754 Rev 5: Table 17 (4x4, 30 Hz), Table 18 (8x8, 15 Hz)
      {"vl53l5cx", 4,
       {{0.88, 0, 4.0}, {0.17, 0, 2.4}, {0.88, 5, 1.7}, {0.17, 5, 1.0}},
       {{0.88, 0, 4.0}, {0.17, 0, 2.2}, {0.88, 5, 1.4}, {0.17, 5, 0.95}},
       vl53l5cx_sigma_4x4},
      {"vl53l5cx", 8,
       {{0.88, 0, 3.5}, {0.17, 0, 1.3}, {0.88, 5, 1.1}, {0.17, 5, 0.8}},
       {{0.88, 0, 3.1}, {0.17, 0, 1.1}, {0.88, 5, 1.0}, {0.17, 5, 0.65}},
       vl53l5cx_sigma_8x8},
      // VL53L7CX, DS13865 Rev 6: Table 17 (4x4, 30 Hz), Table 18 (8x8, 15 Hz);
      // no accuracy table found: the VL53L5CX's (the part it is pin-to-pin
      // and driver compatible with), an assumption
      {"vl53l7cx", 4,
       {{0.88, 0, 3.5}, {0.54, 0, 2.8}, {0.17, 0, 1.4}, {0.88, 5, 0.65}, {0.54, 5, 0.6}, {0.17, 5, 0.55}},
       {{0.88, 0, 3.5}, {0.54, 0, 2.8}, {0.17, 0, 1.4}, {0.88, 5, 0.6}, {0.54, 5, 0.6}, {0.17, 5, 0.5}},
       vl53l5cx_sigma_4x4},
      {"vl53l7cx", 8,
       {{0.88, 0, 2.0}, {0.54, 0, 1.6}, {0.17, 0, 0.8}, {0.88, 5, 0.5}, {0.54, 5, 0.4}, {0.17, 5, 0.35}},
       {{0.88, 0, 1.9}, {0.54, 0, 1.6}, {0.17, 0, 0.75}, {0.88, 5, 0.5}, {0.54, 5, 0.4}, {0.17, 5, 0.25}},
       vl53l5cx_sigma_8x8},
      // VL53L8CX, DS14161 Rev 2: Table 16 (4x4, 30 Hz), Table 17 (8x8, 15 Hz);
      // accuracy Table 18 (200-4000 mm): 4x4 white 3 / 4 %, grey 54 % 4 / 6 %,
      // grey 17 % 4 / 7 %; 8x8 white 5 / 5 %, grey 54 % 5 / 6 %, grey 17 % 5 / 8 %
      {"vl53l8cx", 4,
       {{0.88, 0, 4.0}, {0.54, 0, 4.0}, {0.17, 0, 4.0}, {0.88, 5, 2.85}, {0.54, 5, 2.6}, {0.17, 5, 1.65}},
       {{0.88, 0, 4.0}, {0.54, 0, 4.0}, {0.17, 0, 3.95}, {0.88, 5, 2.85}, {0.54, 5, 2.5}, {0.17, 5, 1.55}},
       {{0.88, 0, 0.03}, {0.54, 0, 0.04}, {0.17, 0, 0.04}, {0.88, 5, 0.04}, {0.54, 5, 0.06}, {0.17, 5, 0.07}}},
      {"vl53l8cx", 8,
       {{0.88, 0, 4.0}, {0.54, 0, 3.3}, {0.17, 0, 2.45}, {0.88, 5, 1.55}, {0.54, 5, 1.4}, {0.17, 5, 1.15}},
       {{0.88, 0, 3.95}, {0.54, 0, 3.1}, {0.17, 0, 1.95}, {0.88, 5, 1.4}, {0.54, 5, 1.25}, {0.17, 5, 0.95}},
       {{0.88, 0, 0.05}, {0.54, 0, 0.05}, {0.17, 0, 0.05}, {0.88, 5, 0.05}, {0.54, 5, 0.06}, {0.17, 5, 0.08}}},
  };
  return tables;
}

const PartTables* FindPartTables(const SensorSpec& spec) {
  if (!spec.zones) return nullptr;
  for (const PartTables& t : AllPartTables()) {
    if (spec.part == t.part && spec.zones->nx == t.zones_across && spec.zones->ny == t.zones_across) return &t;
  }
  return nullptr;
}

}  // namespace

void ApplyMultizonePartTables(SensorSpec& spec) {
  if (const PartTables* t = FindPartTables(spec)) {
    spec.range_table = t->inner;
    spec.corner_range_table = t->corner;
    spec.sigma_table = t->sigma;
  } else if (FindMultizonePart(spec.part) != nullptr) {
    spec.range_table.clear();
    spec.corner_range_table.clear();
    spec.sigma_table.clear();
  }
}

double ZoneCornerWeight(const ZoneSpec& zones, int zone) {
  // the weights of the grid last asked for on this thread: a sensor asks for
  // its zones' at every read (its targets' ranges, its silences' reach)
  thread_local std::array<double, 4> grid = {0, 0, 0, 0};
  thread_local std::vector<double> weights;
  const std::array<double, 4> asked = {static_cast<double>(zones.nx), static_cast<double>(zones.ny), zones.fov_h_deg,
                                       zones.fov_v_deg};
  if (asked != grid || weights.empty()) {
    grid = asked;
    // the centre-most zones (the middle 2x2 of an even grid, the middle one of
    // an odd one) and the corners, by their distance from the grid's centre
    const Vec2 cell(2.0 * HalfTan(zones.fov_h_deg) / zones.nx, 2.0 * HalfTan(zones.fov_v_deg) / zones.ny);
    const auto radius = [&](int column, int row) {
      return Vec2((column + 0.5 - 0.5 * zones.nx) * cell.x(), (row + 0.5 - 0.5 * zones.ny) * cell.y()).norm();
    };
    const double r_in = radius((zones.nx - 1) / 2, (zones.ny - 1) / 2), r_corner = radius(0, 0);
    weights.assign(static_cast<std::size_t>(ZoneCount(zones)), 0.0);
    for (int z = 0; z < ZoneCount(zones) && r_corner > r_in; ++z) {
      weights[static_cast<std::size_t>(z)] =
          std::clamp((radius(z % zones.nx, z / zones.nx) - r_in) / (r_corner - r_in), 0.0, 1.0);
    }
  }
  return weights[static_cast<std::size_t>(zone)];
}

double ZoneMaxRange_m(const SensorSpec& spec, double corner_weight, double reflectance) {
  return ZoneRangeEndsFor(spec, reflectance).At(corner_weight);
}

double ZoneSilenceRange_m(const SensorSpec& spec, int zone) {
  if (spec.corner_range_table.empty() || !spec.zones) return SilenceRange_m(spec);
  double darkest = std::numeric_limits<double>::infinity();
  for (const auto& row : spec.range_table) darkest = std::min(darkest, row[0]);
  for (const auto& row : spec.corner_range_table) darkest = std::min(darkest, row[0]);
  return ZoneMaxRange_m(spec, ZoneCornerWeight(*spec.zones, zone), darkest);
}

double MultizoneMaxRate_hz(const SensorSpec& spec) {
  const MultizonePart* part = FindMultizonePart(spec.part);
  if (part == nullptr || !spec.zones) return 0.0;
  const ZoneSpec& z = *spec.zones;
  for (std::size_t g = 0; g < part->grids_across.size(); ++g) {
    if (part->grids_across[g] > 0 && z.nx == part->grids_across[g] && z.ny == part->grids_across[g])
      return part->max_rate_hz[g];
  }
  return 0.0;  // a grid the part does not have: refused as such (sensor_spec.cc), with no rate to hold it to
}

}  // namespace proxsim
