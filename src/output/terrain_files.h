// OUT/terrain/, the terrain map's files (the contract of issue 14):
//   meta.json        {"resolution_m", "origin_xy_m": [x0, y0], "shape": [ny, nx], ...}:
//                    cell (i, j) covers x in [x0 + j·r, x0 + (j+1)·r), y in [y0 + i·r, y0 + (i+1)·r)
//   elevation.npy    float32 (ny, nx), the fused height; NaN where never measured
//   variance.npy     float32, its variance (m²); NaN where never measured
//   upper_bound.npy  float32, free space's bound on the height; NaN where none
//   truth.npy        float32, the scene's true height (truth_field.h); NaN where no surface
//   hits.npy         uint32, points fused into the height
//   first_update_t_s.npy, last_update_t_s.npy   float32, when the cell first held a height / last changed; NaN: never
//   hazards.csv      class,x_m,y_m,size_x_m,size_y_m,height_m,first_detection_t_s,distance_at_detection_m
//                    (height_m: above the ground for obstacle and step_up, minus the depth for step_down and hole)
//   map.bt           the OctoMap tree (octomap_recorder.h)
// The extent is the tiles the map held or retired (terrain_archive.h) and the
// corridor's cells together (the true
// hazards are classified over 1 m more on every side, so that the extent
// does not cut them down to another class). Rows are
// written one at a time (the truth cast row by row too), so a long walk needs
// no dense copy in memory. The folder is written as terrain.tmp/ and renamed
// when complete.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "raycast/ray_caster.h"
#include "output/terrain_archive.h"

namespace proxsim {

/// Scores the whole walk's map against the scene (terrain_score.h) and, when
/// `dir` is not empty, writes the files into it (OUT/terrain), with map.bt
/// when the archive keeps the OctoMap tree. Returns summary.json `terrain`.
/// Throws std::runtime_error on I/O failure.
nlohmann::json RecordTerrain(TerrainArchive& archive, const RayCaster& caster, const std::string& dir);

/// hazards.csv's text for a list of hazards (sorted by first detection, then x, then y).
std::string HazardsCsvText(const std::vector<Hazard>& hazards);

}  // namespace proxsim
