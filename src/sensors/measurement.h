// One shape for everything a sensor reports beyond its headline reading: a
// multi-zone part's targets (a zone is a group, its targets ranked in the
// part's target order) and a beam's several echoes (one group, nearest
// first) are the same ragged list of measurements, so that the terrain map,
// the strategies, the outputs and Python read them without knowing the
// sensor's type. The truth beside a list has the same shape: the same
// measurements with their noise-free distances.
//
// Convention for "nothing" (as for a reading, the paper's §5): a measurement
// whose status is not kOk reports the sensor's maximum range; `code` keeps
// the part's own status code (ST's target status for a zone: 5 valid, 8
// signal too low, 255 no target), which says why.
//
// Frames: W world, S the sensor.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "core/geometry.h"
#include "sensors/measured_point.h"
#include "sensors/sensor_model.h"

namespace proxsim {

struct Measurement {
  Vec3 p_WS = Vec3::Zero();    ///< the sensor's origin when it measured
  Vec3 dir_W = Vec3::UnitX();  ///< unit: the direction the distance lies along (a zone's axis, a beam's axis)
  double d_m = 0.0;            ///< the reported distance; the sensor's maximum range when status is not kOk
  ReadingStatus status = ReadingStatus::kNoEcho;  ///< kOk: a target or echo the part reports
  std::uint8_t code = 0;       ///< the part's own status code for it (ST's for a zone's target; 0: the part has none)
  double signal = std::numeric_limits<double>::quiet_NaN();  ///< its signal, NaN where the part reports none
  std::int32_t group = 0;      ///< the zone it belongs to (0 for a beam's echoes; -1 a sensor's own reading)
  std::int32_t rank = 0;       ///< its place in its group's order, 0 first (the part's target order; echoes nearest first)
  /// A part that reports distances projected on its axis (ST's multi-zone
  /// parts): the cosine between dir_W and the sensor's axis, so that the
  /// point lies d_m / cos_to_axis along dir_W; 1 for a distance along dir_W.
  double cos_to_axis = 1.0;

  bool detected() const { return status == ReadingStatus::kOk; }
  /// The distance along dir_W from the origin to the point it measured.
  double ray_d_m() const { return d_m / cos_to_axis; }
  /// The point it puts in the world: origin + ray_d_m() along its direction.
  Vec3 p_W() const { return MeasuredPoint_W(p_WS, dir_W, ray_d_m()); }
};

/// A sensor's measurements at one sample; empty for a sensor that reports
/// only its headline reading, and between its own samples.
using Measurements = std::vector<Measurement>;

}  // namespace proxsim
