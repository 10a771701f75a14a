// What the robot knows at a sample, and nothing else: what its devices
// delivered (latency applied), where its own kinematics put its sensors and
// feet, and the terrain map it built from these (knowledge/terrain_map.h).
// The strategies (strategy/strategy.h) and the gait read these; the
// simulation fills them (sim/robot_knowledge.h).
//
// What the robot does not know cannot be reached from here: the types below
// carry no reading status, no true distance, hit point, object or clearance
// (SampleFrame in sim/ holds those, for outputs and scoring). A test checks
// that these types have no such member, and the build that this module sees
// no truth: its modules are core and sensors only, so that an include of the
// scene, the ray caster, the simulation or the outputs' truth field does not
// compile (tests/layering/knowledge_includes_*.cc).
//
// Frames: W world, P pelvis (the robot's root link), S a sensor.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "knowledge/support_leg.h"
#include "sensors/measured_point.h"
#include "sensors/measurement.h"
#include "sensors/sensor_spec.h"

namespace proxsim {

class TerrainMap;  // knowledge/terrain_map.h: built from the readings only

/// What one sensor device delivered at a sample: its outputs, and where the
/// robot's kinematics put the sensor when it measured.
struct SensorOutput {
  bool fresh = false;      ///< a reading arrived at this sample; otherwise the fields below hold no news
  bool detected = false;   ///< the device reports an echo (d_m < its range)
  double d_m = 0.0;        ///< the reported distance; the maximum range when nothing was detected
  double signal = std::numeric_limits<double>::quiet_NaN();  ///< reflectance signal s; NaN for time of flight
  double output = std::numeric_limits<double>::quiet_NaN();  ///< a lookup sensor's output; NaN otherwise
  double t_reported_s = std::numeric_limits<double>::quiet_NaN();  ///< when the reading was reported
  Vec3 p_WS = Vec3::Zero();    ///< the sensor's origin when it measured
  Vec3 dir_W = Vec3::UnitX();  ///< its axis (unit) when it measured
  double cos_to_axis = 1.0;    ///< a zone part reporting distances on its axis: the point lies d_m / cos_to_axis along dir_W

  /// What the device reports beside its reading, each with where it lies
  /// (sensors/measurement.h): a multi-zone part's targets, zone by zone; a
  /// beam's several echoes. Empty for the other sensors; kept as last
  /// delivered while no news arrives.
  Measurements measurements;

  /// The point the reading puts in the world: origin + d_m along the axis.
  Vec3 p_W_measured() const { return MeasuredPoint_W(p_WS, dir_W, d_m / cos_to_axis); }
  /// The reading as a measurement (status ok when detected, no_echo otherwise; group -1: the sensor's own).
  Measurement headline() const {
    return Measurement{.p_WS = p_WS, .dir_W = dir_W, .d_m = d_m,
                       .status = detected ? ReadingStatus::kOk : ReadingStatus::kNoEcho, .signal = signal, .group = -1,
                       .cos_to_axis = cos_to_axis};
  }
};

/// What the robot's datasheets and mounting tell it about one sensor.
struct SensorInfo {
  std::string name;
  SensorType type = SensorType::kIdeal;
  double min_range_m = 0.0;
  double max_range_m = 0.0;
  std::string link;  ///< the link it is fixed on ("world" for a fixed sensor)
  double max_incidence_deg = 90.0;  ///< echoes come back from surfaces met within this angle of their normal
  double aperture_deg = 0.0;        ///< full cone angle of its beam (0: one ray along its axis)
};

/// One foot's contact points, from the robot's kinematics.
struct FootKnowledge {
  Vec3 p_W_sole = Vec3::Zero();  ///< the sole point under the ankle
  Vec3 p_W_toe = Vec3::Zero();   ///< the sole's front end, on the foot's centre line
  Vec3 p_W_heel = Vec3::Zero();  ///< the sole's back end
};

/// The robot's knowledge of itself at a sample (odometry and joint encoders).
struct RobotKnowledge {
  Pose X_WP = Pose::Identity();  ///< pelvis pose
  double yaw_rad = 0.0;          ///< pelvis heading about z
  std::vector<double> q;         ///< joint positions by joint index (rad, or m for prismatic)
  double gait_phase = 0.0;       ///< left leg's phase in [0, 1), 0 at its heel strike
  SupportLeg support = SupportLeg::kDouble;
  bool has_feet = false;                  ///< false for a robot whose locomotion names no feet
  std::array<FootKnowledge, 2> feet;      ///< [0] left, [1] right
  Vec3 heading_W = Vec3::UnitX();         ///< unit, horizontal: the walking direction
  bool stopped = false;                   ///< standing still
  double distance_walked_m = 0.0;
  // derived from the above, as every strategy needs them
  Vec3 p_W_front = Vec3::Zero();  ///< the foremost toe along the heading
  double ground_z_m = 0.0;        ///< height of the ground the robot stands on: its lowest sole or toe point
  double half_width_m = 0.0;      ///< the robot's half-width about its pelvis's sagittal plane (at start)
};

/// Everything a strategy sees at one sample.
struct Observation {
  double t_s = 0.0;
  std::int64_t sample = 0;
  std::span<const SensorOutput> sensors;  ///< one per sensor, in scenario order
  const RobotKnowledge* robot = nullptr;  ///< null when the scenario has no robot
  /// The terrain map built so far from the delivered readings (this sample's
  /// included); null without a robot or when the scenario turns it off.
  const TerrainMap* map = nullptr;
};

}  // namespace proxsim
