// Where a URDF's <mesh filename="..."> is on disk. Three forms:
//   - a path: absolute, or relative to the URDF's folder;
//   - file:///abs/path (file://rest with a relative rest: against the URDF's folder);
//   - package://NAME/rest: NAME is looked for, in this order, in the
//     scenario's robot.package_paths, then in the ROS_PACKAGE_PATH
//     environment variable (folders separated by ':'), then among the URDF's
//     own ancestor folders. In the first two, each folder F is the package
//     when it is named NAME or holds a package.xml whose <name> is NAME, or
//     holds it as a direct subfolder (F/NAME first, then any subfolder whose
//     package.xml names NAME, in name order); an ancestor is the package when
//     it is named NAME or its package.xml says so. The first package found
//     that holds `rest` wins, so a stale copy of a package without the file
//     does not hide a complete one further down the list.
// A mesh must be a regular file (a device such as /dev/zero is refused).
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace proxsim {

/// A mesh file found, or why not: `problem` names the URI's form and every
/// folder searched, for the user's message.
struct MeshLookup {
  std::optional<std::filesystem::path> path;  ///< the file, when found
  std::string problem;                       ///< why not, when not found
  /// A package:// URI whose package is nowhere (not merely one lacking the
  /// file): its name, so that a URDF naming it many times reports it once.
  std::string missing_package;
};

/// Resolves `uri` for a URDF in `urdf_dir` (empty: the current folder).
/// `package_paths` are searched first for package:// URIs (see above).
MeshLookup ResolveMeshUri(const std::string& uri, const std::filesystem::path& urdf_dir,
                          std::span<const std::string> package_paths);

/// The <name> of the package.xml in `dir`, or nullopt when there is none or it has no name.
std::optional<std::string> PackageXmlName(const std::filesystem::path& dir);

}  // namespace proxsim
