// A scenario's relative paths start from its folder (docs/scenario.md): one
// written into another folder (`proxsim generate --out`, docs/worlds.md) has
// them rewritten so that they name the same files from there.
#pragma once

#include <filesystem>
#include <string>

#include <yaml-cpp/yaml.h>

namespace proxsim {

/// `path` as read from `from_dir`, named from `to_dir`: unchanged when it is
/// absolute or the two folders are the same; else relative to `to_dir`, or
/// absolute when it cannot be (another root). Empty folders are the current one.
std::string RebasedPath(const std::string& path, const std::filesystem::path& from_dir,
                        const std::filesystem::path& to_dir);

/// Every path of the scenario `document` that is read relative to its folder
/// — scene.objects[].mesh.file, scene.objects[].motion.trajectory,
/// robot.model (but builtin:), robot.package_paths[], robot.trajectory —
/// rebased from `from_dir` to `to_dir` in place. Nodes of another shape
/// than the scenario's are left for the reader to refuse.
void RebaseScenarioPaths(YAML::Node document, const std::filesystem::path& from_dir,
                         const std::filesystem::path& to_dir);

}  // namespace proxsim
