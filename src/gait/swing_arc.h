// The swing foot's path over uneven ground: the ankle's arc from toe-off to
// heel strike in the step's heading frame H (s along the heading from the
// stance heel, z up), and the clearance of a sole on it over the ground's
// profile.
//
// The arc lifts, carries and lowers the foot: horizontally the ankle eases
// from where the planted foot left it (its speed at toe-off kept) to above
// its landing point over [kArcCarryStart, kArcCarryEnd], lifting before and
// only lowering after;
// vertically it eases from the start height to the landing height, plus a
// lift plateau of `lift_m` that rises over [0, kArcLiftRise] and falls over
// [kArcLowerStart, 1]. The step planner sizes lift_m so that the sole clears
// every edge it passes over by kSwingClearance_m (gait_steps.h).
#pragma once

#include "core/geometry.h"
#include "gait/terrain_profile.h"

namespace proxsim {

/// Swing progress at which the arc's horizontal travel starts (before, it lifts).
constexpr double kArcCarryStart = 0.1;
/// Swing progress at which the arc's horizontal travel ends (then it only lowers).
constexpr double kArcCarryEnd = 0.85;
/// Swing progress by which the lift plateau has risen.
constexpr double kArcLiftRise = 0.3;
/// Swing progress from which the lift plateau falls to the landing.
constexpr double kArcLowerStart = 0.75;
/// Span of swing progress over which a foot changes height, by default: a
/// climbing foot rises over [0, span], a descending one lowers over [1 − span, 1].
constexpr double kArcHeightChangeSpan = 0.7;

/// The ankle's arc in H, u from 0 (toe-off) to 1 (heel strike).
struct SwingArc {
  Vec2 start = Vec2::Zero();       ///< ankle (s, z) at toe-off
  Vec2 start_rate = Vec2::Zero();  ///< its rate d/du at toe-off (the planted foot's)
  Vec2 end = Vec2::Zero();         ///< ankle at heel strike
  double lift_m = 0;               ///< height of the lift plateau
  /// Span over which the height changes (kArcHeightChangeSpan unless the
  /// planner needs the height gained sooner: a steep climb's toe would
  /// otherwise need a lift that carries the foot far above the edge it clears).
  double height_span = kArcHeightChangeSpan;
  /// Swing progress at which the horizontal travel starts (kArcCarryStart
  /// unless the toe must first rise clear of a riser right in front of it).
  double carry_start = kArcCarryStart;
  /// Whether the foot keeps its toe-off pitch until the carry starts (its toe
  /// then rises straight up off a riser right in front of it, instead of
  /// unrolling into it), to level over the carry (StepPlanner::SwingPitch).
  bool hold_pitch = false;
  double start_pitch_rad = 0;  ///< the foot's pitch at toe-off (held with hold_pitch)

  /// The ankle at u in [0, 1].
  Vec2 At(double u) const;
  /// The lift plateau's shape at u (0 at both ends, 1 in the middle).
  static double LiftShape(double u);
  /// The horizontal travel's progress at u (0 until carry_start, 1 from kArcCarryEnd).
  double CarryShape(double u) const;
};

/// A foot's sole in the sagittal plane: its heel and toe from the ankle at pitch 0.
struct SoleShape {
  Vec2 heel_from_ankle = Vec2::Zero();
  Vec2 toe_from_ankle = Vec2::Zero();
  double toe_top_m = 0;   ///< the foot's front face above the toe (at pitch 0)
  double heel_top_m = 0;  ///< its back face above the heel
};

/// How far a sole at (ankle, pitch) in H lies below what it must clear, m
/// (≤ 0: it clears): every edge of `profile` under the sole by `clearance_m`,
/// and every point of the sole and of the foot's front and back faces (which
/// a pitched foot pushes ahead of its toe or behind its heel) above the
/// ground — by `clearance_m` too, except
/// over the segments `own_a` and `own_b` (the treads the foot leaves and lands
/// on), where touching is allowed. Segment indices into profile.segments().
/// An edge within `edge_reach_m` beyond either end of the sole counts as
/// under that end: a sole checked at samples of its motion then cannot step
/// past an edge between two samples unchecked (give the distance it moves
/// between them).
double SoleDeficit(const TerrainProfile& profile, const Vec2& ankle_H, double pitch_rad, const SoleShape& sole,
                   double clearance_m, std::size_t own_a, std::size_t own_b, double edge_reach_m = 0);
/// The sole's heel and toe in H for an ankle and pitch.
std::pair<Vec2, Vec2> SoleEnds(const Vec2& ankle_H, double pitch_rad, const SoleShape& sole);

}  // namespace proxsim
