// The manifest every run leaves in its folder (manifest.json): the files that
// run wrote there, each with its size, and a digest of its summary.json. The
// next run into the same folder removes exactly those files — a user's own
// files are never touched — and `proxsim plot` refuses a folder whose files
// do not agree with its manifest (files of two runs mixed).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace proxsim {

struct ManifestFile {
  std::string path;  ///< relative to the run folder, '/' separated
  std::uintmax_t bytes = 0;
  std::string digest;  ///< FNV-1a 64 of its bytes, hex; a file is removed only when size and digest agree
};

struct RunManifest {
  std::string summary_digest;  ///< FNV-1a 64 of summary.json, hex; empty when the run wrote none
  std::vector<ManifestFile> files;
};

/// The folder's manifest; nullopt when it has none (or it cannot be read).
std::optional<RunManifest> ReadRunManifest(const std::string& dir);

/// Removes every file the folder's manifest lists — only when it is still a
/// regular file of the listed size and digest, reached through real folders
/// (a folder that is a link is never entered) — the folders that leaves
/// empty, and the manifest itself. Nothing else is touched.
void RemovePreviousRun(const std::string& dir);

/// Writes manifest.json listing `paths` as they are now, with sizes and
/// digests (a path ending in '/' stands for the files this process committed
/// under that folder, core/atomic_file.h; paths that do not exist are skipped).
void WriteRunManifest(const std::string& dir, const std::vector<std::string>& paths);

/// Adds `paths` (as in WriteRunManifest) to the folder's manifest.
void AddToRunManifest(const std::string& dir, const std::vector<std::string>& paths);

/// Removes the files of the manifest under `subdir` (e.g. "report/") and drops them from it.
void RemoveFromRunManifest(const std::string& dir, const std::string& subdir);

/// Why the folder does not hold one run's files (a listed file missing or of
/// another size, a summary.json that is not the manifest's, a run output not
/// in the manifest); empty when it does. A folder without a manifest has none;
/// the report's files are not checked (plot draws them again).
std::vector<std::string> RunFolderProblems(const std::string& dir);

/// The names a run writes (files and folders), to spot one left by another run.
const std::vector<std::string>& RunOutputNames();

/// Every name a run may hold at the top of its folder: RunOutputNames() and
/// the files and folders beside them (columns.json, zones/, echoes/,
/// objects_poses.csv, manifest.json, the lock). An export never writes there.
const std::vector<std::string>& RunFileNames();

}  // namespace proxsim
