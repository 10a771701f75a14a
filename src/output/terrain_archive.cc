#include "output/terrain_archive.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace proxsim {

namespace {

// A tile in the scratch file: its index, then its cells as they are in memory.
struct TileHeader {
  std::int32_t tx = 0, ty = 0;
};
constexpr std::size_t kTileRecord = sizeof(TileHeader) + sizeof(TerrainCell) * ElevationGrid::kTileCells;

// The track's points go to the scratch file this many at a time.
constexpr std::size_t kTrackChunk = 4096;

}  // namespace

TerrainArchive::TerrainArchive(const TerrainMap& map, bool with_octomap) : map_(map) {
  if (with_octomap) octomap_.emplace(map.config().resolution_m);
}

void TerrainArchive::Add() {
  for (const auto& tile : map_.last_retired_tiles()) {
    std::string record(kTileRecord, '\0');
    const TileHeader header{tile->tx, tile->ty};
    std::memcpy(record.data(), &header, sizeof header);
    std::memcpy(record.data() + sizeof header, tile->cells.data(), sizeof(TerrainCell) * ElevationGrid::kTileCells);
    tiles_.Append(record);
    retired_bounds_.Expand(TileBox(tile->tx, tile->ty));
    ++retired_tiles_;
    indexed_ = false;
  }
  const std::vector<Hazard>& gone = map_.last_retired_hazards();
  retired_hazards_.insert(retired_hazards_.end(), gone.begin(), gone.end());
  AddTrackPoint(map_.last_position());  // (a map is built by a robot: it was somewhere)
  if (octomap_) {
    for (const RayEvidence& evidence : map_.last_evidence()) octomap_->Add(evidence);
    // the tree's window rolls with the map's, a tile's side at a time
    const Vec2 p = map_.last_position().p_W_pelvis;
    const double step_m = ElevationGrid::kTileSide * map_.config().resolution_m;
    if (!((p - octomap_rolled_at_W_).cwiseAbs().maxCoeff() < step_m)) {
      octomap_rolled_at_W_ = p;
      const Vec2 w = Vec2::Constant(map_.config().window_m);
      octomap_->RetireOutside(p - w, p + w);
    }
  }
}

void TerrainArchive::AddTrackPoint(const TrackPoint& point) {
  if (last_track_point_ && (last_track_point_->p_W_pelvis - point.p_W_pelvis).norm() < kTrackStep_m &&
      std::abs(last_track_point_->ground_z_m - point.ground_z_m) < kTrackGroundStep_m) {
    return;
  }
  last_track_point_ = point;
  ++track_points_;
  max_ground_z_m_ = std::max(max_ground_z_m_, point.ground_z_m);
  track_tail_.push_back(point);
  if (track_tail_.size() < kTrackChunk) return;
  track_file_.Append(std::string_view(reinterpret_cast<const char*>(track_tail_.data()),
                                      track_tail_.size() * sizeof(TrackPoint)));
  track_tail_.clear();
}

void TerrainArchive::ForEachTrackPoint(const std::function<void(const TrackPoint&)>& visit) const {
  // the file holds whole chunks of kTrackChunk points
  std::vector<TrackPoint> chunk(kTrackChunk);
  for (std::uint64_t at = 0; at < track_file_.size(); at += sizeof chunk[0] * kTrackChunk) {
    track_file_.ReadAt(at, chunk.data(), sizeof chunk[0] * kTrackChunk);
    for (const TrackPoint& point : chunk) visit(point);
  }
  for (const TrackPoint& point : track_tail_) visit(point);
}

bool TerrainArchive::TileOrder(const TileSlot& a, const TileSlot& b) { return a.ty != b.ty ? a.ty < b.ty : a.tx < b.tx; }

std::vector<Hazard> TerrainArchive::Hazards() const {
  std::vector<Hazard> hazards = retired_hazards_;
  hazards.insert(hazards.end(), map_.hazards().begin(), map_.hazards().end());
  return hazards;
}

CellBox TerrainArchive::Bounds() const {
  CellBox box = retired_bounds_;
  box.Expand(map_.grid().Bounds());
  return box;
}

double TerrainArchive::truth_ceiling_z_m() const {
  const double ground_z_m = track_points_ == 0 ? 0.0 : std::max(map_.last_position().ground_z_m, max_ground_z_m_);
  return ground_z_m + map_.config().max_height_m;
}

void TerrainArchive::ReadRow(std::int32_t iy, std::int32_t ix_min, std::size_t n,
                             std::vector<const TerrainCell*>& cells, std::vector<TerrainCell>& storage) const {
  const ElevationGrid& grid = map_.grid();
  cells.assign(n, nullptr);
  for (std::size_t k = 0; k < n; ++k) cells[k] = grid.Find({ix_min + static_cast<std::int32_t>(k), iy});
  if (retired_tiles_ == 0) return;
  if (!indexed_) {
    // every record, then the last of each tile (its last state): the records are in the order written
    tile_index_.clear();
    for (std::uint64_t at = 0; at < tiles_.size(); at += kTileRecord) {
      TileHeader header;
      tiles_.ReadAt(at, &header, sizeof header);
      tile_index_.push_back({header.ty, header.tx, at});
    }
    std::stable_sort(tile_index_.begin(), tile_index_.end(), TileOrder);
    const auto last_of_each = std::unique(tile_index_.rbegin(), tile_index_.rend(), [](const TileSlot& a, const TileSlot& b) {
      return a.ty == b.ty && a.tx == b.tx;
    });
    tile_index_.erase(tile_index_.begin(), last_of_each.base());
    tile_index_.shrink_to_fit();
    indexed_ = true;
  }
  storage.resize(n);
  const std::int32_t ix_max = ix_min + static_cast<std::int32_t>(n) - 1;
  const int row_in_tile = iy & (ElevationGrid::kTileSide - 1);
  TerrainCell row[ElevationGrid::kTileSide];
  const TileSlot first{TileCoord(iy), TileCoord(ix_min), 0};
  for (auto it = std::lower_bound(tile_index_.begin(), tile_index_.end(), first, TileOrder);
       it != tile_index_.end() && it->ty == first.ty && it->tx <= TileCoord(ix_max); ++it) {
    const std::int32_t x0 = it->tx * ElevationGrid::kTileSide;
    if (grid.Find({x0, iy}) != nullptr) continue;  // the map holds it again: its state now
    tiles_.ReadAt(it->at + sizeof(TileHeader) + sizeof(TerrainCell) * ElevationGrid::kTileSide * row_in_tile, row,
                  sizeof row);
    for (int j = 0; j < ElevationGrid::kTileSide; ++j) {
      const std::int32_t ix = x0 + j;
      if (ix < ix_min || ix > ix_max) continue;
      const auto k = static_cast<std::size_t>(ix - ix_min);
      storage[k] = row[j];
      cells[k] = &storage[k];
    }
  }
}

}  // namespace proxsim
