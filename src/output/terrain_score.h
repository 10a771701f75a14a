// How far the map is from the truth (summary.json `terrain`), computed row by
// row over the output's extent, with the track streamed (track_reader.h) and
// the errors' percentile taken from a scratch file (bounded_percentile.h), so
// that a walk of any length is scored in memory that does not grow with it:
//  - the elevation error |elevation − truth| over the cells the map measured
//    (and whose column has a surface): its RMSE and 95th percentile;
//  - the corridor's coverage: the share of the corridor's cells (corridor.h)
//    that the map measured;
//  - free space's bounds against the truth: of the cells with a bound (and a
//    true surface), how many put the surface lower than it is by more than
//    drop_min_m (alone, a false hole: a silent ray read as free space where a
//    surface was, e.g. a wall met too obliquely to echo);
//  - ghost cells (scenes with moving objects only): cells whose height
//    stands above the still scene by more than obstacle_min_m where nothing
//    stands now either: a moved object's height the map did not forget;
//  - the true hazards: the truth's cells classified by the map's own rules
//    (hazards.h), each relative to the ground the robot stood on when it
//    came nearest to it; per class, the precision of the map's hazards (the
//    share that overlaps a true hazard of their class) and the recall over
//    the true hazards in the corridor (the share a map hazard of their class
//    overlaps); and for each true hazard in the corridor the time the map
//    first held a hazard (of any class) over it, and the lead distance: the
//    leading toe's distance to it then.
// A map hazard overlaps a true one when one of the true hazard's cells lies
// in the map hazard's bounding box grown by one cell.
#pragma once

#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/bounded_percentile.h"
#include "output/corridor.h"
#include "output/track_reader.h"
#include "knowledge/hazards.h"
#include "knowledge/terrain_map.h"

namespace proxsim {

/// A hazard of the scene and how the map did on it.
struct TrueHazard {
  Hazard hazard;                 ///< classified from the truth (first_detection_*: the map's, below)
  std::vector<CellIndex> cells;
  bool in_corridor = false;
  bool detected = false;         ///< a map hazard overlaps it
  std::optional<HazardClass> found_as;  ///< the class of the map hazard that found it first
  double lead_distance_m = std::numeric_limits<double>::quiet_NaN();
};

class TerrainScorer {
 public:
  /// `map`, `track` and `corridor` must outlive the scorer; `track` and
  /// `hazards` are the whole walk's (terrain_archive.h; the track is streamed
  /// once here and once per level in FindTrueHazards), `truth_ceiling_z_m` the truth's ceiling.
  TerrainScorer(const TerrainMap& map, const TrackReader& track, std::vector<Hazard> hazards,
                double truth_ceiling_z_m, const Corridor& corridor);

  /// Cells [ix_min, ix_min + n) of row iy: the map's (null: never touched)
  /// and the true heights of the still scene (NaN: no surface); `now_m`, in
  /// a scene with moving objects, the heights with them where they are at
  /// the end (empty otherwise: no ghost cells are counted).
  void AddRow(std::int32_t iy, std::int32_t ix_min, std::span<const TerrainCell* const> cells,
              std::span<const float> truth_m, std::span<const float> now_m = {});

  /// The true hazards found and matched; call after the last row.
  const std::vector<TrueHazard>& FindTrueHazards();

  /// summary.json `terrain`; call after the last row.
  nlohmann::json Json();

 private:
  const TerrainMap& map_;
  const TrackReader& track_;
  std::vector<Hazard> hazards_;
  double truth_ceiling_z_m_;
  const Corridor& corridor_;
  std::vector<double> levels_m_;    // the grounds the robot stood on (5 mm apart at least)
  BoundedPercentile abs_errors_m_{"the terrain score's elevation errors"};
  double sum_squared_error_m2_ = 0;
  std::size_t corridor_cells_ = 0, corridor_measured_ = 0, corridor_bounded_ = 0, cells_measured_ = 0;
  std::size_t cells_bounded_ = 0, bounds_below_truth_ = 0;  // cells with a bound and a true surface; bound too low
  bool scores_ghosts_ = false;  // rows came with the heights of now (a scene with moving objects)
  std::size_t ghost_cells_ = 0;
  // the true surface of every cell that is a hazard relative to some level
  std::unordered_map<std::uint64_t, CellSurface> off_ground_;
  std::vector<TrueHazard> true_hazards_;
  bool matched_ = false;
};

}  // namespace proxsim
