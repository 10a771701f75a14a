// `proxsim bench`, the Python environments' section (bench/python_envs.py):
// co-simulation — the cost per step of setting the robot's state from Python
// (robot.locomotion: external) against the robot's own gait step — and the
// batched environment — VecWalkEnv's environment steps per second at N = 64
// on 2 threads against 64 separate WalkEnvs stepped one after another, and
// the Python overhead of a batched step against its C++ work. The machine's
// load is recorded beside the figures: on a shared machine the threads'
// gain is bounded by the cores the other processes leave.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace proxsim::bench {

nlohmann::json PythonEnvsSection(bool quick);

/// The section's lines for the Markdown report.
std::string PythonEnvsReport(const nlohmann::json& section);

}  // namespace proxsim::bench
