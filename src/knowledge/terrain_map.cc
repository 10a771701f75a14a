#include "knowledge/terrain_map.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <iterator>

#include "sensors/measured_point.h"

namespace proxsim {

namespace {

// Ideal sensors have no noise; their heights still need a variance to fuse:
// (0.1 mm)², below any real sensor's.
constexpr double kMinVariance_m2 = 1e-8;
// Labels are recomputed everywhere when the ground moves this much.
constexpr double kRelabelShift_m = 0.005;
// A silent ray that comes this close to a sole's heel–toe line has met the
// robot's own foot (a 0.26 × 0.10 × 0.06 m box on the biped), at an angle
// that sent no echo back: it says nothing beyond.
constexpr double kFootRadius_m = 0.08;
// A hazard pass's flood fill marks the cells it visited in this bit of their
// label (CellLabel takes the low bits), and clears it when done.
constexpr std::uint8_t kFilledBit = 0x80;

// The smallest distance between segments p0-p1 and q0-q1.
double SegmentDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0, t = 0;
  if (a <= 1e-18 && e <= 1e-18) return r.norm();
  if (a <= 1e-18) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 1e-18) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 1e-18 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0, s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return (p0 + s * d1 - (q0 + t * d2)).norm();
}

// How far along a silent ray it stays clear of the robot's own feet (its
// free_end_m when it never comes near them).
double ClearOfFeet_m(const RayEvidence& evidence, const RobotKnowledge& robot, double step_m) {
  double reach_m = evidence.free_end_m;
  if (!robot.has_feet) return reach_m;
  const Vec3 a = evidence.free_begin_W(), b = evidence.free_end_W();
  for (const FootKnowledge& foot : robot.feet) {
    if (SegmentDistance(a, b, foot.p_W_heel, foot.p_W_toe) >= kFootRadius_m) continue;
    // the first point within reach of the foot, a step at a time
    for (double d = evidence.free_begin_m; d < reach_m; d += step_m) {
      const Vec3 p = MeasuredPoint_W(evidence.p_WS, evidence.dir_W, d);
      if (SegmentDistance(p, p, foot.p_W_heel, foot.p_W_toe) < kFootRadius_m) {
        reach_m = d;
        break;
      }
    }
  }
  return reach_m;
}

// The part of segment a → b below height h (false: none).
bool ClipBelow(Vec3& a, Vec3& b, double h) {
  if (a.z() >= h && b.z() >= h) return false;
  if (a.z() > h) a = a + (b - a) * ((a.z() - h) / (a.z() - b.z()));
  if (b.z() > h) b = b + (a - b) * ((b.z() - h) / (b.z() - a.z()));
  return true;
}

}  // namespace

TerrainMap::TerrainMap(const TerrainMapConfig& config, std::vector<SensorSpec> specs, std::vector<bool> feeds_map)
    : config_(config), specs_(std::move(specs)), feeds_map_(std::move(feeds_map)), grid_(config.resolution_m) {
  feeds_map_.resize(specs_.size(), false);
  for (const SensorSpec& spec : specs_) models_.emplace_back(spec);
}

void TerrainMap::Reset() {
  grid_.Clear();
  evidence_.clear();
  hazards_.clear();
  retired_tiles_.clear();
  retired_hazards_.clear();
  last_ = TrackPoint{};
  rolled_at_W_ = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
  labelled_ground_z_m_ = 0.0;
  labels_changed_ = false;
  next_pass_t_s_ = 0.0;
  clusters_.clear();
  clustered_ground_z_m_ = std::numeric_limits<double>::quiet_NaN();
  clusters_kept_ = 0;
  retired_since_pass_ = false;
  relabelled_.clear();
}

void TerrainMap::Update(const Observation& observation, std::span<const RayEvidence> columns) {
  evidence_.clear();
  retired_tiles_.clear();
  retired_hazards_.clear();
  for (std::size_t i = 0; i < observation.sensors.size() && i < specs_.size(); ++i) {
    if (!feeds_map_[i] || !observation.sensors[i].fresh) continue;
    const SensorOutput& output = observation.sensors[i];
    if (output.measurements.empty()) {
      AddEvidence(InterpretMeasurement(specs_[i], models_[i], output.headline()), observation);
      continue;
    }
    // what the part reports beside its reading, each along its own direction:
    // every group's first (a zone's target or its silence, a beam's nearest
    // echo); a later one lies behind it, where its ray is not empty
    for (const Measurement& measurement : output.measurements) {
      if (measurement.rank == 0) AddEvidence(InterpretMeasurement(specs_[i], models_[i], measurement), observation);
    }
  }
  if (observation.robot == nullptr) return;
  for (const RayEvidence& column : columns) {
    Insert(column, observation.t_s, observation.robot->ground_z_m + config_.max_height_m);
  }
  UpdatePosition(observation.t_s, *observation.robot);
  RollWindow();
  if (observation.t_s + 1e-9 >= next_pass_t_s_) {
    next_pass_t_s_ = observation.t_s + kHazardPeriod_s;
    if (Relabel(observation.robot->ground_z_m)) FindHazardsAgain(observation.t_s, *observation.robot);
  }
}

void TerrainMap::AddEvidence(RayEvidence evidence, const Observation& observation) {
  // a silent ray stops at the robot's own feet: they may have swallowed its echo
  if (!evidence.detected && evidence.bounds_height && observation.robot != nullptr) {
    evidence.free_end_m = ClearOfFeet_m(evidence, *observation.robot, 0.5 * grid_.resolution_m());
    evidence.bounds_height = evidence.free_end_m > evidence.free_begin_m;
  }
  evidence_.push_back(evidence);
  // the ceiling rides with the robot: on a landing 0.6 m up, the landing is terrain
  const double ground_z_m = observation.robot != nullptr ? observation.robot->ground_z_m : 0.0;
  Insert(evidence_.back(), observation.t_s, ground_z_m + config_.max_height_m);
}

void TerrainMap::Insert(const RayEvidence& evidence, double t_s, double ceiling_z_m) {
  const double r = grid_.resolution_m();
  // the empty part of the ray, below the map's ceiling
  Vec3 a = evidence.free_begin_W(), b = evidence.free_end_W();
  if (evidence.bounds_height && evidence.free_end_m > evidence.free_begin_m && ClipBelow(a, b, ceiling_z_m)) {
    const Vec3 ab = b - a;
    const double ab_xy2 = ab.head<2>().squaredNorm(), ab_xy = std::sqrt(ab_xy2);
    // "near the centre": within a quarter of a cell's side; its square with a
    // relative margin of 1e-6 either side, far beyond the rounding of the
    // distances compared with it (so the comparisons below decide as a
    // comparison of the distance itself would)
    const double near_m = 0.25 * r;
    const double near2_lo = near_m * near_m * (1 - 1e-6), near2_hi = near_m * near_m * (1 + 1e-6);
    TraverseColumns(a, b, r, [&](CellIndex cell, double t0, double t1) {
      const double z_lo = std::min(a.z() + t0 * ab.z(), a.z() + t1 * ab.z());
      // one lookup for the cell's read and its bounds (the tile is made now
      // if it had none, as the bound below would make it)
      int i = 0;
      ElevationGrid::Tile& tile = grid_.TileOf(cell, &i);
      const TerrainCell& known = tile.cells[i];
      const bool measured = known.has_elevation();
      // a silent ray stops at the first surface the map knows it would
      // cross: it met it at a grazing angle, and says nothing beyond
      if (!evidence.proves_empty && measured &&
          z_lo < known.elevation_m - ElevationGrid::Gate_m(known.variance_m2, 0.0)) {
        return false;
      }
      // a detection's ray overrides a height only where it passes near the
      // cell's centre, or crosses the cell over half its side or more, below
      // the height all the way: one passing through a corner may miss a
      // surface that covers the rest of the cell (an edge). (A ray along a
      // line between two rows of centres, as a sensor's on a straight walk,
      // must still be able to clear what a person walking by left behind.)
      if (evidence.proves_empty && measured) {
        const Vec2 centre = grid_.CellCentre(cell);
        // the ray's nearest point to the centre within the cell; skipped when
        // the ray's whole line is certainly farther (its distance, by the
        // cross product, beyond the margin that rounding could bridge)
        const Vec2 ac = centre - a.head<2>();
        const double cross = ac.x() * ab.y() - ac.y() * ab.x();
        if (!(cross * cross > near2_hi * ab_xy2)) {
          // (a vertical ray passes the centre all along: its lowest point there,
          // or a person's column, as high as the map's ceiling, would never be
          // crossed by the oracle's column from the ceiling down)
          double t = ab_xy2 > 0 ? ac.dot(ab.head<2>()) / ab_xy2 : (ab.z() < 0 ? t1 : t0);
          t = std::clamp(t, t0, t1);
          const Vec3 p = a + t * ab;
          // |p − centre| <= near_m, by its square away from the boundary
          const double d2 = (p.head<2>() - centre).squaredNorm();
          if (d2 < near2_lo || (d2 <= near2_hi && std::sqrt(d2) <= near_m)) {
            grid_.BoundFromFreeSpace(tile, i, z_lo, false, t_s);
            grid_.BoundFromFreeSpace(tile, i, p.z(), true, t_s);
            return true;
          }
        }
        const double crossing_m = ab_xy * (t1 - t0);
        const double z_hi = std::max(a.z() + t0 * ab.z(), a.z() + t1 * ab.z());
        if (crossing_m >= 0.5 * r) {
          grid_.BoundFromFreeSpace(tile, i, z_lo, false, t_s);
          grid_.BoundFromFreeSpace(tile, i, z_hi, true, t_s);
          return true;
        }
      }
      grid_.BoundFromFreeSpace(tile, i, z_lo, false, t_s);
      return true;
    });
  }
  // the point, if below the ceiling
  if (evidence.detected) {
    const Vec3 p = evidence.point_W();
    if (p.z() <= ceiling_z_m) {
      grid_.FusePoint(grid_.IndexOf(p.x(), p.y()), p.z(), std::max(evidence.variance_z_m2, kMinVariance_m2), t_s);
    }
  }
}

void TerrainMap::UpdatePosition(double t_s, const RobotKnowledge& robot) {
  last_.t_s = t_s;
  last_.p_W_pelvis = robot.X_WP.translation().head<2>();
  last_.p_W_front = robot.p_W_front.head<2>();
  const Vec2 heading = robot.heading_W.head<2>();
  last_.heading_W = heading.norm() > 0 ? Vec2(heading.normalized()) : Vec2::UnitX();
  last_.ground_z_m = robot.ground_z_m;
}

void TerrainMap::RollWindow() {
  const double r = grid_.resolution_m();
  const Vec2 p = last_.p_W_pelvis;
  if ((p - rolled_at_W_).cwiseAbs().maxCoeff() < ElevationGrid::kTileSide * r) return;  // false for NaN: the first time
  rolled_at_W_ = p;
  // the window's cells, clamped to the lattice's (a window of 1e9 m keeps everything)
  const auto cell = [r](double v_m) {
    return static_cast<std::int32_t>(std::clamp(std::floor(v_m / r), -2.0e9, 2.0e9));
  };
  const double w = config_.window_m;
  const CellBox keep{cell(p.x() - w), cell(p.y() - w), cell(p.x() + w), cell(p.y() + w)};
  // a hazard leaves with its tiles, once every tile its box touches is outside;
  // until then they all stay, so that it leaves whole
  const auto tiles_of = [](const CellBox& cells) {
    const CellBox lo_tile = TileBox(TileCoord(cells.ix_min), TileCoord(cells.iy_min));
    const CellBox hi_tile = TileBox(TileCoord(cells.ix_max), TileCoord(cells.iy_max));
    return CellBox{lo_tile.ix_min, lo_tile.iy_min, hi_tile.ix_max, hi_tile.iy_max};
  };
  const auto gone = std::stable_partition(hazards_.begin(), hazards_.end(),
                                          [&](const Hazard& h) { return tiles_of(h.cells).Overlaps(keep); });
  retired_hazards_.assign(gone, hazards_.end());
  retired_tiles_ = grid_.RetireTiles([&](const CellBox& tile) {
    return tile.Overlaps(keep) || std::any_of(hazards_.begin(), gone, [&](const Hazard& h) { return tiles_of(h.cells).Overlaps(tile); });
  });
  hazards_.erase(gone, hazards_.end());
  if (!retired_tiles_.empty()) retired_since_pass_ = true;
}

bool TerrainMap::Relabel(double ground_z_m) {
  const bool everywhere = std::abs(ground_z_m - labelled_ground_z_m_) > kRelabelShift_m;
  if (everywhere) labelled_ground_z_m_ = ground_z_m;
  bool changed = everywhere;
  grid_.ForEachTile([&](ElevationGrid::Tile& tile) {
    if (!everywhere && tile.labelled_version == tile.version) return;
    tile.labelled_version = tile.version;
    int count = 0;
    for (int i = 0; i < ElevationGrid::kTileCells; ++i) {
      const auto label = static_cast<std::uint8_t>(LabelCell(SurfaceOf(tile.cells[i]), labelled_ground_z_m_, config_));
      if (label != tile.labels[i]) {
        changed = true;
        // (everywhere: every cluster is found again, no cell need be named)
        if (!everywhere) {
          relabelled_.push_back({tile.tx * ElevationGrid::kTileSide + i % ElevationGrid::kTileSide,
                                 tile.ty * ElevationGrid::kTileSide + i / ElevationGrid::kTileSide});
        }
      }
      tile.labels[i] = label;
      count += label != 0 ? 1 : 0;
    }
    tile.labelled_count = count;
  });
  return changed;
}

void TerrainMap::FindHazardsAgain(double t_s, const RobotKnowledge& robot) {
  // The clusters are the connected components of the labelled cells (an edge
  // joins two cells of one label at most two apart whose surfaces continue
  // each other), each found depth first from its least cell in row order. An
  // edge reads only its two cells' labels and, when labelled, their
  // surfaces. So a cluster of the last pass is still a component, found the
  // same way, when no cell within two of its cells changed since: none was
  // relabelled (Relabel names them) and no labelled cell's surface changed
  // (every labelled cell was in a cluster, which holds its surfaces then).
  // Such clusters are kept; the others are found again from their cells and
  // from the cells relabelled (a cell labelled now and in no cluster before
  // was relabelled). Every cluster is found again when the ground moved or
  // tiles left the window.
  const bool all_again = retired_since_pass_ || !(clustered_ground_z_m_ == labelled_ground_z_m_);
  const auto surface_at = [this](CellIndex c) {
    const TerrainCell* cell = grid_.Find(c);
    return cell ? SurfaceOf(*cell) : CellSurface{};
  };
  const auto same = [](const CellSurface& a, const CellSurface& b) {
    return std::bit_cast<std::uint32_t>(a.height_m) == std::bit_cast<std::uint32_t>(b.height_m) &&
           std::bit_cast<std::uint32_t>(a.upper_bound_m) == std::bit_cast<std::uint32_t>(b.upper_bound_m);
  };
  std::vector<CellIndex>& changed = relabelled_;  // and, below, the labelled cells whose surface changed
  std::vector<bool> moved(clusters_.size(), false);
  for (std::size_t k = 0; k < clusters_.size() && !all_again; ++k) {
    const Cluster& cluster = clusters_[k];
    for (std::size_t m = 0; m < cluster.cells.size(); ++m) {
      if (same(surface_at(cluster.cells[m]), cluster.surfaces[m])) continue;
      changed.push_back(cluster.cells[m]);
      moved[k] = true;
    }
  }
  const auto row_order = [](CellIndex a, CellIndex b) { return a.iy != b.iy ? a.iy < b.iy : a.ix < b.ix; };
  std::sort(changed.begin(), changed.end(), row_order);
  // whether a changed cell lies in the box
  const auto changed_in = [&](const CellBox& box) {
    for (std::int32_t iy = box.iy_min; iy <= box.iy_max; ++iy) {
      const auto it = std::lower_bound(changed.begin(), changed.end(), CellIndex{box.ix_min, iy}, row_order);
      if (it != changed.end() && it->iy == iy && it->ix <= box.ix_max) return true;
    }
    return false;
  };
  // the fill's visited cells: a bit of their label, cleared below
  struct Marks {
    ElevationGrid& grid;
    bool Test(CellIndex c) const {
      const ElevationGrid::Tile* tile = grid.FindTile(c);
      return tile != nullptr && (tile->labels[CellInTile(c)] & kFilledBit) != 0;
    }
    void Mark(CellIndex c) const {
      if (ElevationGrid::Tile* tile = grid.FindTile(c)) tile->labels[CellInTile(c)] |= kFilledBit;
    }
  } marks{grid_};
  std::vector<Cluster> kept;
  std::vector<CellIndex> seeds;
  for (std::size_t k = 0; k < clusters_.size(); ++k) {
    Cluster& cluster = clusters_[k];
    const CellBox& box = cluster.hazard.cells;
    if (!all_again && !moved[k] && !changed_in({box.ix_min - 2, box.iy_min - 2, box.ix_max + 2, box.iy_max + 2})) {
      for (const CellIndex c : cluster.cells) marks.Mark(c);
      kept.push_back(std::move(cluster));
    } else {
      seeds.insert(seeds.end(), cluster.cells.begin(), cluster.cells.end());
    }
  }
  if (all_again) {
    grid_.ForEachTile([&](const ElevationGrid::Tile& tile) {
      if (tile.labelled_count == 0) return;
      for (int i = 0; i < ElevationGrid::kTileCells; ++i) {
        if (tile.labels[i] == 0) continue;
        seeds.push_back({tile.tx * ElevationGrid::kTileSide + i % ElevationGrid::kTileSide,
                         tile.ty * ElevationGrid::kTileSide + i / ElevationGrid::kTileSide});
      }
    });
  } else {
    seeds.insert(seeds.end(), changed.begin(), changed.end());  // (the fill skips those unlabelled now)
  }
  std::sort(seeds.begin(), seeds.end(), row_order);
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  const auto label_at = [this](CellIndex c) {
    ElevationGrid::Tile* tile = grid_.FindTile(c);
    return tile ? static_cast<CellLabel>(tile->labels[CellInTile(c)] & ~kFilledBit) : CellLabel::kNone;
  };
  std::vector<Cluster> fresh;
  FillClusters(seeds, label_at, surface_at, marks, config_,
               [&](CellLabel label, const std::vector<CellIndex>& cells, const std::vector<CellSurface>& surfaces) {
                 fresh.push_back({cells, surfaces, hazards_internal::Classify(cells, surfaces, label, labelled_ground_z_m_,
                                                                    grid_.resolution_m(), config_)});
               });
  // in the order a fill from every labelled cell would find them: by their least cell
  clusters_.clear();
  clusters_kept_ = kept.size();
  std::merge(std::make_move_iterator(kept.begin()), std::make_move_iterator(kept.end()),
             std::make_move_iterator(fresh.begin()), std::make_move_iterator(fresh.end()), std::back_inserter(clusters_),
             [&](const Cluster& a, const Cluster& b) { return row_order(a.cells.front(), b.cells.front()); });
  // every cell visited is in a cluster
  for (const Cluster& cluster : clusters_) {
    for (const CellIndex c : cluster.cells) grid_.FindTile(c)->labels[CellInTile(c)] &= ~kFilledBit;
  }
  relabelled_.clear();
  clustered_ground_z_m_ = labelled_ground_z_m_;
  retired_since_pass_ = false;
  std::vector<Hazard> found;
  found.reserve(clusters_.size());
  for (const Cluster& cluster : clusters_) found.push_back(cluster.hazard);

  // each hazard found keeps the earliest detection of the hazards it overlaps
  // (the old hazards that may overlap one are those sharing a tile with its
  // box grown by a cell: an index of them by tile, sorted, so the scan below
  // meets the same hazards in the same order as a scan of all)
  by_tile_.clear();
  const auto for_each_tile = [](const CellBox& box, auto&& f) {
    for (std::int32_t ty = TileCoord(box.iy_min - 1); ty <= TileCoord(box.iy_max + 1); ++ty) {
      for (std::int32_t tx = TileCoord(box.ix_min - 1); tx <= TileCoord(box.ix_max + 1); ++tx) {
        f(TileKey(tx, ty));
      }
    }
  };
  for (std::size_t k = 0; k < hazards_.size(); ++k) {
    for_each_tile(hazards_[k].cells, [&](std::uint64_t key) { by_tile_.emplace_back(key, k); });
  }
  std::sort(by_tile_.begin(), by_tile_.end());
  std::vector<bool> matched(hazards_.size(), false);
  std::vector<std::size_t>& near = near_;
  const Vec2 front = robot.p_W_front.head<2>();
  for (Hazard& hazard : found) {
    near.clear();
    for_each_tile(hazard.cells, [&](std::uint64_t key) {
      auto it = std::lower_bound(by_tile_.begin(), by_tile_.end(), std::pair<std::uint64_t, std::size_t>(key, 0));
      for (; it != by_tile_.end() && it->first == key; ++it) near.push_back(it->second);
    });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (const std::size_t k : near) {
      const Hazard& before = hazards_[k];
      if (before.raised() != hazard.raised() || !before.cells.Overlaps(hazard.cells, 1)) continue;
      matched[k] = true;
      if (std::isnan(hazard.first_detection_t_s) || before.first_detection_t_s < hazard.first_detection_t_s) {
        hazard.first_detection_t_s = before.first_detection_t_s;
        hazard.distance_at_detection_m = before.distance_at_detection_m;
      }
    }
    if (std::isnan(hazard.first_detection_t_s)) {
      hazard.first_detection_t_s = t_s;
      hazard.distance_at_detection_m = hazard.DistanceTo(front);
    }
  }
  // a hazard no longer found is gone (the map was corrected), unless it was
  // found from another ground: the robot climbed or went down since
  for (std::size_t k = 0; k < hazards_.size(); ++k) {
    if (!matched[k] && std::abs(hazards_[k].ground_z_m - labelled_ground_z_m_) > config_.obstacle_min_m) {
      found.push_back(hazards_[k]);
    }
  }
  hazards_ = std::move(found);
}

}  // namespace proxsim
