// A finished run as a ROS 2 bag (docs/ros2.md): runs the bag writer that
// ships with proxsim (python/proxsim/ros2_bag.py, written with PyPI's
// `rosbags`, pinned by python/requirements.txt) with the build's Python, as
// a child process.
#pragma once

#include <string>

namespace proxsim {

/// The exit code of the bag writer for bad input (a run file it cannot read).
constexpr int kRos2ExportBadInput = 2;

/// Checks, before anything is run, that `bag_dir` can be the bag's folder:
/// not empty, not a file, not a folder that holds anything, in a folder that
/// exists, and neither the run's folder `run_dir` (which may be still to
/// come) nor inside it: the bag is never among the run's own files.
/// Throws InputError naming it.
void CheckRos2Path(const std::string& bag_dir, const std::string& run_dir);

/// Writes the finished run in run_dir as a ROS 2 bag in bag_dir (whole, or
/// not at all); returns 0, kRos2ExportBadInput when a run file is
/// unreadable, else 1, with the reason on stderr.
int ExportRos2(const std::string& run_dir, const std::string& bag_dir);

}  // namespace proxsim
