#include "output/terrain_sink.h"

#include "output/terrain_files.h"

namespace proxsim {

TerrainSink::TerrainSink(const TerrainMap& map, const RayCaster& caster, std::string dir)
    : archive_(map, !dir.empty()), caster_(caster), dir_(std::move(dir)) {}

void TerrainSink::Add(const SampleFrame&) {
  // the map updated itself from this sample's readings: what it retired, where the robot was, the rays
  archive_.Add();
}

void TerrainSink::Commit() { committed_ = RecordTerrain(archive_, caster_, dir_); }

void TerrainSink::AddToSummary(nlohmann::json& summary) const {
  summary["terrain"] = committed_ ? *committed_ : RecordTerrain(archive_, caster_, "");
  if (!dir_.empty()) summary["outputs"].push_back("terrain/");
}

}  // namespace proxsim
