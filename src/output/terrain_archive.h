// What the outputs keep of the terrain map over the whole walk, while the map
// itself holds its rolling window only (terrain_map.h): fed after every
// sample, it appends the tiles the map retired to a scratch file (the tiles'
// cells as they were), the robot's track (a point every centimetre walked,
// and whenever the ground it stands on changes) to another, keeps the hazards
// the map retired, and feeds the OctoMap tree the sample's rays, retiring its
// subtrees with the map's window. At the end the files and the score read
// the retired tiles back a piece of a row at a time (terrain_files.h) and
// stream the track (track_reader.h), so that a walk of any length is written
// and scored whole, in memory that hardly grows with it (the hazards, a few
// dozen bytes each; the retired tiles' index and the corridor's bitmaps, a
// few dozen bytes per tile: docs/trust.md).
//
// Frames: W world.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/spill_file.h"
#include "output/octomap_tiles.h"
#include "output/track_reader.h"
#include "knowledge/terrain_map.h"

namespace proxsim {

class TerrainArchive : public TrackReader {
 public:
  /// The track keeps a point every this far walked ...
  static constexpr double kTrackStep_m = 0.01;
  /// ... and whenever the ground the robot stands on changes this much.
  static constexpr double kTrackGroundStep_m = 0.005;

  /// `map` must outlive the archive; `with_octomap`: keep the OctoMap tree too.
  TerrainArchive(const TerrainMap& map, bool with_octomap);

  /// After each map update: what the map retired, the track, the rays.
  void Add();

  const TerrainMap& map() const { return map_; }
  /// The whole walk's track, read back from the scratch file a chunk at a time.
  void ForEachTrackPoint(const std::function<void(const TrackPoint&)>& visit) const override;
  /// Every hazard: those retired, then those the map holds.
  std::vector<Hazard> Hazards() const;
  /// The cells of every tile the map held or retired.
  CellBox Bounds() const;
  /// The map's ceiling for the truth: max_height_m above the highest ground
  /// the robot stood on (each reading's own ceiling is max_height_m above the
  /// ground the robot stood on then).
  double truth_ceiling_z_m() const;
  /// The OctoMap tree about the world origin (terrain/map.bt's), or null.
  OctomapRecorder* octomap() { return octomap_ ? &octomap_->origin_tile() : nullptr; }
  /// Every tile of the walk's OctoMap (map.bt and, beyond its reach, map_tiles/), or null.
  const OctomapTiles* octomap_tiles() const { return octomap_ ? &*octomap_ : nullptr; }
  std::size_t retired_tiles() const { return retired_tiles_; }

  /// Reads cells [ix_min, ix_min + n) of row iy into `cells` (null where no
  /// tile was ever made): the map's tile where it holds one, otherwise the
  /// tile as it was last retired. `storage` holds the retired ones' cells.
  void ReadRow(std::int32_t iy, std::int32_t ix_min, std::size_t n, std::vector<const TerrainCell*>& cells,
               std::vector<TerrainCell>& storage) const;

 private:
  void AddTrackPoint(const TrackPoint& point);

  const TerrainMap& map_;
  std::optional<OctomapTiles> octomap_;
  SpillFile tiles_{"the terrain map's retired tiles"};
  SpillFile track_file_{"the robot's track"};
  std::vector<TrackPoint> track_tail_;  // the points not yet in track_file_
  std::optional<TrackPoint> last_track_point_;
  std::size_t track_points_ = 0;
  double max_ground_z_m_ = -std::numeric_limits<double>::infinity();
  std::vector<Hazard> retired_hazards_;
  CellBox retired_bounds_;
  std::size_t retired_tiles_ = 0;
  Vec2 octomap_rolled_at_W_ = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
  // where each retired tile's last cells are in tiles_, sorted by tile row
  // then column (built at the first ReadRow; 16 bytes a tile)
  struct TileSlot {
    std::int32_t ty = 0, tx = 0;
    std::uint64_t at = 0;
  };
  mutable std::vector<TileSlot> tile_index_;
  static bool TileOrder(const TileSlot& a, const TileSlot& b);
  mutable bool indexed_ = false;
};

}  // namespace proxsim
