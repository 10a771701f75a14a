// A finished run as an MCAP file for Foxglove (docs/foxglove.md): runs the
// exporter that ships with proxsim (foxglove/src/export_mcap.mjs, written with
// the npm packages @mcap/core and @foxglove/schemas, pinned by
// foxglove/package-lock.json) with node, as a child process.
#pragma once

#include <string>

namespace proxsim {

/// The exit code of the exporter for bad input (a run file it cannot read).
constexpr int kMcapExportBadInput = 2;

/// Checks, before anything is run, that `mcap_path` can be the MCAP file: not
/// empty, not a folder, in a folder that exists or is `run_dir` (the run's
/// output folder, which a run creates), and neither one of the run's files
/// nor in one of its folders (RunFileNames(): its layout goes beside it too).
/// Throws InputError naming it.
void CheckMcapPath(const std::string& mcap_path, const std::string& run_dir);

/// Writes the finished run in run_dir to mcap_path (whole, or not at all);
/// returns 0, kMcapExportBadInput when a run file is unreadable, else 1,
/// with the reason on stderr.
int ExportMcap(const std::string& run_dir, const std::string& mcap_path);

}  // namespace proxsim
