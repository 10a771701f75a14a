// The terrain map as a run's output: each sample, what the map retired, the
// track and the rays into the archive (output/terrain_archive.h), then at the end OUT/terrain/ (output/terrain_files.h) and the map's score
// against the truth in summary.json `terrain`.
#pragma once

#include <optional>
#include <string>

#include "output/run_sink.h"
#include "raycast/ray_caster.h"
#include "output/terrain_archive.h"

namespace proxsim {

class TerrainSink : public RunSink {
 public:
  /// `dir` empty: no files, the score only. `map` and `caster` must outlive the sink.
  TerrainSink(const TerrainMap& map, const RayCaster& caster, std::string dir);

  void Add(const SampleFrame& frame) override;
  /// Writes terrain/ and keeps its score for the summary.
  void Commit() override;
  /// `terrain`: the score as of the last Commit, or of the map as it stands.
  void AddToSummary(nlohmann::json& summary) const override;

 private:
  // mutable: the summary of a run without files scores the archive as it stands
  mutable TerrainArchive archive_;
  const RayCaster& caster_;
  std::string dir_;
  std::optional<nlohmann::json> committed_;
};

}  // namespace proxsim
