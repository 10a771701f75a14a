// `proxsim bench`, the robots' section: what a real robot of meshes costs.
// Loading the Unitree H1 (Unitree's description, not part of this repository,
// expected beside it in ../shared/robots/h1_description: its URDF and 21
// binary STL meshes, ~346k triangles) and building its bodies (the ray
// caster's BVHs and the clearance's surface samples); then the cost of one
// paper-like sample (the paper's four sensors, one ray each, on the left
// shin, walking in the built-in dining room, no strategy) with the H1
// against the built-in primitive biped, and with the H1's collision
// geometry. Without the H1 folder the section says so and measures nothing.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace proxsim::bench {

/// The section's figures; `quick` times fewer repeats.
nlohmann::json RobotsSection(bool quick);

/// The section's lines for the Markdown report.
std::string RobotsReport(const nlohmann::json& section);

/// What the contact check (sim/contacts.h) costs in a paper-like sample, with
/// the built-in biped and (when its folder is there) the H1's meshes:
/// `{biped,h1}_{step_s,contacts_s,contacts_share}`.
nlohmann::json ContactsSection(bool quick);
std::string ContactsReport(const nlohmann::json& section);

}  // namespace proxsim::bench
