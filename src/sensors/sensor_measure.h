// One sample of a sensor from its rays' echoes, whatever its type: the
// headline reading (readings.csv's row, the paper's distance curve) and the
// ragged list of measurements beside it (sensors/measurement.h). A single ray
// is the paper's model (sensor_model.h); a beam combines its rays
// (MeasureBeam) and, with `echoes: strongest | all`, lists its echoes
// (beam_echoes.h); a grid of zones lists every zone's targets (multizone.h)
// and its headline is the nearest valid target of any zone, along that
// zone's axis. Pure: the same echoes and draws give the same sample.
//
// Frames: W world, S the sensor.
#pragma once

#include <span>

#include "sensors/beam.h"
#include "sensors/measurement.h"
#include "sensors/sensor_model.h"
#include "sensors/sensor_spec.h"

namespace proxsim {

/// Where a sensor stood when it measured, in W.
struct SensorPlacement {
  Vec3 p_WS = Vec3::Zero();           ///< its origin (its rays start here)
  Vec3 dir_W = Vec3::UnitX();         ///< its axis: its frame's +x (unit)
  std::span<const Vec3> zone_dir_W;   ///< a multi-zone part's zone axes (unit), zone order; empty otherwise
};

/// A sensor's sample.
struct SensorMeasurement {
  BeamReading headline;               ///< the reading, the ray it came from, the ray whose truth stands beside it
  Vec3 headline_dir_W = Vec3::UnitX();  ///< the axis the reading lies along: the sensor's, or its zone's
  double headline_cos_to_axis = 1.0;    ///< as Measurement::cos_to_axis: a perpendicular zone's reading lies d / cos along it
  Measurements measured;              ///< what the part reports beside the reading (empty for most parts)
  Measurements truth;                 ///< the same list with noise-free distances
};

/// Measures one sample: echoes[i] belongs to rays[i]; `draw` gives ray i's
/// noise draws (asked only for the rays a measurement comes from). Writes
/// every field of `out`, reusing its buffers.
void MeasureSensorSample(const SensorSpec& spec, const SensorPlacement& at, std::span<const Echo> echoes,
                         std::span<const BeamRay> rays, const DrawOfRay& draw, SensorMeasurement& out);

}  // namespace proxsim
