#include "sim/truth_map_feed.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "sim/truth_field.h"

namespace proxsim {

namespace {

// the height variance of a true column: exact, but not zero (the map's fusion divides by it)
constexpr double kTrueColumnVariance_m2 = 1e-8;

}  // namespace

TruthMapFeed::TruthMapFeed(double reach_m, double resolution_m) : reach_m_(reach_m), resolution_m_(resolution_m) {}

void TruthMapFeed::Reset() {
  next_feed_t_s_ = 0;
  cast_.clear();
  moving_before_.clear();
  reach_before_W_.reset();
}

void TruthMapFeed::AddDisc(const Vec2& p_W, double radius_m, const Vec2& p_W_pelvis, const Vec2& heading_W) {
  const double r = resolution_m_;
  const auto lo = [r](double v) { return static_cast<std::int32_t>(std::floor(v / r)); };
  for (std::int32_t iy = lo(p_W.y() - radius_m); iy <= lo(p_W.y() + radius_m); ++iy) {
    for (std::int32_t ix = lo(p_W.x() - radius_m); ix <= lo(p_W.x() + radius_m); ++ix) {
      const Vec2 centre((ix + 0.5) * r, (iy + 0.5) * r);
      if ((centre - p_W).squaredNorm() > radius_m * radius_m) continue;
      // within reach, or cast before (what a person leaves behind is cleared even beyond it)
      const std::int64_t key = Key(ix, iy);
      const Vec2 d = centre - p_W_pelvis;
      const bool in_reach = d.squaredNorm() <= reach_m_ * reach_m_ && d.dot(heading_W) >= -kTruthBehind_m;
      if (!in_reach && !cast_.contains(key)) continue;
      if (queued_.insert(key).second) due_xy_W_.push_back(centre);
    }
  }
}

std::pair<std::int32_t, std::int32_t> TruthMapFeed::ReachInRow(std::int32_t iy, const Vec2& p_W,
                                                               const Vec2& heading_W) const {
  const double r = resolution_m_;
  const double dy = (iy + 0.5) * r - p_W.y();
  if (std::abs(dy) > reach_m_) return {1, 0};
  // the disc's chord, then the half-plane (x − px)·hx + dy·hy >= −behind
  const double half_chord = std::sqrt(reach_m_ * reach_m_ - dy * dy);
  double lo = p_W.x() - half_chord, hi = p_W.x() + half_chord;
  const double hx = heading_W.x(), rest = -kTruthBehind_m - dy * heading_W.y();
  if (std::abs(hx) < 1e-12) {
    if (rest > 0) return {1, 0};
  } else if (hx > 0) {
    lo = std::max(lo, p_W.x() + rest / hx);
  } else {
    hi = std::min(hi, p_W.x() + rest / hx);
  }
  if (lo > hi) return {1, 0};
  // the cells whose centres (ix + 0.5)·r lie in [lo, hi]
  return {static_cast<std::int32_t>(std::ceil(lo / r - 0.5)), static_cast<std::int32_t>(std::floor(hi / r - 0.5))};
}

void TruthMapFeed::AddReach(const Vec2& p_W, const Vec2& heading_W) {
  const double r = resolution_m_;
  const auto add = [&](std::int32_t ix, std::int32_t iy) {
    const std::int64_t key = Key(ix, iy);
    if (cast_.insert(key).second && queued_.insert(key).second) due_xy_W_.emplace_back((ix + 0.5) * r, (iy + 0.5) * r);
  };
  const auto lo = [r](double v) { return static_cast<std::int32_t>(std::floor(v / r)); };
  for (std::int32_t iy = lo(p_W.y() - reach_m_) - 1; iy <= lo(p_W.y() + reach_m_) + 1; ++iy) {
    const auto [first, last] = ReachInRow(iy, p_W, heading_W);
    if (first > last) continue;
    // (the reach at the last feed was cast whole: only the columns it did not hold are looked up)
    std::int32_t before_first = 1, before_last = 0;
    if (reach_before_W_) std::tie(before_first, before_last) = ReachInRow(iy, reach_before_W_->first, reach_before_W_->second);
    if (before_first > before_last) {
      for (std::int32_t ix = first; ix <= last; ++ix) add(ix, iy);
      continue;
    }
    for (std::int32_t ix = first; ix <= std::min(last, before_first - 1); ++ix) add(ix, iy);
    for (std::int32_t ix = std::max(first, before_last + 1); ix <= last; ++ix) add(ix, iy);
  }
  reach_before_W_ = {p_W, heading_W};
}

const std::vector<RayEvidence>& TruthMapFeed::Columns(const World& world, const Vec2& p_W_pelvis,
                                                      const Vec2& heading_W, double ceiling_z_m, double t_s) {
  columns_.clear();
  if (t_s + 1e-9 < next_feed_t_s_) return columns_;
  next_feed_t_s_ = t_s + 1.0 / kTruthFeedRate_hz;
  queued_.clear();
  due_xy_W_.clear();
  // moving things, where they were and where they are: cast again (a cell
  // also within reach for the first time is then marked cast below)
  const std::vector<std::pair<Vec2, double>> moving = world.MovingFootprints_W();
  for (const auto& [p_W, radius_m] : moving_before_) AddDisc(p_W, radius_m + resolution_m_, p_W_pelvis, heading_W);
  for (const auto& [p_W, radius_m] : moving) AddDisc(p_W, radius_m + resolution_m_, p_W_pelvis, heading_W);
  moving_before_ = moving;
  AddReach(p_W_pelvis, heading_W);
  if (due_xy_W_.empty()) return columns_;

  const std::vector<float> heights = TrueHeightsAt(world.caster(), due_xy_W_, ceiling_z_m, true);
  columns_.reserve(due_xy_W_.size());
  for (std::size_t i = 0; i < due_xy_W_.size(); ++i) {
    // nothing below (beyond a course's edge, in a gap): left unknown — a void
    // column would make every cell beside a course one vast hole to classify
    // again at every feed, and no built-in strategy walks around a hole (the
    // legs plan over gaps on the true ground)
    if (std::isnan(heights[i])) continue;
    RayEvidence column;
    column.p_WS = Vec3(due_xy_W_[i].x(), due_xy_W_[i].y(), ceiling_z_m);
    column.dir_W = -Vec3::UnitZ();
    column.bounds_height = true;
    column.proves_empty = true;
    column.detected = true;
    column.d_m = std::max(0.0, ceiling_z_m - heights[i]);
    column.variance_z_m2 = kTrueColumnVariance_m2;
    column.free_end_m = column.d_m;
    columns_.push_back(column);
  }
  return columns_;
}

}  // namespace proxsim
