// `proxsim bench`, the study's section: what a placement study costs on the
// paper's walk. A run is one candidate mounting in one scene with one seed; a
// job (one scene and seed) carries every candidate at once. Measured: runs
// per second on one core (in this process, one worker thread); the wall time
// of a 1000-run study through `proxsim study` on every core (target < 1 min);
// and `mpirun -np 2` against `-np 1`, one worker thread per rank (target
// >= 1.85x on a 2-core machine), when mpirun is installed.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace proxsim::bench {

/// `tmp`: a scratch folder; `quick`: a smaller study for the MPI comparison.
nlohmann::json StudySection(bool quick, const std::string& tmp);

/// The section's lines for the Markdown report.
std::string StudyReport(const nlohmann::json& section);

}  // namespace proxsim::bench
