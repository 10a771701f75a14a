#include "output/terrain_sink.h"

#include "terrain/terrain_files.h"

namespace proxsim {

TerrainSink::TerrainSink(const TerrainMap& map, const RayCaster& caster, std::string dir)
    : map_(map), caster_(caster), dir_(std::move(dir)) {
  if (!dir_.empty()) octomap_.emplace(map.config().resolution_m);
}

void TerrainSink::Add(const SampleFrame&) {
  // the map updated itself from this sample's readings; its rays go into the tree
  if (octomap_) {
    for (const RayEvidence& evidence : map_.last_evidence()) octomap_->Add(evidence);
  }
}

void TerrainSink::Commit() { committed_ = RecordTerrain(map_, caster_, dir_, octomap_ ? &*octomap_ : nullptr); }

void TerrainSink::AddToSummary(nlohmann::json& summary) const {
  summary["terrain"] = committed_ ? *committed_ : RecordTerrain(map_, caster_, "", nullptr);
  if (!dir_.empty()) summary["outputs"].push_back("terrain/");
}

}  // namespace proxsim
