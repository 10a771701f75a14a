// `proxsim bench`, the terrain section (docs/terrain.md): what planning footsteps on
// the scene's true surface costs, against a paper-like sample's time. The
// gait plans a step at each heel strike (terrain queries through the world's
// ray caster, the ground profile, the foothold, the swing arc); between heel
// strikes it only evaluates the planned step. On the stairs course, every
// Advance() of a walker built as the simulation builds it is timed; the calls
// that cross a heel strike, less the median of the others, are the planning.
// Spread over the samples, that is set against one Simulation::Step of the
// paper run without its stop rule (every sample walks): the target is < 5 %.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace proxsim::bench {

nlohmann::json TerrainSection(bool quick);

/// The section's lines for the Markdown report.
std::string TerrainReport(const nlohmann::json& section);

}  // namespace proxsim::bench
