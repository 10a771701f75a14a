// `proxsim bench`, the terrain map's section (`--only map`): what the terrain map costs per
// sample. On a paper-like walk (the paper's four sensors, one ray each, on
// the left tibia, the dining room, no strategy, 5 s at 100 Hz): one whole
// Simulation::Step with the map and without it, the map's own update
// (TerrainMap::Update replayed on the walk's recorded observations) and its
// share of the sample (the target: at most 20 %); the OctoMap tree's
// insertion per sample (an output, written by the run's recorder, apart);
// and scoring the map at the end of the run (the truth's vertical rays).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace proxsim::bench {

/// The section's figures; `quick` times fewer repeats.
nlohmann::json MapSection(bool quick);

/// The section's lines for the Markdown report.
std::string MapReport(const nlohmann::json& section);

}  // namespace proxsim::bench
