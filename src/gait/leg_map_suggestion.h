// A leg map (`robot.legs`) suggested from a URDF's geometry, never from its
// names, for `proxsim inspect`: the feet are the lowest links of the chains
// that reach the ground, and on each foot's chain from the root the hip, knee
// and ankle pitch joints are the revolute joints whose axis lies along the
// root's lateral y (within kMaxPitchAxisTilt_deg, as the gait requires),
// ordered hip above knee above ankle. The suggestion is then read by the
// same code that reads a scenario's map (BipedLegs), so what it says is
// accepted is what `proxsim validate` accepts.
//
// With it, where a sensor can sit on each shank (the link the knee joint
// moves, or a link fixed to it that has geometry when it has none): the
// point of the shank's geometry farthest forward (the root's +x) at a few
// heights between the knee and the ankle.
//
// Frames: W world = the root link's frame at the reference pose (every joint
// 0), L a link.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "gait/gait_config.h"
#include "robot/robot_inspect.h"

namespace proxsim {

/// A link a leg chain ends on, low in the robot: a foot.
struct FootCandidate {
  int link = -1;
  double lowest_z_m = 0;  ///< its geometry's lowest point in W
  double y_m = 0;         ///< its geometry's centre across, in W (> 0: left)
};

/// A place for a sensor on the front of a shank, in the shank's link frame.
struct ShankSpot {
  double fraction = 0;     ///< from the knee (0) to the ankle (1)
  Vec3 p_L = Vec3::Zero(); ///< kShankStandOff_m proud of the front surface there (the sensor's origin)
  Vec3 rpy_deg = Vec3::Zero();  ///< a sensor frame whose +x is the robot's forward (level, at the zero pose)
  Vec3 rpy_deg_pitched_down = Vec3::Zero();  ///< the same frame pitched down kShankPitchDown_deg
};

/// How far a suggested sensor origin stands off the shank's surface: on
/// the surface itself, a ray may meet the link at 0 mm (every reading `self`).
inline constexpr double kShankStandOff_m = 0.005;
/// The pitch down of the second suggested orientation (the paper's shin sensors look down 8-20°).
inline constexpr double kShankPitchDown_deg = 15.0;

struct LegSuggestion {
  std::optional<LegNames> names;  ///< none when no leg map could be read off this side
  std::string problem;            ///< why not
  int shank_link = -1;            ///< the knee's child link (or one fixed to it with geometry), when there is a knee
  std::vector<ShankSpot> shank_front;  ///< at kShankFractions, where the front line meets the shank
};

struct LegMapSuggestion {
  std::vector<FootCandidate> feet;      ///< every candidate, left (y > 0) first
  std::array<LegSuggestion, 2> legs;    ///< left, right
  bool accepted = false;                ///< both legs found and BipedLegs reads them
  /// When accepted: each foot's pitch at the reference pose as the gait reads
  /// it (left, right; toe up +), degrees — 0 for a sole flat at joint zero, else
  /// the pitch its geometry lies flattest at, which the gait walks flat
  /// (what `legs.*.ankle_zero_deg` would give)
  std::array<double, 2> ankle_zero_deg{0, 0};
  std::vector<std::string> problems;    ///< why BipedLegs refuses them (its messages), when it does
};

/// Heights along each shank where its front surface is reported.
inline constexpr std::array<double, 3> kShankFractions = {0.25, 0.5, 0.75};

/// Suggests a leg map for `model` at its reference pose (`summary`).
LegMapSuggestion SuggestLegMap(const RobotModel& model, const RobotSummary& summary);

}  // namespace proxsim
