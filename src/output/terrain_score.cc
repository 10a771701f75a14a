#include "output/terrain_score.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "sim/truth_field.h"

namespace proxsim {

namespace {

// Grounds closer than this are one level.
constexpr double kLevelStep_m = 0.005;

std::uint64_t Key(CellIndex c) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.ix)) << 32) | static_cast<std::uint32_t>(c.iy);
}

nlohmann::json NumberOrNull(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

nlohmann::json Ratio(std::size_t numerator, std::size_t denominator) {
  return denominator > 0 ? nlohmann::json(static_cast<double>(numerator) / static_cast<double>(denominator))
                         : nlohmann::json(nullptr);
}

// Whether a map hazard's box (grown by a cell) holds one of the true hazard's cells.
bool Overlaps(const Hazard& map_hazard, const TrueHazard& truth) {
  CellBox box = map_hazard.cells;
  box.ix_min -= 1, box.iy_min -= 1, box.ix_max += 1, box.iy_max += 1;
  if (!box.Overlaps(truth.hazard.cells)) return false;
  return std::any_of(truth.cells.begin(), truth.cells.end(), [&](CellIndex c) { return box.Contains(c); });
}

// The track point at each of the times (the last one at or before it; the
// first one for a time before the track starts; `last` without a track), in
// one pass over the track, whose times never decrease.
std::vector<TrackPoint> PointsAt(const TrackReader& track, const TrackPoint& last, const std::vector<double>& times_s) {
  if (times_s.empty()) return {};
  std::vector<std::size_t> order(times_s.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  // by time, NaN last (no point comes after it: it gets the track's last point)
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return times_s[a] < times_s[b] || (!std::isnan(times_s[a]) && std::isnan(times_s[b]));
  });
  std::vector<TrackPoint> points(times_s.size(), last);
  std::size_t next = 0;  // in `order`: the first time not yet placed
  std::optional<TrackPoint> previous;
  track.ForEachTrackPoint([&](const TrackPoint& point) {
    for (; next < order.size() && times_s[order[next]] < point.t_s; ++next) points[order[next]] = previous.value_or(point);
    previous = point;
  });
  for (; next < order.size(); ++next) points[order[next]] = previous.value_or(last);
  return points;
}

// For each hazard, the ground the robot stood on when it came nearest to it
// (`last`'s without a track), in one pass over the track.
std::vector<double> NearestGrounds(const TrackReader& track, const TrackPoint& last, const std::vector<Hazard>& hazards) {
  std::vector<double> nearest_m(hazards.size(), std::numeric_limits<double>::infinity());
  std::vector<double> grounds_m(hazards.size(), last.ground_z_m);
  track.ForEachTrackPoint([&](const TrackPoint& point) {
    for (std::size_t k = 0; k < hazards.size(); ++k) {
      const double d = hazards[k].DistanceTo(point.p_W_pelvis);
      if (d < nearest_m[k]) nearest_m[k] = d, grounds_m[k] = point.ground_z_m;
    }
  });
  return grounds_m;
}

}  // namespace

TerrainScorer::TerrainScorer(const TerrainMap& map, const TrackReader& track, std::vector<Hazard> hazards,
                             double truth_ceiling_z_m, const Corridor& corridor)
    : map_(map), track_(track), hazards_(std::move(hazards)), truth_ceiling_z_m_(truth_ceiling_z_m), corridor_(corridor) {
  track.ForEachTrackPoint([&](const TrackPoint& point) {
    const bool known = std::any_of(levels_m_.begin(), levels_m_.end(),
                                   [&](double level) { return std::abs(level - point.ground_z_m) < kLevelStep_m; });
    if (!known) levels_m_.push_back(point.ground_z_m);
  });
  if (levels_m_.empty()) levels_m_.push_back(map.last_position().ground_z_m);
}

void TerrainScorer::AddRow(std::int32_t iy, std::int32_t ix_min, std::span<const TerrainCell* const> cells,
                           std::span<const float> truth_m, std::span<const float> now_m) {
  const TerrainMapConfig& config = map_.config();
  scores_ghosts_ = scores_ghosts_ || !now_m.empty();
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const CellIndex c{ix_min + static_cast<std::int32_t>(k), iy};
    const TerrainCell* cell = cells[k];
    const float truth = truth_m[k];
    const bool measured = cell != nullptr && cell->has_elevation();
    // the elevation's error where both are known
    if (measured) ++cells_measured_;
    if (measured && !std::isnan(truth)) {
      const double error_m = static_cast<double>(cell->elevation_m) - truth;
      abs_errors_m_.Add(static_cast<float>(std::abs(error_m)));
      sum_squared_error_m2_ += error_m * error_m;
    }
    // a ghost: raised above the still scene, and above whatever stands there now
    if (measured && !now_m.empty()) {
      const double above_still_m = std::isnan(truth) ? std::numeric_limits<double>::infinity() : cell->elevation_m - truth;
      const double above_now_m = std::isnan(now_m[k]) ? std::numeric_limits<double>::infinity() : cell->elevation_m - now_m[k];
      if (above_still_m > config.obstacle_min_m && above_now_m > config.obstacle_min_m) ++ghost_cells_;
    }
    // free space's bound, where there is a surface it should stay above
    if (cell != nullptr && std::isfinite(cell->upper_bound_m) && !std::isnan(truth)) {
      ++cells_bounded_;
      if (cell->upper_bound_m < truth - config.drop_min_m) ++bounds_below_truth_;
    }
    if (corridor_.Contains(c)) {
      ++corridor_cells_;
      if (measured) ++corridor_measured_;
      if (measured || (cell != nullptr && std::isfinite(cell->upper_bound_m))) ++corridor_bounded_;
    }
    // a column with no surface is as deep as the truth looked
    const CellSurface surface = std::isnan(truth)
                                    ? CellSurface{std::numeric_limits<float>::quiet_NaN(),
                                                  static_cast<float>(truth_ceiling_z_m_ - kTruthDepth_m)}
                                    : CellSurface{truth, std::numeric_limits<float>::quiet_NaN()};
    for (double level : levels_m_) {
      if (LabelCell(surface, level, config) != CellLabel::kNone) {
        off_ground_.emplace(Key(c), surface);
        break;
      }
    }
  }
}

const std::vector<TrueHazard>& TerrainScorer::FindTrueHazards() {
  if (matched_) return true_hazards_;
  matched_ = true;
  const TerrainMapConfig& config = map_.config();
  const double r = map_.grid().resolution_m();
  std::vector<CellIndex> seeds;
  for (const auto& [key, surface] : off_ground_) {
    seeds.push_back({static_cast<std::int32_t>(key >> 32), static_cast<std::int32_t>(key & 0xFFFFFFFFu)});
  }
  std::sort(seeds.begin(), seeds.end(), [](CellIndex a, CellIndex b) { return a.iy != b.iy ? a.iy < b.iy : a.ix < b.ix; });
  const auto surface_at = [this](CellIndex c) {
    const auto it = off_ground_.find(Key(c));
    return it == off_ground_.end() ? CellSurface{} : it->second;
  };
  for (double level : levels_m_) {
    const auto label_at = [&](CellIndex c) {
      const auto it = off_ground_.find(Key(c));
      return it == off_ground_.end() ? CellLabel::kNone : LabelCell(it->second, level, config);
    };
    std::vector<std::vector<CellIndex>> clusters;
    const std::vector<Hazard> found = FindHazards(seeds, label_at, surface_at, level, r, config, &clusters);
    // on several levels, each cluster is the one relative to the ground the robot stood on when nearest to it
    const std::vector<double> grounds_m =
        levels_m_.size() > 1 ? NearestGrounds(track_, map_.last_position(), found) : std::vector<double>{};
    for (std::size_t k = 0; k < found.size(); ++k) {
      if (!grounds_m.empty() && std::abs(grounds_m[k] - level) >= kLevelStep_m) continue;
      TrueHazard truth;
      truth.hazard = found[k];
      truth.cells = std::move(clusters[k]);
      truth.in_corridor = std::any_of(truth.cells.begin(), truth.cells.end(), [&](CellIndex c) { return corridor_.Contains(c); });
      true_hazards_.push_back(std::move(truth));
    }
  }
  // the map's first detection over each true hazard ...
  for (TrueHazard& truth : true_hazards_) {
    for (const Hazard& mapped : hazards_) {
      if (!Overlaps(mapped, truth)) continue;
      if (!truth.detected || mapped.first_detection_t_s < truth.hazard.first_detection_t_s) {
        truth.detected = true;
        truth.found_as = mapped.hazard_class;
        truth.hazard.first_detection_t_s = mapped.first_detection_t_s;
      }
    }
  }
  // ... and the leading toe's distance to it then
  std::vector<double> detected_t_s;
  for (const TrueHazard& truth : true_hazards_) {
    if (truth.detected) detected_t_s.push_back(truth.hazard.first_detection_t_s);
  }
  const std::vector<TrackPoint> at_detection = PointsAt(track_, map_.last_position(), detected_t_s);
  std::size_t detected = 0;
  for (TrueHazard& truth : true_hazards_) {
    if (!truth.detected) continue;
    const Vec2 toe = at_detection[detected++].p_W_front;
    double lead_m = std::numeric_limits<double>::infinity();
    for (const CellIndex& c : truth.cells) {
      const Vec2 lo(c.ix * r, c.iy * r), hi = lo + Vec2(r, r);
      const double dx = std::max({lo.x() - toe.x(), 0.0, toe.x() - hi.x()});
      const double dy = std::max({lo.y() - toe.y(), 0.0, toe.y() - hi.y()});
      lead_m = std::min(lead_m, std::hypot(dx, dy));
    }
    truth.lead_distance_m = lead_m;
    truth.hazard.distance_at_detection_m = lead_m;
  }
  return true_hazards_;
}

nlohmann::json TerrainScorer::Json() {
  const std::vector<TrueHazard>& truths = FindTrueHazards();
  const std::size_t n = abs_errors_m_.count();
  nlohmann::json error = {{"cells", n}, {"rmse_m", nullptr}, {"p95_m", nullptr}, {"max_m", nullptr}};
  if (n > 0) {
    error["rmse_m"] = std::sqrt(sum_squared_error_m2_ / static_cast<double>(n));
    error["p95_m"] = abs_errors_m_.Percentile(0.95);  // numpy's default: linear between the order statistics around it
    error["max_m"] = abs_errors_m_.max();
  }

  // per class: the map's hazards that are right, the true ones (in the corridor) that were found
  nlohmann::json classes = nlohmann::json::object();
  for (int k = 0; k < kHazardClassCount; ++k) {
    const auto hazard_class = static_cast<HazardClass>(k);
    std::size_t mapped = 0, mapped_right = 0, truths_in_corridor = 0, truths_found = 0;
    for (const Hazard& hazard : hazards_) {
      if (hazard.hazard_class != hazard_class) continue;
      ++mapped;
      mapped_right += std::any_of(truths.begin(), truths.end(), [&](const TrueHazard& truth) {
        return truth.hazard.hazard_class == hazard_class && Overlaps(hazard, truth);
      });
    }
    for (const TrueHazard& truth : truths) {
      if (truth.hazard.hazard_class != hazard_class || !truth.in_corridor) continue;
      ++truths_in_corridor;
      truths_found += std::any_of(hazards_.begin(), hazards_.end(), [&](const Hazard& hazard) {
        return hazard.hazard_class == hazard_class && Overlaps(hazard, truth);
      });
    }
    classes[HazardClassName(hazard_class)] = {{"mapped", mapped},
                                              {"true_in_corridor", truths_in_corridor},
                                              {"precision", Ratio(mapped_right, mapped)},
                                              {"recall", Ratio(truths_found, truths_in_corridor)}};
  }
  nlohmann::json true_hazards = nlohmann::json::array();
  for (const TrueHazard& truth : truths) {
    if (!truth.in_corridor) continue;
    const Hazard& h = truth.hazard;
    true_hazards.push_back({{"class", HazardClassName(h.hazard_class)},
                            {"x_m", h.centroid_W.x()},
                            {"y_m", h.centroid_W.y()},
                            {"size_x_m", h.max_W.x() - h.min_W.x()},
                            {"size_y_m", h.max_W.y() - h.min_W.y()},
                            {"height_m", h.height_m},
                            {"detected", truth.detected},
                            {"found_as", truth.found_as ? nlohmann::json(HazardClassName(*truth.found_as)) : nlohmann::json(nullptr)},
                            {"first_detection_t_s", truth.detected ? NumberOrNull(h.first_detection_t_s) : nlohmann::json(nullptr)},
                            {"lead_distance_m", truth.detected ? NumberOrNull(truth.lead_distance_m) : nlohmann::json(nullptr)}});
  }
  nlohmann::json json = {{"resolution_m", map_.grid().resolution_m()},
          {"cells_measured", cells_measured_},
          {"elevation_error", error},
          {"corridor", {{"half_width_m", Corridor::kHalfWidth_m},
                        {"ahead_m", Corridor::kAhead_m},
                        {"cells", corridor_cells_},
                        {"measured", corridor_measured_},
                        {"coverage", Ratio(corridor_measured_, corridor_cells_)},
                        {"coverage_with_bounds", Ratio(corridor_bounded_, corridor_cells_)}}},
          {"upper_bound", {{"cells", cells_bounded_},
                           {"below_truth", bounds_below_truth_},
                           {"below_truth_share", Ratio(bounds_below_truth_, cells_bounded_)},
                           {"tolerance_m", map_.config().drop_min_m}}},
          {"hazards", {{"mapped", hazards_.size()}, {"classes", classes}}},
          {"true_hazards", true_hazards},
          {"map_memory_bytes", map_.grid().memory_bytes()},
          {"map_tiles", map_.grid().tile_count()}};
  if (scores_ghosts_) json["ghost_cells"] = {{"cells", ghost_cells_}, {"tolerance_m", map_.config().obstacle_min_m}};
  return json;
}

}  // namespace proxsim
