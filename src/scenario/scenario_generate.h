// Generated worlds in a scenario (docs/worlds.md): `scene: {generate: {...}}`
// read, the world generated and written in as plain objects.
#pragma once

#include <string>

#include <yaml-cpp/yaml.h>

namespace proxsim {

/// Whether a parsed scenario document asks for a generated world (`scene.generate`).
bool HasGenerate(const YAML::Node& document);

/// The scenario `yaml_text` with its generated world written out: the
/// generated objects (then the file's own) under scene.objects, and the
/// robot's path when the file has a robot without a path. What
/// `proxsim generate` writes, and what a scenario with `generate` is read as.
/// Throws InputError naming the fault (an unknown family, an impossible
/// range, a person taller than the room) with `source` in every message.
/// With `written_to` (the file the text is for, in another folder than
/// `source`), the paths read relative to the scenario's folder (meshes,
/// trajectories, the robot's model) are rewritten to name the same files from
/// that file's folder (scenario/scenario_paths.h).
std::string GeneratedScenarioText(const std::string& yaml_text, const std::string& source,
                                  const std::string& written_to = {});

/// The same on a parsed document (changed in place and returned), without
/// writing it out: the text above is this node emitted. A closed-loop study
/// runs its episodes from the node, which spares each episode a write and
/// two parses of its world (~20 % of an episode's time on a generated room).
YAML::Node GeneratedScenarioNode(YAML::Node document, const std::string& source);

}  // namespace proxsim
