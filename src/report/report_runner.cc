// MakeReport: runs `/usr/bin/python3 PROXSIM_REPORT_SCRIPT OUT --viewer-bundle
// PROXSIM_VIEWER_BUNDLE` (report/child_process.h), waits for it and returns its
// exit status. The paths are compile definitions set by cmake/viewer.cmake.
#include "report/report_runner.h"

#include <unistd.h>

#include <filesystem>
#include <map>
#include <iostream>
#include <string>
#include <vector>

#include "output/run_manifest.h"
#include "report/child_process.h"

namespace proxsim {
namespace {

#ifndef PROXSIM_REPORT_SCRIPT
#define PROXSIM_REPORT_SCRIPT PROXSIM_SOURCE_DIR "/report/make_report.py"
#endif
#ifndef PROXSIM_VIEWER_BUNDLE
#define PROXSIM_VIEWER_BUNDLE ""
#endif

// Debian's interpreter: its packages (python3-matplotlib) serve this one only.
constexpr const char* kPython = "/usr/bin/python3";
// make_report.py's exit code when it cannot import matplotlib or numpy.
constexpr int kMissingPlotting = 3;

// Runs the script with Debian's interpreter and returns its exit status,
// saying why on stderr when it is not 0.
int RunPythonScript(std::vector<std::string> args) {
  const int code = RunChildProcess(kPython, std::move(args), "the report script");
  if (code == kMissingPlotting) {
    std::cerr << "proxsim: the report needs matplotlib for " << kPython
              << " (apt-get install python3-matplotlib python3-numpy)\n";
  } else if (code != 0) {
    std::cerr << "proxsim: the report script failed (exit " << code << ")\n";
  }
  return code;
}

}  // namespace

namespace {

namespace fs = std::filesystem;

// size and modification time of a file: how a script's writes are told from a user's files
using FileStamp = std::pair<std::uintmax_t, fs::file_time_type>;

// The regular files under out_dir/sub (no link followed), relative to out_dir.
std::map<std::string, FileStamp> StampsUnder(const std::string& out_dir, const std::string& sub) {
  std::map<std::string, FileStamp> stamps;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(fs::path(out_dir) / sub, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_regular_file(ec) || it->is_symlink(ec)) continue;
    stamps[fs::relative(it->path(), out_dir, ec).generic_string()] = {it->file_size(ec), it->last_write_time(ec)};
  }
  return stamps;
}

}  // namespace

int MakeReport(const std::string& out_dir) {
  const std::string script = PROXSIM_REPORT_SCRIPT;
  const std::string bundle = PROXSIM_VIEWER_BUNDLE;

  // what the report needs, checked up front for a clear message
  if (access(kPython, X_OK) != 0) {
    std::cerr << "proxsim: cannot draw the report: " << kPython
              << " is missing (apt-get install python3 python3-matplotlib python3-numpy)\n";
    return 1;
  }
  std::error_code ec;
  if (!fs::is_regular_file(script, ec)) {
    std::cerr << "proxsim: cannot draw the report: the report script " << script << " is missing\n";
    return 1;
  }
  if (bundle.empty() || !fs::is_regular_file(bundle, ec)) {
    std::cerr << "proxsim: cannot write the viewer: its bundle " << (bundle.empty() ? "(unset)" : bundle)
              << " is missing (build the proxsim_viewer target: cmake --build --preset release)\n";
    return 1;
  }
  if (!fs::is_directory(out_dir, ec)) {
    std::cerr << "proxsim: cannot draw the report: " << out_dir << " is not a run directory\n";
    return 1;
  }

  // the script writes into report/: it must be a real folder, never a link to elsewhere
  const fs::path report = fs::path(out_dir) / "report";
  const fs::file_status report_status = fs::symlink_status(report, ec);
  if (fs::exists(report_status) && !fs::is_directory(report_status)) {
    std::cerr << "proxsim: cannot draw the report: " << report.string()
              << " is a symbolic link or not a folder; proxsim never writes through a link\n";
    return 1;
  }

  // the previous report's files go; the ones the script writes join the run's
  // manifest — a user's own files in report/ are neither removed nor listed
  RemoveFromRunManifest(out_dir, "report/");
  const std::map<std::string, FileStamp> before = StampsUnder(out_dir, "report");
  const int status = RunPythonScript({kPython, script, out_dir, "--viewer-bundle", bundle});
  if (status == 0) {
    std::vector<std::string> written;
    for (const auto& [path, stamp] : StampsUnder(out_dir, "report")) {
      const auto old = before.find(path);
      if (old == before.end() || old->second != stamp) written.push_back(path);
    }
    AddToRunManifest(out_dir, written);
  }
  return status;
}

namespace {

// Runs one of the report scripts that draw from a folder's files (report/NAME), saying what it draws when it cannot.
int RunFolderScript(const char* name, const char* what, const std::string& out_dir) {
  const std::string script = std::string(PROXSIM_SOURCE_DIR) + "/report/" + name;
  std::error_code ec;
  if (access(kPython, X_OK) != 0 || !std::filesystem::is_regular_file(script, ec)) {
    std::cerr << "proxsim: cannot draw " << what << ": " << kPython << " or " << script << " is missing\n";
    return 1;
  }
  return RunPythonScript({kPython, script, out_dir});
}

}  // namespace

int MakeStudyReport(const std::string& out_dir) {
  return RunFolderScript("study_report.py", "the study's figures", out_dir);
}

int MakeFidelityReport(const std::string& out_dir) {
  return RunFolderScript("fidelity_report.py", "the fidelity figure", out_dir);
}

}  // namespace proxsim
