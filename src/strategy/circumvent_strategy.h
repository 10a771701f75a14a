// The built-in strategy `circumvent`: walk around an obstacle on the path and
// reach the goal, from the readings alone (the paper's abstract: "strategies
// to avoid and circumvent an obstacle").
//
// What it does, every sample:
//  1. Keeps the measured points of fresh detections that stand at least
//     min_height_m above the ground the robot stands on, one per 2 cm cell of
//     the floor plane (so memory grows with the area seen, not with time).
//  2. Following the path: a point within detect_distance_m ahead of the leading
//     toe and within the robot's half-width plus margin_m of the path is an
//     obstacle (a wall beyond the goal is not). Its extent is the cluster of kept points connected to it
//     (cells closer than kClusterLink_m), measured in the frame of the path
//     segment it sits on (s along the path, l to its left).
//  3. The detour passes on the side needing the smaller sideways shift (and
//     stays on it as more is seen, unless that side no longer fits),
//     keeping half-width + margin_m from the extent: waypoints beside the
//     near and far ends (the far end at least assumed_depth_m behind the near
//     one until more is seen), then back onto the path rejoin_m further on,
//     then the rest of the path. As more of the obstacle is seen the extent
//     grows and the detour is replanned. The gait is given only the detour's
//     waypoints still ahead (a waypoint counts as passed once the pelvis is
//     kPassed_m from it along the path), so it never turns back to one.
//  4. A shift beyond max_detour_m means no way around is seen (a wall): from
//     then on it stops as `stop` would. Whatever the state, a point inside
//     the robot's own width within stop_distance_m ahead of the toe, or
//     within half a stride + 5 cm when that is farther (the swing foot lands
//     up to a step beyond the toe after the stop is commanded), stops it;
//     "ahead" along the heading turned toward the gait's next waypoint as
//     the gait turns its steps (the pelvis lags the step).
//  5. It paces the gait: a 0.3 m stride (or its own, if shorter) while the
//     detour's sideways shift is still to be made or near a sharp corner of
//     the path — half the step halves the radius the gait turns on (15
//     degrees a step); a 0.1 m stride while facing more than 30 degrees away
//     from the gait's next waypoint, the safety stop then looking only a
//     step's reach ahead (the feet move no farther before it takes effect).
//  6. Following the path, it keeps the gait on the path's line: the gait
//     heads for the next waypoint, so after overshooting a corner it would
//     cut across, out of the corridor the path keeps clear; off the line by
//     more than 0.1 m it is given a point on the line 0.6 m ahead.
//  7. Reading the map (`perception: map`), it plans instead of 2-4 a route
//     around every obstacle the map shows (knowledge/map_route.h) to the
//     path's next waypoint, keeping half-width + margin_m clear (or, where
//     only a tighter way exists, half-width + 5 cm), replanned every 0.5 s
//     as the map fills, and follows it as it follows the path (6); with no
//     route it walks on to the safety stop. A safety stop waits: once the
//     way ahead has stayed clear for a second — a person who crossed has
//     walked on — it walks on with its plan; a static obstacle never clears.
// Events: obstacle_seen, detour_planned, detour_replanned, obstacle_passed,
// rejoined, no_way_around, blocked, walking_on, slowing_down, speeding_up.
//
// Frames: W world; the path frame: origin at the segment's start, s along it,
// l to its left, both in metres on the floor plane.
#pragma once

#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "strategy/strategy.h"
#include "strategy/strategy_config.h"

namespace proxsim {

class CircumventStrategy : public Strategy {
 public:
  explicit CircumventStrategy(CircumventConfig config) : config_(config) {}

  std::string name() const override { return "circumvent"; }
  void Reset(const StrategySetup& setup) override;
  void Decide(const Observation& observation, RobotCommands& robot, EventLog& events) override;

  /// The obstacle's extent in the path frame, as last measured (for tests and viewers).
  struct Extent {
    double s_min = 0, s_max = 0, l_min = 0, l_max = 0;
  };
  const std::optional<Extent>& extent() const { return extent_; }
  /// The detour last commanded (world x-y), empty when none.
  const std::vector<Vec2>& detour() const { return detour_; }

  /// Cells closer than this belong to one obstacle, m.
  static constexpr double kClusterLink_m = 0.12;
  /// Side of the cells that keep one point each, m.
  static constexpr double kCell_m = 0.02;

 private:
  // kWaiting: stopped by the safety stop for the map's obstacle, which may walk away (a person)
  enum class Mode { kFollowing, kDetouring, kBlocked, kStopped, kWaiting };
  using Cell = std::pair<std::int64_t, std::int64_t>;
  struct Segment {
    Vec2 origin = Vec2::Zero();
    Vec2 u = Vec2::UnitX();          // unit, along the path
    std::vector<Vec2> rest;          // the path's waypoints after this segment's start
  };

  // reading the map: a route to the path's next waypoint around every obstacle mapped,
  // replanned every kReplanRoute_s as the map fills, followed as the path is
  void FollowRouteOnMap(const Observation& observation, const Vec2& p_WP, RobotCommands& robot, EventLog& events);
  // following the path or detouring around what was seen (after the safety stop)
  void FollowOrDetour(const Observation& observation, const Vec2& p_WP, RobotCommands& robot, EventLog& events);
  // the stride for what is ahead: slower while the detour's shift is being made, near a sharp
  // corner of the path, or while turning hard toward the gait's target
  void Pace(const Vec2& p_WP, double yaw_rad, RobotCommands& robot, EventLog& events);
  bool NearSharpCorner(const Vec2& p_WP) const;
  void KeepPoints(const Observation& observation);
  // the first fresh point within look_ahead_m ahead of the leading toe, inside lateral_m of the pelvis's line along walking_W
  std::optional<Vec3> PointInTheWay(const Observation& observation, const Vec3& walking_W, double look_ahead_m,
                                    double lateral_m) const;
  // the waypoint the gait walks toward: the first of the path it follows not yet passed
  Vec2 GaitTarget(const Vec2& p_WP) const;
  // the index the gait heads for in `path` (its first point: where the pelvis was when it was given), from `first` (>= 1) on
  std::size_t GaitTargetIndex(const std::vector<Vec2>& path, std::size_t first, const Vec2& p_WP) const;
  // following the path: steer the gait back onto the path's line when it strays
  void TrackPath(const Vec2& p_WP, RobotCommands& robot);
  // the heading turned toward the gait's target as the step under way turns (unit, horizontal)
  Vec3 WalkingDirection(const RobotKnowledge& self, const Vec2& p_WP) const;
  // the first fresh point ahead within detect_distance_m and within half-width + margin of the path
  std::optional<Vec3> PointOnThePath(const Observation& observation) const;
  double DistanceToPath_m(const Vec2& p_W) const;
  // the kept points connected to the seed cell, as an extent in the segment's frame
  Extent MeasureCluster(const Cell& seed, const Segment& segment) const;
  Segment SegmentNear(const Vec2& p_W) const;
  // the detour around `extent`; false (no waypoints) when the shift would exceed max_detour_m
  bool PlanDetour(const Extent& extent, std::vector<Vec2>* waypoints, double* shift_m) const;
  Cell CellOf(const Vec3& p_W) const;
  // the detour's waypoints still ahead of the robot
  std::vector<Vec2> Remaining() const;
  // "to the left of the path, 0.46 m aside; obstacle s in [...]; via (x, y), ..."
  std::string DescribeDetour() const;
  Vec2 ToWorld(double s, double l) const;

  CircumventConfig config_;
  // this sample's raised points (fresh readings' or the map's obstacles' outlines: config_.perception)
  void FindRaisedPoints(const Observation& observation);

  std::vector<SensorInfo> sensors_;
  std::vector<Vec3> raised_;
  std::vector<Vec2> path_m_;
  double stride_m_ = 0;      // the gait's own stride (NaN: not known)
  double stride_now_m_ = 0;  // the stride last commanded
  double stride_in_force_m_ = 0;  // the stride of the step being walked
  Vec2 detour_given_at_W_ = Vec2::Zero();  // where the pelvis was when the detour's waypoints were last given to the gait
  bool stride_changed_ = false;   // a stride commanded that the step being walked does not have yet
  SupportLeg last_support_ = SupportLeg::kDouble;
  bool started_ = false;
  Mode mode_ = Mode::kFollowing;
  std::vector<Vec2> given_path_m_;     // the path the robot was given (path_m_ becomes the route on the map)
  std::size_t given_target_ = 1;       // its next waypoint not yet passed
  double next_route_t_s_ = 0;          // when the route is planned again
  bool no_route_ = false;              // the last planning found no route
  Mode mode_before_waiting_ = Mode::kFollowing;
  WayClearWait way_clear_;           // waiting: the wait for the way ahead to clear
  double half_width_m_ = 0;
  std::map<Cell, Vec3> points_;  // the kept points, one per cell
  std::vector<Cell> cells_added_;   // the cells of points_ in the order they were added
  std::uint64_t cells_moved_ = 0;   // how often a kept cell's point moved in x-y
  // a walk of the kept cells from a seed in a segment's frame (MeasureCluster)
  struct ClusterWalk {
    bool valid = false;
    Cell seed{};
    Vec2 origin = Vec2::Zero(), u = Vec2::Zero();
    std::uint64_t moved = 0;      // cells_moved_ when walked
    std::size_t added = 0;        // cells_added_ taken into account
    std::set<Cell> seen;          // the cells reached (and the seed)
    Extent extent{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                  std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  };
  mutable ClusterWalk cluster_walk_;
  // the walk carried on from the cells in `queue` (each already in walk.seen)
  void GrowCluster(ClusterWalk& walk, std::deque<Cell> queue) const;
  // visit(cell) for each kept cell linked to a point p_W of `cell` (closer than
  // kClusterLink_m), until visit returns false
  template <typename Visit>
  void ForEachLinkedCell(const Cell& cell, const Vec2& p_W, Visit visit) const;
  Cell seed_{};
  Segment segment_;
  std::optional<Extent> extent_;
  double shift_m_ = 0;  // the detour's sideways shift, signed (> 0: to the left)
  std::vector<Vec2> detour_;
  static constexpr std::size_t kDetourWaypoints = 3;  // detour_ starts with these, then the rest of the path
  std::size_t next_waypoint_ = 0;    // detour_ before this one are behind the robot
  std::size_t detour_waypoints_ = 0;  // of detour_, the ones the strategy steers through
  int side_ = 0;                   // +1 left, -1 right, 0 not chosen yet
  bool passed_ = false;
  std::size_t path_target_ = 1;  // following: the path's waypoint the gait walks toward (only moves on)
  bool tracking_ = false;  // following: the gait is steered to carrot_ on the path's line
  Vec2 carrot_ = Vec2::Zero();
};

}  // namespace proxsim
