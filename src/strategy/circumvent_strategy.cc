#include "strategy/circumvent_strategy.h"

#include "knowledge/echo_cone.h"
#include "knowledge/map_queries.h"
#include "knowledge/map_route.h"
#include "core/message_format.h"
#include "gait/gait_walker.h"
#include "gait/waypoint_rule.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <set>
#include <string>

namespace proxsim {

namespace {

// after the far end the detour runs parallel to the path this much further
// before it turns back, so that the robot's trailing foot clears the corner
constexpr double kRunOut_m = 0.2;
// a detour waypoint counts as passed once the pelvis is this close to it along the path
constexpr double kPassed_m = 0.15;
// a replan is worth it when the plan moves by more than this
constexpr double kReplanTolerance_m = 0.03;
// back on the path: the pelvis within this of the path line
constexpr double kRejoined_m = 0.1;
// the safety stop looks this much wider than the robot's own half-width
constexpr double kSafetyWidthMargin_m = 0.05;
// Near an obstacle or a sharp corner of the path the robot walks at this
// stride (or its own, if shorter): the gait turns at most 15 degrees a step,
// so half the step halves the radius it turns on — the detour's sideways
// shift is made in half the distance, and a corner is overshot by half as much
// (a 90-degree corner 1 m before a wall is overshot into the wall at 0.6 m).
constexpr double kSlowStride_m = 0.3;
// Facing more than kSharpCorner_rad away from the gait's target (at the start,
// or after a detour's corner), the robot turns on short steps: its lasers look
// along its heading, not along the way it is turning to, so a wide turn sweeps
// its feet through ground no sensor has seen (generated rooms 105 and 438:
// a table leg inside a 45-degree turn at the start, met by the swing foot).
constexpr double kTurningStride_m = 0.1;
// the detour's shift counts as made once the pelvis is this close to it sideways
constexpr double kShifted_m = 0.05;
// following the path: off its line by more than this, the gait is steered back
// to a point on the line this far ahead (re-aimed when it has moved this much),
// until the pelvis is back within kBackOnPath_m
constexpr double kOffPath_m = 0.10;
constexpr double kCarrot_m = 0.6;
constexpr double kCarrotMove_m = 0.1;
constexpr double kBackOnPath_m = 0.03;
// a corner of the path turning more than this is walked slowly ...
constexpr double kSharpCorner_rad = 30.0 * kPi / 180.0;
// ... from this far before it (pelvis to corner) until this far past it
constexpr double kCornerSlowBefore_m = 1.0;
constexpr double kCornerSlowAfter_m = 0.3;
// The safety stop takes effect at the next double support: the swing foot
// still lands up to a step (half the stride) beyond the leading toe, so the
// stop looks at least that far ahead, and this much more.
constexpr double kSwingMargin_m = 0.05;
// A point farther than this behind the leading toe lies behind the robot, not
// in its way: about a foot behind it the trailing foot stands (a map's
// obstacle passed long ago, a stair's upper tread after the way down, once
// stopped the robot from 5 m behind)
constexpr double kBehindTheToe_m = 0.3;
// reading the map: the route is planned again this often (the map fills, people move) ...
constexpr double kReplanRoute_s = 0.5;
// ... and the gait given it when one of its waypoints moved by more than this
constexpr double kRouteMoved_m = 0.15;


Vec2 Left(const Vec2& u) { return {-u.y(), u.x()}; }

}  // namespace

void CircumventStrategy::Reset(const StrategySetup& setup) {
  sensors_.assign(setup.sensors.begin(), setup.sensors.end());
  path_m_ = setup.path_m;
  given_path_m_ = setup.path_m;
  given_target_ = 1;
  next_route_t_s_ = 0;
  no_route_ = false;
  stride_m_ = setup.stride_m;
  stride_now_m_ = setup.stride_m;
  stride_in_force_m_ = setup.stride_m;
  stride_changed_ = false;
  last_support_ = SupportLeg::kDouble;
  started_ = false;
  mode_ = Mode::kFollowing;
  points_.clear();
  cells_added_.clear();
  cluster_walk_ = ClusterWalk{};
  extent_.reset();
  detour_.clear();
  shift_m_ = 0;
  side_ = 0;
  tracking_ = false;
  path_target_ = 1;
  next_waypoint_ = 0;
  detour_waypoints_ = 0;
  passed_ = false;
}

CircumventStrategy::Cell CircumventStrategy::CellOf(const Vec3& p_W) const {
  return {static_cast<std::int64_t>(std::floor(p_W.x() / kCell_m)),
          static_cast<std::int64_t>(std::floor(p_W.y() / kCell_m))};
}

Vec2 CircumventStrategy::ToWorld(double s, double l) const {
  return segment_.origin + s * segment_.u + l * Left(segment_.u);
}

void CircumventStrategy::FindRaisedPoints(const Observation& observation) {
  raised_.clear();
  const RobotKnowledge& self = *observation.robot;
  if (config_.perception == Perception::kMap) {
    // the map's obstacles, their outlines every cell of ours (steps and holes are the legs' to plan)
    // each at the centre of its cell: an outline that grows as more is
    // mapped adds cells rather than moving the points of those it had
    if (observation.map != nullptr) {
      ForEachObstacleOutlinePoint(*observation.map, [&](const Vec3& p_W) {
        const Cell cell = CellOf(p_W);
        raised_.emplace_back((static_cast<double>(cell.first) + 0.5) * kCell_m,
                             (static_cast<double>(cell.second) + 0.5) * kCell_m, p_W.z());
      });
    }
    return;
  }
  for (std::size_t i = 0; i < observation.sensors.size() && i < sensors_.size(); ++i) {
    const SensorOutput& sensor = observation.sensors[i];
    // the points it reports above the floor, wherever in its cone they echoed
    ForEachRaisedEcho(sensor, sensors_[i], self.ground_z_m, config_.min_height_m,
                      [&](const Measurement& measurement) { raised_.push_back(measurement.p_W()); });
  }
}

void CircumventStrategy::KeepPoints(const Observation& observation) {
  FindRaisedPoints(observation);
  for (const Vec3& p_W : raised_) {
    const Cell cell = CellOf(p_W);
    const auto [kept, added] = points_.try_emplace(cell, p_W);
    if (added) {
      cells_added_.push_back(cell);
      continue;
    }
    // (the map's outlines come back every sample, in the same places)
    if (kept->second.head<2>() != p_W.head<2>()) ++cells_moved_;
    kept->second = p_W;
  }
}

std::optional<Vec3> CircumventStrategy::PointInTheWay(const Observation& observation, const Vec3& walking_W,
                                                       double look_ahead_m, double lateral_m) const {
  const RobotKnowledge& self = *observation.robot;
  const Vec3 lateral_W = Vec3::UnitZ().cross(walking_W);
  for (const Vec3& p_W : raised_) {
    // ahead of the leading toe, aside of the pelvis (the toe leads on one side)
    const double ahead_m = (p_W - self.p_W_front).dot(walking_W);
    const double aside_m = (p_W - self.X_WP.translation()).dot(lateral_W);
    if (ahead_m <= look_ahead_m && ahead_m >= -kBehindTheToe_m && std::abs(aside_m) <= lateral_m) return p_W;
  }
  return std::nullopt;
}

std::size_t CircumventStrategy::GaitTargetIndex(const std::vector<Vec2>& path, std::size_t first, const Vec2& p_WP) const {
  // the gait's own rule (gait/waypoint_rule.h) on the path as it was given: its first point is where the pelvis was
  return 1 + WaypointAhead(std::span<const Vec2>(path).subspan(1), first - 1, path[0], p_WP, stride_in_force_m_);
}

Vec2 CircumventStrategy::GaitTarget(const Vec2& p_WP) const {
  if (tracking_) return carrot_;
  if (mode_ == Mode::kDetouring) {
    // the detour's waypoints still ahead, as last given to the gait from where the pelvis was then
    std::vector<Vec2> given = Remaining();
    if (given.empty()) return p_WP;
    given.insert(given.begin(), detour_given_at_W_);
    return given[GaitTargetIndex(given, 1, p_WP)];
  }
  return path_m_.size() < 2 ? p_WP : path_m_[GaitTargetIndex(path_m_, path_target_, p_WP)];
}

void CircumventStrategy::TrackPath(const Vec2& p_WP, RobotCommands& robot) {
  // Following the path, the gait heads for the next waypoint, not along the
  // line to it: after overshooting a corner (it turns at most 15 degrees a
  // step) it would cut back to the far waypoint on a line of its own, out of
  // the corridor the path keeps clear. Off the line by more than kOffPath_m,
  // it is given a point on the line kCarrot_m ahead, then the rest of the path.
  if (path_m_.size() < 2) return;
  const std::size_t i = path_target_ = GaitTargetIndex(path_m_, path_target_, p_WP);
  const Vec2 a = path_m_[i - 1], b = path_m_[i];
  const double length_m = (b - a).norm();
  if (length_m < 1e-6) return;
  const Vec2 u = (b - a) / length_m;
  const double s = std::clamp((p_WP - a).dot(u), 0.0, length_m);
  const double off_m = (p_WP - (a + s * u)).norm();
  if (!tracking_ && off_m <= kOffPath_m) return;
  std::vector<Vec2> path;
  if (off_m <= kBackOnPath_m || length_m - s <= kCarrot_m) {
    if (!tracking_) return;
    tracking_ = false;  // back on the line, or near its end: the path itself
  } else {
    const Vec2 carrot = a + (s + kCarrot_m) * u;
    if (tracking_ && (carrot - carrot_).norm() < kCarrotMove_m) return;
    tracking_ = true;
    carrot_ = carrot;
    path.push_back(carrot);
  }
  path.insert(path.end(), path_m_.begin() + static_cast<std::ptrdiff_t>(i), path_m_.end());
  robot.SetPath(path);
}

Vec3 CircumventStrategy::WalkingDirection(const RobotKnowledge& self, const Vec2& p_WP) const {
  // the step under way turns toward the gait's target as the gait turns it
  // (gait/waypoint_rule.h); the pelvis lags the step
  const Vec2 target = GaitTarget(p_WP);
  if ((target - p_WP).norm() < 1e-6) return self.heading_W;
  const double yaw = self.yaw_rad + TurnTowardRad(p_WP, self.yaw_rad, target, 0.5 * stride_in_force_m_);
  return {std::cos(yaw), std::sin(yaw), 0.0};
}

std::optional<Vec3> CircumventStrategy::PointOnThePath(const Observation& observation) const {
  const RobotKnowledge& self = *observation.robot;
  const double clear_m = half_width_m_ + config_.margin_m;
  for (const Vec3& p_W : raised_) {
    const double ahead_m = (p_W - self.p_W_front).dot(self.heading_W);
    if (ahead_m < 0 || ahead_m > config_.detect_distance_m) continue;
    // nearer the path than the robot may pass: in the way (beyond the goal: not)
    if (DistanceToPath_m(p_W.head<2>()) <= clear_m) return p_W;
  }
  return std::nullopt;
}

double CircumventStrategy::DistanceToPath_m(const Vec2& p_W) const {
  double best_m = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < path_m_.size(); ++i) {
    const Vec2 a = path_m_[i], b = path_m_[i + 1];
    const double length_m = (b - a).norm();
    const double s = length_m > 1e-9 ? std::clamp((p_W - a).dot(b - a) / length_m, 0.0, length_m) : 0.0;
    best_m = std::min(best_m, (p_W - (a + (length_m > 1e-9 ? s / length_m : 0.0) * (b - a))).norm());
  }
  return best_m;
}

CircumventStrategy::Segment CircumventStrategy::SegmentNear(const Vec2& p_W) const {
  // the path segment whose line passes nearest the point (between its ends)
  Segment best;
  double best_distance_m = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < path_m_.size(); ++i) {
    const Vec2 a = path_m_[i], b = path_m_[i + 1];
    const double length_m = (b - a).norm();
    if (length_m < 1e-6) continue;
    const Vec2 u = (b - a) / length_m;
    const double s = std::clamp((p_W - a).dot(u), 0.0, length_m);
    const double distance_m = (p_W - (a + s * u)).norm();
    if (distance_m < best_distance_m) {
      best_distance_m = distance_m;
      best.origin = a;
      best.u = u;
      best.rest.assign(path_m_.begin() + static_cast<std::ptrdiff_t>(i + 1), path_m_.end());
    }
  }
  return best;
}

template <typename Visit>
void CircumventStrategy::ForEachLinkedCell(const Cell& cell, const Vec2& p_W, Visit visit) const {
  // the kept cells within reach, row by row (a row's cells are contiguous in
  // the ordered map: the scan never walks a whole stripe of the map), whose
  // points lie within kClusterLink_m of p_W; stops when visit returns false
  const auto reach = static_cast<std::int64_t>(std::ceil(kClusterLink_m / kCell_m));
  for (std::int64_t row = cell.first - reach; row <= cell.first + reach; ++row) {
    for (auto it = points_.lower_bound({row, cell.second - reach});
         it != points_.end() && it->first.first == row && it->first.second <= cell.second + reach; ++it) {
      if ((it->second.head<2>() - p_W).norm() > kClusterLink_m) continue;
      if (!visit(it->first)) return;
    }
  }
}

void CircumventStrategy::GrowCluster(ClusterWalk& walk, std::deque<Cell> queue) const {
  // breadth-first over the kept cells, linking those closer than kClusterLink_m
  const Vec2 left = Left(walk.u);
  while (!queue.empty()) {
    const Cell cell = queue.front();
    queue.pop_front();
    const auto point = points_.find(cell);
    if (point == points_.end()) continue;  // the seed, before a point falls in its cell
    const Vec2 d = point->second.head<2>() - walk.origin;
    walk.extent.s_min = std::min(walk.extent.s_min, d.dot(walk.u));
    walk.extent.s_max = std::max(walk.extent.s_max, d.dot(walk.u));
    walk.extent.l_min = std::min(walk.extent.l_min, d.dot(left));
    walk.extent.l_max = std::max(walk.extent.l_max, d.dot(left));
    ForEachLinkedCell(cell, point->second.head<2>(), [&](const Cell& linked) {
      if (walk.seen.insert(linked).second) queue.push_back(linked);
      return true;
    });
  }
}

CircumventStrategy::Extent CircumventStrategy::MeasureCluster(const Cell& seed, const Segment& segment) const {
  // The cluster is the seed's connected component among the kept cells
  // (linked closer than kClusterLink_m), whatever order it is walked in. A
  // walk of the same seed in the same frame is grown from the cells added
  // since, not walked again (a mapped wall is thousands of cells, and the
  // map's outlines grow every sample); a kept cell that moved walks it anew.
  ClusterWalk& walk = cluster_walk_;
  const bool same = walk.valid && walk.seed == seed && walk.origin == segment.origin && walk.u == segment.u &&
                    walk.moved == cells_moved_;
  if (!same) {
    walk = ClusterWalk{};
    walk.valid = true;
    walk.seed = seed;
    walk.origin = segment.origin;
    walk.u = segment.u;
    walk.moved = cells_moved_;
    walk.added = cells_added_.size();
    walk.seen = {seed};
    GrowCluster(walk, {seed});
    return walk.extent;
  }
  for (; walk.added < cells_added_.size(); ++walk.added) {
    const Cell cell = cells_added_[walk.added];
    if (cell == seed) {  // the seed's own point, come at last
      GrowCluster(walk, {seed});
      continue;
    }
    if (walk.seen.contains(cell)) continue;  // reached from another new cell already
    // linked to the walk: a reached cell within kClusterLink_m
    bool linked = false;
    ForEachLinkedCell(cell, points_.at(cell).head<2>(), [&](const Cell& near) {
      linked = walk.seen.contains(near);
      return !linked;
    });
    if (!linked) continue;
    walk.seen.insert(cell);
    GrowCluster(walk, {cell});
  }
  return walk.extent;
}

bool CircumventStrategy::PlanDetour(const Extent& extent, std::vector<Vec2>* waypoints, double* shift_m) const {
  // pass half-width + margin clear of the extent: on the side chosen first
  // (a detour that flips sides as more is seen would zigzag into the
  // obstacle), else on the side that needs the smaller shift
  const double clear_m = half_width_m_ + config_.margin_m;
  const double left_m = extent.l_max + clear_m;
  const double right_m = extent.l_min - clear_m;
  const bool fits_left = left_m <= config_.max_detour_m;
  const bool fits_right = -right_m <= config_.max_detour_m;
  if (side_ > 0 && fits_left) {
    *shift_m = left_m;
  } else if (side_ < 0 && fits_right) {
    *shift_m = right_m;
  } else {
    *shift_m = std::abs(left_m) <= std::abs(right_m) ? left_m : right_m;
    if (!fits_left && !fits_right) return false;
    *shift_m = !fits_right || (fits_left && std::abs(left_m) <= std::abs(right_m)) ? left_m : right_m;
  }

  // beside the near end, beside the far end (the far side unseen: assumed_depth_m behind), back on the path
  const double s_far = std::max(extent.s_max, extent.s_min + config_.assumed_depth_m);
  const double s_near = extent.s_min - clear_m;
  const double s_after = s_far + clear_m + kRunOut_m;
  double s_rejoin = s_after + config_.rejoin_m;
  waypoints->clear();
  waypoints->push_back(ToWorld(s_near, *shift_m));
  waypoints->push_back(ToWorld(s_after, *shift_m));
  // the rest of the path beyond the rejoining point (the goal at least)
  std::vector<Vec2> rest;
  for (std::size_t i = 0; i < segment_.rest.size(); ++i) {
    const double s = (segment_.rest[i] - segment_.origin).dot(segment_.u);
    if (i > 0 || s > s_rejoin) rest.push_back(segment_.rest[i]);
    else if (i == 0) s_rejoin = std::min(s_rejoin, s);  // the segment ends before: rejoin at its end
  }
  waypoints->push_back(ToWorld(s_rejoin, 0.0));
  waypoints->insert(waypoints->end(), rest.begin(), rest.end());
  static_assert(kDetourWaypoints == 3, "beside the near end, beside the far end, back on the path");
  return true;
}

bool CircumventStrategy::NearSharpCorner(const Vec2& p_WP) const {
  for (std::size_t i = 1; i + 1 < path_m_.size(); ++i) {
    const Vec2 in = path_m_[i] - path_m_[i - 1], out = path_m_[i + 1] - path_m_[i];
    if (in.norm() < 1e-6 || out.norm() < 1e-6) continue;
    const double turn_rad = std::acos(std::clamp(in.dot(out) / (in.norm() * out.norm()), -1.0, 1.0));
    if (turn_rad > kSharpCorner_rad && (path_m_[i] - p_WP).norm() < kCornerSlowBefore_m) return true;
  }
  return false;
}

void CircumventStrategy::Pace(const Vec2& p_WP, double yaw_rad, RobotCommands& robot, EventLog& events) {
  if (!(stride_m_ > 0)) return;  // the gait's stride is not known: leave it
  // slow while the detour's sideways shift is still to be made, or a sharp corner is near
  bool shifting = false;
  if (mode_ == Mode::kDetouring && !passed_) {
    const double l_WP = (p_WP - segment_.origin).dot(Left(segment_.u));
    shifting = std::abs(l_WP - shift_m_) > kShifted_m;
  }
  // (turning hard toward the gait's target counts as a corner: at the start, facing away from the path)
  const Vec2 to = GaitTarget(p_WP) - p_WP;
  const bool turning = to.norm() > 1e-6 &&
                       std::abs(std::remainder(std::atan2(to.y(), to.x()) - yaw_rad, 2 * kPi)) > kSharpCorner_rad;
  const bool slow = shifting || turning || NearSharpCorner(p_WP);
  const double stride_m = turning ? std::min(kTurningStride_m, stride_m_)
                          : slow  ? std::min(kSlowStride_m, stride_m_)
                                  : stride_m_;
  if (stride_m == stride_now_m_) return;
  robot.SetStride(stride_m);
  stride_now_m_ = stride_m;
  stride_changed_ = true;
  events.Log(slow ? "slowing_down" : "speeding_up",
             FormatNumbers(slow ? "an obstacle or a sharp corner ahead: stride %.2f m" : "the way is clear: stride %.2f m",
                           stride_m));
}

std::vector<Vec2> CircumventStrategy::Remaining() const {
  return {detour_.begin() + static_cast<std::ptrdiff_t>(std::min(next_waypoint_, detour_.size())), detour_.end()};
}

std::string CircumventStrategy::DescribeDetour() const {
  std::string text = std::string(shift_m_ > 0 ? "to the left" : "to the right") +
                     FormatNumbers(" of the path, %.2f m aside; obstacle s in [%.2f, %.2f] m,", std::abs(shift_m_),
                            extent_->s_min, extent_->s_max) +
                     FormatNumbers(" l in [%.2f, %.2f] m; via", extent_->l_min, extent_->l_max);
  for (std::size_t i = 0; i < detour_.size(); ++i) {
    text += FormatNumbers(i == 0 ? " (%.2f, %.2f)" : ", (%.2f, %.2f)", detour_[i].x(), detour_[i].y());
  }
  return text;
}

void CircumventStrategy::Decide(const Observation& observation, RobotCommands& robot, EventLog& events) {
  if (observation.robot == nullptr) return;
  const RobotKnowledge& self = *observation.robot;
  if (!started_) {
    // the path starts where the robot stands when it was given without its start
    started_ = true;
    half_width_m_ = self.half_width_m;
    const Vec2 p_start = self.X_WP.translation().head<2>();
    if (path_m_.empty() || (path_m_.front() - p_start).norm() > 0.05) path_m_.insert(path_m_.begin(), p_start);
    given_path_m_ = path_m_;
  }
  if (mode_ == Mode::kStopped) return;
  KeepPoints(observation);

  // whatever the plan, something right in front of the feet stops the robot
  const double own_width_m = half_width_m_ + kSafetyWidthMargin_m;
  // the stride commanded takes effect at the next heel strike: until then the longer one reaches
  // (a heel strike: into double support, or straight from one leg to the other)
  const bool heel_strike = self.support != last_support_ &&
                           (self.support == SupportLeg::kDouble || last_support_ != SupportLeg::kDouble);
  if (heel_strike && stride_changed_) {
    stride_changed_ = false;
    stride_in_force_m_ = stride_now_m_;
  }
  last_support_ = self.support;
  const double reach_stride_m = stride_changed_ ? std::max(stride_in_force_m_, stride_now_m_) : stride_in_force_m_;
  const double reach_m = reach_stride_m > 0 ? 0.5 * reach_stride_m + kSwingMargin_m : 0.0;
  const Vec3 walking_W = WalkingDirection(self, self.X_WP.translation().head<2>());
  // turning on short steps the feet move at most a step from where they are
  // before a stop takes effect: the stop looks that far (the swing's reach),
  // not stop_distance_m along a heading the robot is turning away from
  // (the short steps are Pace's turning steps only when the gait's own stride is longer)
  const bool turning_on_short_steps =
      reach_stride_m > 0 && reach_stride_m <= kTurningStride_m && stride_m_ > kTurningStride_m;
  const double look_ahead_m = turning_on_short_steps ? reach_m : std::max(config_.stop_distance_m, reach_m);
  const auto p_W_in_the_way = PointInTheWay(observation, walking_W, look_ahead_m, own_width_m);
  if (mode_ == Mode::kWaiting) {
    // reading the map, it plans a way round from where it stands, and the way
    // is the one toward the route's next waypoint (standing, it turns there on
    // short steps), not along its heading
    bool in_the_way = p_W_in_the_way.has_value();
    if (config_.perception == Perception::kMap && mode_before_waiting_ != Mode::kBlocked) {
      const Vec2 p_WP = self.X_WP.translation().head<2>();
      FollowRouteOnMap(observation, p_WP, robot, events);
      const Vec2 to = GaitTarget(p_WP) - p_WP;
      if (to.norm() > 1e-6)
        in_the_way = PointInTheWay(observation, Vec3(to.x(), to.y(), 0).normalized(), look_ahead_m, own_width_m)
                         .has_value();
    }
    if (way_clear_.StayedClear(!in_the_way, observation.t_s)) {
      robot.Resume();
      mode_ = mode_before_waiting_;
      events.Log("walking_on", FormatNumbers("the way ahead has been clear for %.1f s: walking on",
                                             kClearBeforeWalkingOn_s));
    }
    return;
  }
  if (p_W_in_the_way) {
    robot.Stop();
    const bool may_clear = config_.perception == Perception::kMap;
    mode_before_waiting_ = mode_;
    mode_ = may_clear ? Mode::kWaiting : Mode::kStopped;
    way_clear_.Restart();
    const double ahead_m = (*p_W_in_the_way - self.p_W_front).dot(walking_W);
    events.Log("blocked", may_clear ? FormatNumbers("a point at (%.2f, %.2f, %.2f) m, %.3f m ahead of the leading toe, "
                                                    "in the robot's way: stopping until the way is clear",
                                                    p_W_in_the_way->x(), p_W_in_the_way->y(), p_W_in_the_way->z(), ahead_m)
                                    : FormatNumbers("a point %.3f m ahead of the leading toe, in the robot's way: stopping",
                                                    ahead_m));
    return;
  }
  if (mode_ == Mode::kBlocked) return;

  const Vec2 p_WP = self.X_WP.translation().head<2>();
  if (config_.perception == Perception::kMap) FollowRouteOnMap(observation, p_WP, robot, events);
  else FollowOrDetour(observation, p_WP, robot, events);
  if (mode_ != Mode::kBlocked) Pace(p_WP, self.yaw_rad, robot, events);
}

void CircumventStrategy::FollowRouteOnMap(const Observation& observation, const Vec2& p_WP, RobotCommands& robot,
                                          EventLog& events) {
  if (observation.map != nullptr && given_path_m_.size() >= 2 && observation.t_s >= next_route_t_s_) {
    next_route_t_s_ = observation.t_s + kReplanRoute_s;
    given_target_ = GaitTargetIndex(given_path_m_, given_target_, p_WP);
    const Vec2 target = given_path_m_[given_target_];
    // the obstacles within detect_distance_m (pelvis to cell, with the toe's lead) are avoided
    const double reach_m = config_.detect_distance_m + (observation.robot->p_W_front.head<2>() - p_WP).norm();
    auto route = RouteAroundObstacles(*observation.map, p_WP, target, half_width_m_ + config_.margin_m, reach_m);
    if (!route)
      route = RouteAroundObstacles(*observation.map, p_WP, target, half_width_m_ + kSafetyWidthMargin_m, reach_m);
    if (!route) {
      if (!no_route_)
        events.Log("no_way_around", FormatNumbers("the map shows no way to (%.2f, %.2f) m: walking on to the safety stop",
                                                  target.x(), target.y()));
      no_route_ = true;
    } else {
      no_route_ = false;
      route->insert(route->end(), given_path_m_.begin() + static_cast<std::ptrdiff_t>(given_target_) + 1,
                    given_path_m_.end());
      // a new route when one of its waypoints moved (the path after p_WP is the route last given)
      bool moved = route->size() + 1 != path_m_.size();
      for (std::size_t i = 0; !moved && i < route->size(); ++i) moved = ((*route)[i] - path_m_[i + 1]).norm() > kRouteMoved_m;
      if (moved) {
        path_m_.assign(1, p_WP);
        path_m_.insert(path_m_.end(), route->begin(), route->end());
        path_target_ = 1;
        tracking_ = false;
        robot.SetPath(*route);
        std::string via;
        for (const Vec2& p : *route) via += FormatNumbers(via.empty() ? "(%.2f, %.2f)" : ", (%.2f, %.2f)", p.x(), p.y());
        events.Log("route_planned", "around every obstacle mapped, via " + via);
      }
    }
  }
  TrackPath(p_WP, robot);
}

void CircumventStrategy::FollowOrDetour(const Observation& observation, const Vec2& p_WP, RobotCommands& robot,
                                EventLog& events) {
  const RobotKnowledge& self = *observation.robot;
  if (mode_ == Mode::kFollowing) {
    const auto p_W = PointOnThePath(observation);
    if (!p_W) {
      TrackPath(p_WP, robot);
      return;
    }
    tracking_ = false;
    seed_ = CellOf(*p_W);
    segment_ = SegmentNear(p_W->head<2>());
    extent_ = MeasureCluster(seed_, segment_);
    events.Log("obstacle_seen",
               FormatNumbers("a point at (%.2f, %.2f, %.2f) m, %.2f m ahead of the leading toe", p_W->x(),
                                       p_W->y(), p_W->z(), (*p_W - self.p_W_front).dot(self.heading_W)));
    if (!PlanDetour(*extent_, &detour_, &shift_m_)) {
      mode_ = Mode::kBlocked;
      detour_.clear();
      events.Log("no_way_around",
                 FormatNumbers("a detour would shift %.2f m, more than max_detour_m = %.2f m", shift_m_,
                                         config_.max_detour_m));
      return;
    }
    side_ = shift_m_ > 0 ? 1 : -1;
    next_waypoint_ = 0;
    detour_waypoints_ = kDetourWaypoints;
    robot.SetPath(detour_);
    detour_given_at_W_ = p_WP;
    mode_ = Mode::kDetouring;
    passed_ = false;
    events.Log("detour_planned", DescribeDetour());
    return;
  }

  // detouring: more of the obstacle seen moves the plan
  if (!passed_) {
    const Extent extent = MeasureCluster(seed_, segment_);
    std::vector<Vec2> detour;
    double shift_m = 0;
    if (!PlanDetour(extent, &detour, &shift_m)) {
      mode_ = Mode::kBlocked;
      events.Log("no_way_around",
                 FormatNumbers("the obstacle grew: a detour would shift %.2f m, more than %.2f m", shift_m,
                                         config_.max_detour_m));
      return;
    }
    bool moved = detour.size() != detour_.size();
    for (std::size_t i = 0; !moved && i < detour.size(); ++i) moved = (detour[i] - detour_[i]).norm() > kReplanTolerance_m;
    extent_ = extent;
    if (moved) {
      detour_ = detour;
      shift_m_ = shift_m;
      side_ = shift_m_ > 0 ? 1 : -1;
      robot.SetPath(Remaining());
      detour_given_at_W_ = p_WP;
      events.Log("detour_replanned", "more of the obstacle seen: " + DescribeDetour());
    }
  }
  const Vec2 d = p_WP - segment_.origin;
  const double s_WP = d.dot(segment_.u);
  // the gait is given only the waypoints still ahead
  const std::size_t before = next_waypoint_;
  while (next_waypoint_ < detour_waypoints_ &&
         (detour_[next_waypoint_] - segment_.origin).dot(segment_.u) - s_WP < kPassed_m) {
    ++next_waypoint_;
  }
  if (next_waypoint_ != before) {
    robot.SetPath(Remaining());
    detour_given_at_W_ = p_WP;
  }
  const double s_far = std::max(extent_->s_max, extent_->s_min + config_.assumed_depth_m);
  if (!passed_ && s_WP > s_far + half_width_m_ + config_.margin_m) {
    passed_ = true;
    events.Log("obstacle_passed", FormatNumbers("pelvis %.2f m past the obstacle's far end", s_WP - s_far));
  }
  if (passed_ && next_waypoint_ >= detour_waypoints_ && std::abs(d.dot(Left(segment_.u))) < kRejoined_m) {
    mode_ = Mode::kFollowing;
    events.Log("rejoined", FormatNumbers("back on the path at (%.2f, %.2f) m", p_WP.x(), p_WP.y()));
  }
}

}  // namespace proxsim
