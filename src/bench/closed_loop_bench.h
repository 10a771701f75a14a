// `proxsim bench`, the closed loop's section: what a new episode costs
// against building the world (Reset vs the construction of a Simulation in
// the 1M-triangle room), and what driving the paper run from Python costs
// against the same run in C++ (the stop rule in Python; the binding's
// overhead per step).
#pragma once

#include <nlohmann/json.hpp>

#include "scenario/scenario.h"

namespace proxsim::bench {

/// `heavy`: the bench's scenario in the 1M-triangle room; `tmp` a scratch folder.
nlohmann::json ClosedLoopSection(const Scenario& heavy, const std::string& tmp, int repeats);

/// The section's lines for the Markdown report.
std::string ClosedLoopReport(const nlohmann::json& section);

}  // namespace proxsim::bench
