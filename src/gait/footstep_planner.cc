#include "gait/footstep_planner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace proxsim {

namespace {

// Steps of look-ahead: a foothold is chosen, if it can be, from which this
// many more steps find footholds.
constexpr int kLookAheadSteps = 2;
// How far inside a later foothold's bounds the look-ahead aims, m.
constexpr double kLookAheadSlack_m = 0.005;

// The heels a segment holds, within [s_min, s_max]: the sole on it, clear of
// its edges by the margin.
struct Interval {
  double lo_m, hi_m;
  double z_m;
  std::size_t segment;
};

std::vector<Interval> Footholds(const TerrainProfile& profile, double z_from_m, double s_min_m, double s_max_m,
                                const FootholdLimits& limits) {
  std::vector<Interval> found;
  const auto& segments = profile.segments();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const GroundSegment& g = segments[i];
    if (!g.walkable() || std::abs(g.z_m - z_from_m) > limits.max_rise_m) continue;
    const double lo = std::max(g.s_begin_m + limits.margin_m, s_min_m);
    const double hi = std::min(g.s_end_m - limits.margin_m - limits.sole_length_m, s_max_m);
    if (lo <= hi) found.push_back({lo, hi, g.z_m, i});
  }
  return found;
}

// The point of `intervals` nearest s (the shorter step on a tie); false when there is none.
bool Nearest(const std::vector<Interval>& intervals, double s_m, Interval* best, double* at_m) {
  bool any = false;
  for (const Interval& i : intervals) {
    const double at = std::clamp(s_m, i.lo_m, i.hi_m);
    if (!any || std::abs(at - s_m) < std::abs(*at_m - s_m) || (std::abs(at - s_m) == std::abs(*at_m - s_m) && at < *at_m)) {
      *best = i;
      *at_m = at;
      any = true;
    }
  }
  return any;
}

// The heels of `from` from which one step reaches a heel of `to`: a later
// one within [min_step, max_step] ahead and max_rise_m up or down, kept
// kLookAheadSlack_m inside (profiles made at different steps locate an edge
// to within kEdgeResolution_m each).
std::vector<Interval> Onward(const std::vector<Interval>& from, const std::vector<Interval>& to,
                             const FootholdLimits& limits) {
  std::vector<Interval> out;
  for (const Interval& a : from) {
    for (const Interval& b : to) {
      if (std::abs(a.z_m - b.z_m) > limits.max_rise_m) continue;
      const double lo = std::max(a.lo_m, b.lo_m + kLookAheadSlack_m - limits.max_step_m);
      const double hi = std::min(a.hi_m, b.hi_m - kLookAheadSlack_m - limits.min_step_m);
      if (lo <= hi) out.push_back({lo, hi, a.z_m, a.segment});
    }
  }
  // overlapping pieces of one segment as one
  std::sort(out.begin(), out.end(), [](const Interval& x, const Interval& y) {
    return x.segment != y.segment ? x.segment < y.segment : x.lo_m < y.lo_m;
  });
  std::vector<Interval> merged;
  for (const Interval& i : out) {
    if (!merged.empty() && merged.back().segment == i.segment && i.lo_m <= merged.back().hi_m)
      merged.back().hi_m = std::max(merged.back().hi_m, i.hi_m);
    else
      merged.push_back(i);
  }
  return merged;
}

}  // namespace

namespace {

// Why no foothold lies within reach: the first thing ahead of the stance toe
// that the legs cannot take.
std::string Reason(const TerrainProfile& profile, double s_stance_m, double z_stance_m, const FootholdLimits& limits) {
  const auto& segments = profile.segments();
  const double s_toe = s_stance_m + limits.sole_length_m;
  const double s_reach = s_stance_m + limits.max_step_m + limits.sole_length_m;
  char text[320];
  for (std::size_t i = profile.SegmentAt(s_toe); i < segments.size() && segments[i].s_begin_m < s_reach; ++i) {
    const GroundSegment& g = segments[i];
    const Vec3 at = profile.PointW(std::max(g.s_begin_m, s_toe), std::isfinite(g.z_m) ? g.z_m : z_stance_m);
    const double ahead = std::max(0.0, g.s_begin_m - s_toe);
    if (g.z_m > z_stance_m + limits.max_rise_m) {
      if (std::isinf(g.z_m)) {
        std::snprintf(text, sizeof text, "an object stands %.2f m ahead of the stance toe, at (%.2f, %.2f): no ground "
                      "to step on", ahead, at.x(), at.y());
      } else {
        std::snprintf(text, sizeof text, "a step up of %.2f m, %.2f m ahead of the stance toe at (%.2f, %.2f), is "
                      "higher than gait.max_step_m = %.2f m", g.z_m - z_stance_m, ahead, at.x(), at.y(),
                      limits.max_rise_m);
      }
      return text;
    }
    if (g.z_m < z_stance_m - limits.max_rise_m) {
      // a gap: lower ground until a level the legs can stand on again
      std::size_t j = i;
      while (j < segments.size() && !(segments[j].walkable() && std::abs(segments[j].z_m - z_stance_m) <= limits.max_rise_m))
        ++j;
      const Vec3 near = profile.PointW(g.s_begin_m, z_stance_m);
      if (j == segments.size()) {
        if (std::isinf(g.z_m)) {
          std::snprintf(text, sizeof text, "the ground ends %.2f m ahead of the stance toe, at (%.2f, %.2f): nothing "
                        "below within %.1f m", ahead, near.x(), near.y(), profile.line().depth_m);
        } else {
          std::snprintf(text, sizeof text, "a step down of %.2f m, %.2f m ahead of the stance toe at (%.2f, %.2f), is "
                        "deeper than gait.max_step_m = %.2f m", z_stance_m - g.z_m, ahead, near.x(), near.y(),
                        limits.max_rise_m);
        }
        return text;
      }
      const double gap = segments[j].s_begin_m - g.s_begin_m;
      const Vec3 far = profile.PointW(segments[j].s_begin_m, z_stance_m);
      const double needed = segments[j].s_begin_m + limits.margin_m - s_stance_m;
      std::snprintf(text, sizeof text, "a gap of %.2f m, from (%.2f, %.2f) to (%.2f, %.2f), %s; stepping over it takes "
                    "a step of %.2f m heel to heel, longer than a stride (%.2f m)",
                    gap, near.x(), near.y(), far.x(), far.y(),
                    std::isinf(g.z_m) ? "with no ground below" : "deeper than gait.max_step_m", needed,
                    limits.max_step_m);
      return text;
    }
  }
  return "no level ground a sole fits on within a stride ahead (a slope, or treads shorter than the sole)";
}

}  // namespace

std::vector<Foothold> PlanFootholds(const TerrainProfile& profile, double s_stance_m, double z_stance_m,
                                   double s_nominal_m, const FootholdLimits& limits, double spacing_m,
                                   std::size_t count) {
  const double s_min = s_stance_m + limits.min_step_m, s_max = s_stance_m + limits.max_step_m;
  const std::vector<Interval> now = Footholds(profile, z_stance_m, s_min, s_max, limits);
  if (now.empty()) return {Foothold{.reason = Reason(profile, s_stance_m, z_stance_m, limits)}};
  // onward[k]: the heels from which k more steps find footholds, built
  // backwards from every foothold of the profile one step of reach at a time
  constexpr double kAny = std::numeric_limits<double>::infinity();
  FootholdLimits any_height = limits;
  any_height.max_rise_m = kAny;
  const std::vector<Interval> all = Footholds(profile, z_stance_m, -kAny, kAny, any_height);
  std::vector<std::vector<Interval>> onward{all};
  for (int k = 1; k <= kLookAheadSteps; ++k) onward.push_back(Onward(all, onward.back(), limits));
  // the reachable heels with k steps ahead, k from the most to none
  std::vector<std::vector<Interval>> levels;
  for (int k = kLookAheadSteps; k >= 1; --k) {
    std::vector<Interval> reachable;
    for (const Interval& i : onward[k]) {
      const double lo = std::max(i.lo_m, s_min), hi = std::min(i.hi_m, s_max);
      if (lo <= hi && std::abs(i.z_m - z_stance_m) <= limits.max_rise_m) reachable.push_back({lo, hi, i.z_m, i.segment});
    }
    levels.push_back(std::move(reachable));
  }
  levels.push_back(now);
  // the first: the heel nearest the curves' with the most steps ahead
  std::vector<Foothold> choices;
  const auto taken = [&](double s_m) {
    for (const Foothold& f : choices)
      if (std::abs(f.s_heel_m - s_m) < 0.5 * spacing_m) return true;
    return false;
  };
  for (const std::vector<Interval>& level : levels) {
    Interval best{};
    double at = 0;
    if (!Nearest(level, s_nominal_m, &best, &at)) continue;
    choices.push_back(Foothold{.found = true, .s_heel_m = at, .z_m = best.z_m, .segment = best.segment, .reason = {}});
    break;
  }
  if (!(spacing_m > 0)) return choices;
  // then the others, the most steps ahead first, each level's nearest the
  // curves' first: every interval's nearest heel, and heels spacing_m apart
  // from it to either end
  for (const std::vector<Interval>& level : levels) {
    if (choices.size() >= count) break;
    std::vector<Foothold> more;
    for (const Interval& i : level) {
      const double near = std::clamp(s_nominal_m, i.lo_m, i.hi_m);
      const auto add = [&](double s_m) {
        more.push_back(Foothold{.found = true, .s_heel_m = s_m, .z_m = i.z_m, .segment = i.segment, .reason = {}});
      };
      add(near);
      for (double s = near - spacing_m; s > i.lo_m; s -= spacing_m) add(s);
      for (double s = near + spacing_m; s < i.hi_m; s += spacing_m) add(s);
      if (i.lo_m < near) add(i.lo_m);
      if (i.hi_m > near) add(i.hi_m);
    }
    std::stable_sort(more.begin(), more.end(), [&](const Foothold& a, const Foothold& b) {
      return std::abs(a.s_heel_m - s_nominal_m) < std::abs(b.s_heel_m - s_nominal_m);
    });
    for (const Foothold& f : more) {
      if (choices.size() >= count) break;
      if (!taken(f.s_heel_m)) choices.push_back(f);
    }
  }
  return choices;
}

Foothold PlanFoothold(const TerrainProfile& profile, double s_stance_m, double z_stance_m, double s_nominal_m,
                      const FootholdLimits& limits) {
  return PlanFootholds(profile, s_stance_m, z_stance_m, s_nominal_m, limits, 0.0, 1).front();
}

}  // namespace proxsim
