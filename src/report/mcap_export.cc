// ExportMcap: runs `node PROXSIM_MCAP_EXPORTER RUN_DIR FILE` (paths set by
// cmake/foxglove.cmake) and returns its exit status.
#include "report/mcap_export.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <vector>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "output/run_manifest.h"
#include "report/child_process.h"

namespace proxsim {
namespace {

#ifndef PROXSIM_NODE_PROGRAM
#define PROXSIM_NODE_PROGRAM "/usr/bin/node"
#endif
#ifndef PROXSIM_MCAP_EXPORTER
#define PROXSIM_MCAP_EXPORTER PROXSIM_SOURCE_DIR "/foxglove/src/export_mcap.mjs"
#endif

namespace fs = std::filesystem;

}  // namespace

void CheckMcapPath(const std::string& mcap_path, const std::string& run_dir) {
  if (mcap_path.empty()) throw InputError("--mcap: an empty path; give the MCAP file to write");
  std::error_code ec;
  if (fs::is_directory(mcap_path, ec)) {
    throw InputError("--mcap " + mcap_path + ": a folder; give the MCAP file to write (e.g. run.mcap)");
  }
  if (const std::string problem = ReplaceableFileProblem(mcap_path); !problem.empty())
    throw InputError("--mcap " + problem);
  const fs::path parent = fs::path(mcap_path).parent_path();
  // compared as folders ("out" and "out/" alike)
  const bool comes = !parent.empty() &&
                     (parent / "").lexically_normal() == (fs::path(run_dir) / "").lexically_normal();
  if (!parent.empty() && !comes && !fs::is_directory(parent, ec)) {
    throw InputError("--mcap " + mcap_path + ": its folder " + parent.string() + " does not exist");
  }
  // never over the run's own files: its path inside the run's folder starts with none of their names
  const fs::path inside = fs::weakly_canonical(fs::absolute(mcap_path, ec), ec)
                              .lexically_relative(fs::weakly_canonical(fs::absolute(run_dir, ec), ec));
  if (!inside.empty() && *inside.begin() != "..") {
    const std::vector<std::string>& names = RunFileNames();
    if (std::find(names.begin(), names.end(), inside.begin()->string()) != names.end()) {
      throw InputError("--mcap " + mcap_path + ": one of the run's files (or in one of its folders) in " + run_dir +
                       "; give a file of its own");
    }
  }
}

int ExportMcap(const std::string& run_dir, const std::string& mcap_path) {
  const std::string node = PROXSIM_NODE_PROGRAM;
  const std::string exporter = PROXSIM_MCAP_EXPORTER;
  std::error_code ec;
  // what the export needs, checked up front for a clear message
  if (access(node.c_str(), X_OK) != 0) {
    std::cerr << "proxsim: cannot write the MCAP file: " << node << " is missing (scripts/install-deps.sh installs nodejs)\n";
    return 1;
  }
  const fs::path packages = fs::path(exporter).parent_path().parent_path() / "node_modules" / "@mcap" / "core";
  if (!fs::is_regular_file(exporter, ec) || !fs::is_directory(packages, ec)) {
    std::cerr << "proxsim: cannot write the MCAP file: the exporter " << exporter << " or its npm packages are "
              << "missing (build the proxsim_foxglove target: cmake --build --preset release)\n";
    return 1;
  }
  const int code = RunChildProcess(node, {node, exporter, run_dir, mcap_path}, "the MCAP exporter");
  if (code != 0 && code != kMcapExportBadInput) std::cerr << "proxsim: the MCAP exporter failed (exit " << code << ")\n";
  return code;
}

}  // namespace proxsim
