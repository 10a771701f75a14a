#include "output/terrain_files.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <vector>

#include "core/atomic_file.h"
#include "core/number_format.h"
#include "output/corridor.h"
#include "output/terrain_score.h"
#include "sim/truth_field.h"

namespace proxsim {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
// The truth's hazards are found this far beyond the files' extent.
constexpr double kTruthMargin_m = 1.0;
// A row (as long as the walk, along a straight one) is read, cast, scored and
// written this many cells at a time, so that the end's memory does not grow
// with the walk; a multiple of the ray caster's packet (8 rays), so that the
// truth's rays are cast in the same packets as a whole row's would be.
constexpr std::size_t kRowChunkCells = 4096;

// A 2-D .npy array (format 1.0, C order), written row after row.
class NpyRows {
 public:
  NpyRows(const std::string& path, const char* descr, std::int32_t ny, std::int32_t nx) : file_(path) {
    std::string dict = std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': (" +
                       std::to_string(ny) + ", " + std::to_string(nx) + "), }";
    // magic, version, header length, then the dict padded so that the data starts at a multiple of 64
    const std::size_t unpadded = 10 + dict.size() + 1;
    dict.append((64 - unpadded % 64) % 64, ' ');
    dict += '\n';
    std::string header = "\x93NUMPY";
    header += '\x01';
    header += '\x00';
    header += static_cast<char>(dict.size() & 0xFF);
    header += static_cast<char>(dict.size() >> 8);
    file_.Write(header + dict);
  }
  /// The next cells, in C order (a row may come in several pieces).
  template <class T>
  void Cells(const std::vector<T>& values, std::size_t n) {
    file_.Write(std::string_view(reinterpret_cast<const char*>(values.data()), n * sizeof(T)));
  }
  void Commit() { file_.Commit(); }

 private:
  AtomicFile file_;
};

}  // namespace

std::string HazardsCsvText(const std::vector<Hazard>& hazards) {
  std::vector<const Hazard*> sorted;
  for (const Hazard& hazard : hazards) sorted.push_back(&hazard);
  std::sort(sorted.begin(), sorted.end(), [](const Hazard* a, const Hazard* b) {
    if (a->first_detection_t_s != b->first_detection_t_s) return a->first_detection_t_s < b->first_detection_t_s;
    if (a->centroid_W.x() != b->centroid_W.x()) return a->centroid_W.x() < b->centroid_W.x();
    return a->centroid_W.y() < b->centroid_W.y();
  });
  std::string text = "class,x_m,y_m,size_x_m,size_y_m,height_m,first_detection_t_s,distance_at_detection_m\n";
  for (const Hazard* h : sorted) {
    text += HazardClassName(h->hazard_class);
    for (double value : {h->centroid_W.x(), h->centroid_W.y(), h->max_W.x() - h->min_W.x(), h->max_W.y() - h->min_W.y(),
                         h->height_m, h->first_detection_t_s, h->distance_at_detection_m}) {
      text += ',';
      AppendNumber(text, value);
    }
    text += '\n';
  }
  return text;
}

nlohmann::json RecordTerrain(TerrainArchive& archive, const RayCaster& caster, const std::string& dir) {
  const TerrainMap& map = archive.map();
  const double r = map.grid().resolution_m();
  const double ceiling_z_m = archive.truth_ceiling_z_m();
  const Corridor corridor(archive, map.last_position(), r);
  TerrainScorer scorer(map, archive, archive.Hazards(), ceiling_z_m, corridor);
  CellBox extent = archive.Bounds();
  extent.Expand(corridor.Bounds());
  const std::int32_t nx = extent.nx(), ny = extent.ny();
  // the truth is classified over a wider box, so that a hazard the extent
  // cuts keeps its true size and class (the files hold the extent only)
  const auto margin = static_cast<std::int32_t>(std::ceil(kTruthMargin_m / r));
  const CellBox scored = extent.empty() ? extent
                                        : CellBox{extent.ix_min - margin, extent.iy_min - margin, extent.ix_max + margin,
                                                  extent.iy_max + margin};

  // the files, when asked for, each an atomic file in the folder: a user's own
  // files there stay (the previous run's went by its manifest)
  const std::filesystem::path final_dir(dir);
  // one file per array, in kArrayNames' order
  static constexpr const char* kArrayNames[] = {"elevation.npy", "variance.npy", "upper_bound.npy", "truth.npy",
                                                "hits.npy", "first_update_t_s.npy", "last_update_t_s.npy"};
  enum { kElevation, kVariance, kUpperBound, kTruth, kHits, kFirstT, kLastT };
  std::vector<std::unique_ptr<NpyRows>> arrays;
  if (!dir.empty()) {
    std::filesystem::create_directories(final_dir);
    for (const char* name : kArrayNames) {
      arrays.push_back(std::make_unique<NpyRows>((final_dir / name).string(), name == std::string("hits.npy") ? "<u4" : "<f4", ny, nx));
    }
  }

  // row by row, a chunk of a row at a time: the map's cells, the truth under them, scored and written
  std::vector<const TerrainCell*> cells(kRowChunkCells);
  std::vector<TerrainCell> retired_cells;
  std::vector<float> elevation(kRowChunkCells), variance(kRowChunkCells), upper_bound(kRowChunkCells),
      first_t(kRowChunkCells), last_t(kRowChunkCells), truth(kRowChunkCells);
  std::vector<std::uint32_t> hits(kRowChunkCells);
  for (std::int32_t iy = scored.iy_min; iy <= scored.iy_max; ++iy) {
    for (std::int32_t x0 = scored.ix_min; x0 <= scored.ix_max; x0 += static_cast<std::int32_t>(kRowChunkCells)) {
      const std::int32_t x1 = std::min(scored.ix_max, x0 + static_cast<std::int32_t>(kRowChunkCells) - 1);
      const auto chunk_n = static_cast<std::size_t>(x1 - x0 + 1);
      archive.ReadRow(iy, x0, chunk_n, cells, retired_cells);
      const std::vector<float> scored_truth = TrueHeights(caster, CellBox{x0, iy, x1, iy}, r, ceiling_z_m);
      // with moving objects: the heights with them where they are now, for the ghost cells
      const std::vector<float> scored_now =
          caster.has_moving() ? TrueHeights(caster, CellBox{x0, iy, x1, iy}, r, ceiling_z_m, true) : std::vector<float>{};
      scorer.AddRow(iy, x0, cells, scored_truth, scored_now);
      // the files hold the extent's part of the chunk
      const std::int32_t file_x0 = std::max(x0, extent.ix_min), file_x1 = std::min(x1, extent.ix_max);
      if (arrays.empty() || iy < extent.iy_min || iy > extent.iy_max || file_x0 > file_x1) continue;
      const auto n = static_cast<std::size_t>(file_x1 - file_x0 + 1);
      const auto offset = static_cast<std::size_t>(file_x0 - x0);
      for (std::size_t k = 0; k < n; ++k) {
        const TerrainCell* cell = cells[offset + k];
        truth[k] = scored_truth[offset + k];
        const bool measured = cell != nullptr && cell->has_elevation();
        elevation[k] = measured ? cell->elevation_m : kNaN;
        variance[k] = measured ? cell->variance_m2 : kNaN;
        upper_bound[k] = cell != nullptr && std::isfinite(cell->upper_bound_m) ? cell->upper_bound_m : kNaN;
        hits[k] = cell != nullptr ? cell->hits : 0;
        first_t[k] = cell != nullptr ? cell->first_t_s : kNaN;
        last_t[k] = cell != nullptr ? cell->last_t_s : kNaN;
      }
      arrays[kElevation]->Cells(elevation, n);
      arrays[kVariance]->Cells(variance, n);
      arrays[kUpperBound]->Cells(upper_bound, n);
      arrays[kTruth]->Cells(truth, n);
      arrays[kHits]->Cells(hits, n);
      arrays[kFirstT]->Cells(first_t, n);
      arrays[kLastT]->Cells(last_t, n);
    }
  }
  nlohmann::json score = scorer.Json();
  if (arrays.empty()) return score;

  for (const auto& array : arrays) array->Commit();
  const nlohmann::json meta = {
      {"resolution_m", r},
      {"origin_xy_m", {extent.ix_min * r, extent.iy_min * r}},
      {"shape", {ny, nx}},
      {"max_height_m", map.config().max_height_m},
      {"truth_ceiling_z_m", ceiling_z_m},
      {"frame", "world"},
      {"arrays", kArrayNames}};
  WriteFileAtomically((final_dir / "meta.json").string(), meta.dump(2) + "\n");
  WriteFileAtomically((final_dir / "hazards.csv").string(), HazardsCsvText(archive.Hazards()));
  if (const OctomapTiles* octomap = archive.octomap_tiles(); octomap != nullptr) {
    const std::vector<OctomapTiles::Tile> tiles = octomap->WriteBinary(final_dir);
    // a walk beyond the keys' reach: map.bt holds what lies within it, the tiles the rest (octomap_tiles.h)
    if (!tiles.empty() || octomap->left_out() > 0) {
      nlohmann::json listed = nlohmann::json::array();
      for (const OctomapTiles::Tile& tile : tiles)
        listed.push_back({{"file", "terrain/" + tile.file},
                          {"origin_m", {tile.origin_W.x(), tile.origin_W.y(), tile.origin_W.z()}}});
      score["map_bt"] = {{"tiles", listed},
                         {"left_out_readings", octomap->left_out()},
                         {"reach_m", octomap->reach_m()},
                         {"note", "OctoMap's keys reach this far from a tree's origin at the map's resolution: "
                                  "terrain/map.bt holds the readings within it of the world origin, each tile "
                                  "the readings whose sensor was nearest its origin, in its own frame (the world "
                                  "moved by origin_m)"}};
    }
  }
  return score;
}

}  // namespace proxsim
