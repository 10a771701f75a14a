// A multi-zone time-of-flight sensor (ST's VL53L5CX, VL53L7CX, VL53L8CX; ST's
// single-zone, multi-target VL53L4CX as a grid of one zone; or a generic
// `multizone` one): its square field of view is split into nx × ny
// zones, each sampled by k × k rays, and each zone reports up to `targets`
// targets in one of ST's two target orders: nearest first ("closest", the
// default here) or the most signal first ("strongest", the default of ST's
// driver: `target_order`).
//
// Geometry. The zones are the cells of a grid on the image plane x = 1 of the
// sensor frame S (the SPAD array behind the receiver lens): u = y/x across
// [−tan(h/2), tan(h/2)], v = z/x across [−tan(v/2), tan(v/2)]. Zone z = row·nx
// + column, row 0 at the top (+z), column 0 on the left (+y) as seen looking
// along +x. A zone's rays pass through the centres of a k × k sub-grid of its
// cell, its axis through the cell's centre.
//
// Targets. The rays of a zone whose echo counts (the range and incidence
// window, or the physical echo model, as for any time-of-flight sensor) are
// sorted by distance and split where two successive distances differ by the
// part's minimum target separation or more: ST gives 600 mm for the
// VL53L5CX/L7CX/L8CX ("the minimum distance between two targets to be
// detected is 600 mm", UM2884, UM3038, UM3109), and no figure was found for
// the VL53L4CX, which takes the same 600 mm (an assumption); closer surfaces
// merge into one target. A ray's distance is the one the part reports:
// projected on the sensor's axis for ST's multi-zone parts (`perpendicular`:
// a flat wall facing the sensor reads the same in every zone; ST does the
// conversion on the chip), or along the ray (`radial`: the single-zone
// VL53L4CX's, which times its photons along their paths). A target's
// distance is the centre of its rays' distances weighed by the signal each
// returns, ρ·cos θ / d² for a matte surface (the histogram's peak: a zone
// straddling a near bright edge and a far wall leans to the edge), with the
// sensor's noise model applied once per target (the draw of the target's
// nearest ray). The same signal
// sets a ray's range: a part whose range depends on the target (its range
// tables, measured on a flat target facing the sensor, which a ray meets at
// its own angle φ off the axis) sees a surface met at incidence θ as a target
// of reflectance ρ·cos θ / cos φ, so a grazing floor falls silent ("signal
// rate too low") before a wall facing it. Rays that hit the robot's own body
// never make a target (the `self` convention).
//
// Status, per zone and target, as ST's ULD API codes it (UM2884 Table 4):
// 5 "range valid" for a target; for a zone without one, 8 "signal rate too
// low for the current target" when a surface lies within range but none of
// its echoes counts (too grazing, too weak, or in the dead zone), else 255
// "no target detected"; 0 "ranging data are not updated" between the
// sensor's own samples. The other codes of the table (sigma, wrap-around,
// consistency checks) depend on the device's internal algorithms and are not
// produced.
//
// Frames: S the sensor (its +x is the field of view's axis), W world.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sensors/beam.h"
#include "sensors/sensor_model.h"

namespace proxsim {

/// ST's target status codes that the model produces (UM2884 Table 4).
inline constexpr std::uint8_t kZoneNotUpdated = 0;       ///< "ranging data are not updated"
inline constexpr std::uint8_t kZoneRangeValid = 5;       ///< "range valid"
inline constexpr std::uint8_t kZoneSignalTooLow = 8;     ///< "signal rate too low for the current target"
inline constexpr std::uint8_t kZoneNoTarget = 255;       ///< "no target detected"

/// The snake_case name of a zone status code the model produces ("?" otherwise).
const char* ZoneStatusName(std::uint8_t code);
/// The codes the model produces, in ascending order.
const std::vector<std::uint8_t>& ZoneStatusCodes();

/// One target of one zone in one sample.
struct ZoneTarget {
  double d_m = 0.0;                     ///< the reported distance; 0 where there is no target
  std::uint8_t status = kZoneNoTarget;  ///< ST's code
  std::int32_t ray = -1;                ///< the sensor's ray nearest in the target (truth), -1: none
  double truth_d_m = 0.0;               ///< the noise-free distance: the mean of its rays' arrivals
};

/// A sensor's zones in one sample: zones × targets, zone-major.
struct ZoneReadings {
  std::vector<ZoneTarget> targets;          ///< [zone · targets + target]
  std::vector<std::uint8_t> target_count;   ///< [zone]: valid targets found
};

/// The part's limits that a scenario is checked against, and its preset's grid.
struct MultizonePart {
  const char* name;
  double fov_deg;             ///< square field of view, degrees (each side)
  double max_range_m;         ///< the datasheet's longest range
  /// The grids the part has, zones a side (0: no second grid), the first its
  /// preset's, and the ranging frequency limit at each, Hz.
  std::array<int, 2> grids_across;
  std::array<double, 2> max_rate_hz;
  int rays_per_zone;          ///< the preset's rays per zone (k², an assumption of the model)
  int targets;                ///< the preset's targets per zone (the driver's default)
  bool perpendicular;         ///< the preset's distance: projected on the axis (true) or radial
  const char* source;         ///< where the figures come from
};

/// The named multi-zone parts ("vl53l4cx", "vl53l5cx", "vl53l7cx", "vl53l8cx").
std::span<const MultizonePart> MultizoneParts();
/// The part called `name`, or null.
const MultizonePart* FindMultizonePart(const std::string& name);
/// The grids a part has, as a scenario writes them: "[4, 4] or [8, 8]", "[1, 1]".
std::string MultizonePartGrids(const MultizonePart& part);

/// The number of zones.
inline int ZoneCount(const ZoneSpec& zones) { return zones.nx * zones.ny; }

/// The rays of a zone grid, zone-major (zone z owns rays [z·k², (z+1)·k²)), gain 1, weight 1/N.
std::vector<BeamRay> MakeZoneRays(const ZoneSpec& zones);

/// The axis of zone `zone` in S (unit): through the centre of its cell.
Vec3 ZoneAxis_S(const ZoneSpec& zones, int zone);

/// The rays a sensor casts: its zones, its beam, or the paper's single ray.
std::vector<BeamRay> MakeSensorRays(const SensorSpec& spec);

/// The zones' targets from every ray's echo (echoes[i] belongs to the
/// sensor's ray rays[i]); `draw` gives ray i's noise draws. Writes `out`, sized here.
void MeasureZones(const SensorSpec& spec, std::span<const Echo> echoes, std::span<const BeamRay> rays,
                  const DrawOfRay& draw, ZoneReadings& out);

/// Sets a named part's tables at the sensor's resolution from its datasheet:
/// range_table (the inner zones' longest range), corner_range_table (the
/// corner zones') and noise.sigma_table (its ranging accuracy); see
/// docs/sensors.md for each part's tables. No-op for a generic grid.
void ApplyMultizonePartTables(SensorSpec& spec);

/// Where a zone lies between the grid's centre zones (0: the middle 2x2 of
/// an even grid, the middle zone of an odd one) and its four corners (1):
/// its cell centre's distance from the grid's centre on the image plane,
/// linear between the two (the datasheets tabulate only those two ends).
double ZoneCornerWeight(const ZoneSpec& zones, int zone);

/// A zone's longest range for a target of reflectance ρ: range_table's,
/// moved toward corner_range_table's by the zone's corner weight; capped at
/// max_range_m.
double ZoneMaxRange_m(const SensorSpec& spec, double corner_weight, double reflectance);

/// How far a zone's silence says nothing is: its range for the darkest
/// target its tables hold (SilenceRange_m without a corner table).
double ZoneSilenceRange_m(const SensorSpec& spec, int zone);

/// The fastest ranging rate of the sensor's part at its resolution, Hz (0: no
/// limit, or a resolution the part does not have).
double MultizoneMaxRate_hz(const SensorSpec& spec);

}  // namespace proxsim
