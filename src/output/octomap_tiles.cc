#include "output/octomap_tiles.h"

#include <cmath>
#include <string>

namespace proxsim {

OctomapTiles::OctomapTiles(double resolution_m) : resolution_m_(resolution_m) {
  tiles_.emplace(std::make_pair(0, 0), std::make_unique<OctomapRecorder>(resolution_m));
}

void OctomapTiles::Add(const RayEvidence& evidence_W) {
  // within map.bt's reach: there, as a walk that never left it always had it
  if (origin_tile().Add(evidence_W)) return;
  // else the tile whose origin is nearest the sensor (a ray from it reaches
  // a sensor's range, metres, within the tile's ±reach)
  const double spacing_m = reach_m();
  const double ix = std::round(evidence_W.p_WS.x() / spacing_m), iy = std::round(evidence_W.p_WS.y() / spacing_m);
  // (a coordinate no tile index holds: a NaN or a walk of 1e12 m)
  if (!(std::abs(ix) < 1e6 && std::abs(iy) < 1e6)) {
    ++left_out_;
    return;
  }
  const std::pair<int, int> key(static_cast<int>(ix), static_cast<int>(iy));
  auto tile = tiles_.find(key);
  if (tile == tiles_.end()) tile = tiles_.emplace(key, std::make_unique<OctomapRecorder>(resolution_m_)).first;
  RayEvidence evidence_T = evidence_W;
  evidence_T.p_WS -= Vec3(ix * spacing_m, iy * spacing_m, 0.0);
  if (key == std::make_pair(0, 0) || !tile->second->Add(evidence_T)) ++left_out_;
}

void OctomapTiles::RetireOutside(const Vec2& lo_W, const Vec2& hi_W) {
  for (const auto& [key, tile] : tiles_) {
    const Vec2 origin_W(key.first * reach_m(), key.second * reach_m());
    tile->RetireOutside(lo_W - origin_W, hi_W - origin_W);
  }
}

std::vector<OctomapTiles::Tile> OctomapTiles::WriteBinary(const std::filesystem::path& dir) const {
  origin_tile().WriteBinary((dir / "map.bt").string());
  std::vector<Tile> written;
  for (const auto& [key, tile] : tiles_) {
    if (key == std::make_pair(0, 0)) continue;
    std::filesystem::create_directories(dir / "map_tiles");
    Tile out{.ix = key.first,
             .iy = key.second,
             .origin_W = Vec3(key.first * reach_m(), key.second * reach_m(), 0.0),
             .file = "map_tiles/map_" + std::to_string(key.first) + "_" + std::to_string(key.second) + ".bt"};
    tile->WriteBinary((dir / out.file).string());
    written.push_back(std::move(out));
  }
  return written;
}

}  // namespace proxsim
