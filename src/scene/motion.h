// How a scene object moves (docs/worlds.md, "Moving objects"). An object with
// a motion is carried by a moving frame M: along waypoints at a speed, turning
// to face its direction of travel; at a constant velocity; or along a
// recorded trajectory (t_s, x, y, z, yaw), interpolated linearly. The object
// sits in M at a fixed pose X_MO, optionally swung about a pivot of M by an
// angle that follows the distance M has travelled (a person's legs and arms:
// scene/person.h), so a part stands still when its carrier does.
//
// Everything here is a pure function of time: the pose at t does not depend
// on the samples taken before it, so an episode's objects are where they are
// at t whatever the thread count, and Reset needs nothing.
//
// Frames: W world, M the moving frame, O the object.
#pragma once

#include <string>
#include <vector>

#include "core/geometry.h"

namespace proxsim {

/// What waypoints do at the last one.
enum class MotionMode {
  kLoop,         ///< on from the last waypoint straight back to the first, round and round
  kBackAndForth, ///< back along the waypoints, then forth again
  kOnce,         ///< stop at the last waypoint
};

/// Names of the modes in MotionMode order ("loop", "back_and_forth", "once").
const std::vector<std::string>& MotionModeNames();

/// One row of a recorded trajectory: where M is at t_s.
struct TrajectoryRow {
  double t_s = 0;
  Vec3 p_WM = Vec3::Zero();  ///< metres
  double yaw_rad = 0;        ///< about world z
};

/// A part's swing about a pivot of M: angle(t) = amplitude·sin(2π·s(t)/cycle + phase),
/// s the distance M has travelled; the rotation is about axis_M through pivot_M.
struct Swing {
  Vec3 pivot_M = Vec3::Zero();
  Vec3 axis_M = Vec3::UnitY();  ///< unit; a person's own y (its legs swing fore and aft)
  double amplitude_rad = 0;  ///< 0: no swing
  double cycle_m = 1.0;      ///< distance travelled per full swing, > 0
  double phase_rad = 0;
};

struct Motion {
  enum class Kind { kWaypoints, kVelocity, kTrajectory };
  Kind kind = Kind::kWaypoints;
  // waypoints: M at the polyline's point, x axis along the segment walked
  std::vector<Vec2> waypoints_m;  ///< at least two, consecutive ones distinct
  double speed_m_s = 1.0;         ///< > 0
  MotionMode mode = MotionMode::kLoop;
  double start_s = 0;             ///< M waits at the first waypoint until then, >= 0
  // velocity: M = translation by v·t (no turning)
  Vec3 velocity_m_s = Vec3::Zero();
  // trajectory: rows with increasing t_s; before the first and after the last, M holds still
  std::vector<TrajectoryRow> trajectory;
  std::string trajectory_file;    ///< as written in the scenario (for echoing)
  /// The object's pose in M (a moving object's `pose` key).
  Pose X_MO = Pose::Identity();
  Swing swing;
};

/// Where the moving frame is at t_s, and how far it has travelled.
struct MotionFrame {
  Pose X_WM = Pose::Identity();
  double travelled_m = 0;
};
MotionFrame MotionFrameAt(const Motion& motion, double t_s);

/// The object's pose in W at t_s: X_WM(t)·(swing about the pivot)·X_MO.
Pose MotionPoseAt(const Motion& motion, double t_s);

/// The velocity in W at t_s of the object's material point that is at p_W at
/// t_s (a central difference over ±0.5 ms: exact for constant velocities).
Vec3 MotionPointVelocity_W(const Motion& motion, double t_s, const Vec3& p_W);

/// Problems of a motion ("waypoints_m: two consecutive waypoints are the
/// same", "trajectory: t_s must increase: row 3 ..."); none when valid.
std::vector<std::string> MotionProblems(const Motion& motion);

}  // namespace proxsim
