// `proxsim bench`, the closed-loop study's section: what an outcome study
// costs on generated rooms. A run is one episode (a set of 8 lasers on the
// shins, the stop rule, 10 s at 50 Hz) in a 10 x 10 m room at difficulty 0.5;
// Measured: closed-loop runs per second on one core (in this process, one
// worker thread; issue 26's target: 200), and `mpirun -np 2` against `-np 1`,
// one worker thread per rank, when mpirun is installed.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace proxsim::bench {

/// The section's sensor set as a YAML flow list: 8 lasers, on each shin
/// straight ahead and yawed ±30° at two pitches (the micro-benchmark's too).
std::string EightShinLasers();

/// `tmp`: a scratch folder; `quick`: fewer rooms.
nlohmann::json OutcomesSection(bool quick, const std::string& tmp);

/// The section's lines for the Markdown report.
std::string OutcomesReport(const nlohmann::json& section);

}  // namespace proxsim::bench
