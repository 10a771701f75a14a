// ExportRos2: runs `PYTHON -I PROXSIM_ROS2_BAG_WRITER RUN_DIR BAG_DIR` (paths
// set by cmake/python.cmake: the build's Python, the venv's with rosbags) and
// returns its exit status. -I: the writer imports only rosbags and numpy,
// whatever PYTHONPATH or the current folder hold.
#include "report/ros2_export.h"

#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "core/input_error.h"
#include "report/child_process.h"

namespace proxsim {
namespace {

#ifndef PROXSIM_PYTHON_PROGRAM
#define PROXSIM_PYTHON_PROGRAM "/usr/bin/python3"
#endif
#ifndef PROXSIM_ROS2_BAG_WRITER
#define PROXSIM_ROS2_BAG_WRITER PROXSIM_SOURCE_DIR "/python/proxsim/ros2_bag.py"
#endif

namespace fs = std::filesystem;

// `inner` is `outer` or lies below it, both taken as absolute and without `..`
// (through the links that exist: a link to the run's folder is the run's folder)
bool IsAtOrInside(const fs::path& inner, const fs::path& outer) {
  std::error_code ec;
  const fs::path a = fs::weakly_canonical(fs::absolute(inner, ec), ec);
  const fs::path b = fs::weakly_canonical(fs::absolute(outer, ec), ec);
  auto ai = a.begin();
  for (auto bi = b.begin(); bi != b.end(); ++bi, ++ai) {
    if (bi->empty()) continue;  // a trailing separator
    if (ai == a.end() || *ai != *bi) return false;
  }
  return true;
}

}  // namespace

void CheckRos2Path(const std::string& bag_dir, const std::string& run_dir) {
  if (bag_dir.empty()) throw InputError("--ros2: an empty path; give the folder to write the bag into");
  std::error_code ec;
  const fs::path bag(bag_dir);
  if (IsAtOrInside(bag, run_dir)) {
    throw InputError("--ros2 " + bag_dir + ": the run's folder " + run_dir +
                     " or a folder in it; the bag is not one of the run's files, give a folder beside the run");
  }
  if (fs::exists(fs::symlink_status(bag, ec)) && !fs::is_directory(bag, ec)) {
    throw InputError("--ros2 " + bag_dir + ": not a folder; give a new (or empty) folder for the bag");
  }
  if (fs::is_directory(bag, ec) && !fs::is_empty(bag, ec)) {
    throw InputError("--ros2 " + bag_dir + ": a folder that holds files; give a new (or empty) folder for the bag");
  }
  fs::path full = fs::absolute(bag, ec).lexically_normal();
  if (!full.has_filename()) full = full.parent_path();  // "bag/" is the folder bag
  const fs::path parent = full.parent_path();
  if (!fs::is_directory(parent, ec)) {
    throw InputError("--ros2 " + bag_dir + ": its folder " + parent.string() + " does not exist");
  }
}

int ExportRos2(const std::string& run_dir, const std::string& bag_dir) {
  const std::string python = PROXSIM_PYTHON_PROGRAM;
  const std::string writer = PROXSIM_ROS2_BAG_WRITER;
  std::error_code ec;
  // what the export needs, checked up front for a clear message
  if (access(python.c_str(), X_OK) != 0 || !fs::is_regular_file(writer, ec)) {
    std::cerr << "proxsim: cannot write the ROS 2 bag: " << python << " or the bag writer " << writer
              << " is missing (scripts/install-deps.sh makes .venv/ with rosbags; then configure again)\n";
    return 1;
  }
  const int code = RunChildProcess(python, {python, "-I", writer, run_dir, bag_dir}, "the ROS 2 bag writer");
  if (code != 0 && code != kRos2ExportBadInput) {
    std::cerr << "proxsim: the ROS 2 bag writer failed (exit " << code << ")\n";
  }
  return code;
}

}  // namespace proxsim
