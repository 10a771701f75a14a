// Perfect perception for the terrain map (`map.truth_within_m` > 0, the
// outcome study's oracle baseline, study/outcome_baselines.h): every cell
// within that distance of the pelvis, ahead of it (in front of the line
// across the walk kTruthBehind_m behind the pelvis: what is behind the robot
// it has walked), takes the scene's true height, as a
// vertical ray from the map's ceiling down finds it (truth_field.h), so the
// map holds what perfect sensors would have shown — no sensor's sampling,
// range, incidence or noise between the world and the strategy.
//
// A still cell is cast once, when it first comes within reach; the cells
// about each moving object (where it is, and where it was at the last feed)
// are cast again at every feed, so a person is seen where it stands and
// leaves nothing behind. Fed kTruthFeedRate_hz times a second.
//
// Frames: W world.
#pragma once

#include <cstdint>
#include <optional>
#include <unordered_set>
#include <utility>
#include <vector>

#include "knowledge/ray_evidence.h"
#include "sim/world.h"

namespace proxsim {

inline constexpr double kTruthFeedRate_hz = 10;
inline constexpr double kTruthBehind_m = 0.5;

class TruthMapFeed {
 public:
  /// Cells of `resolution_m` (the map's) within `reach_m` of the pelvis.
  TruthMapFeed(double reach_m, double resolution_m);

  /// A new episode: nothing cast yet.
  void Reset();

  /// The columns due at t_s (none between feeds): vertical rays from
  /// `ceiling_z_m` (the map's) through each cell's centre, detected at the
  /// true height; none where there is no surface at all (the cell stays unknown).
  /// `heading_W`: the robot's (unit, horizontal).
  const std::vector<RayEvidence>& Columns(const World& world, const Vec2& p_W_pelvis, const Vec2& heading_W,
                                          double ceiling_z_m, double t_s);

 private:
  static std::int64_t Key(std::int32_t ix, std::int32_t iy) {
    return (static_cast<std::int64_t>(ix) << 32) ^ static_cast<std::uint32_t>(iy);
  }
  // the cells within radius_m of p_W that are within the reach about
  // p_W_pelvis (or were cast before), each once into `due` (and `queued`)
  void AddDisc(const Vec2& p_W, double radius_m, const Vec2& p_W_pelvis, const Vec2& heading_W);
  // the never-cast cells of the reach about p_W along heading_W, but those in the reach at the last feed
  void AddReach(const Vec2& p_W, const Vec2& heading_W);
  // the columns ix (first, last) of row iy whose centres lie in the reach
  // about p_W along heading_W; first > last when none
  std::pair<std::int32_t, std::int32_t> ReachInRow(std::int32_t iy, const Vec2& p_W, const Vec2& heading_W) const;

  double reach_m_;
  double resolution_m_;
  double next_feed_t_s_ = 0;
  std::unordered_set<std::int64_t> cast_;          // still cells cast already
  std::vector<std::pair<Vec2, double>> moving_before_;  // the moving objects at the last feed
  std::optional<std::pair<Vec2, Vec2>> reach_before_W_;  // the reach's centre and heading at the last feed
  std::unordered_set<std::int64_t> queued_;        // this feed's cells, once each
  std::vector<Vec2> due_xy_W_;
  std::vector<RayEvidence> columns_;
};

}  // namespace proxsim
