// The output folder of one run or study, held for the whole of it (issue 23).
//
// Claiming a folder:
//   - refuses an empty path, "/" and the home folder outright, and a folder
//     that holds anything but a previous proxsim output (its manifest.json,
//     or a study's journal.jsonl) unless forced: a run must not scatter its
//     files among a user's;
//   - creates it, resolves it once to its real path (the writers then open
//     every file relative to that, never through a link further down);
//   - takes an exclusive lock: OUT/.proxsim.lock, flock(LOCK_EX | LOCK_NB),
//     holding "pid N: proxsim COMMAND". A second run or study into the same
//     folder fails at once with an InputError (exit 2) naming the holder. The
//     lock goes with the process (flock), so a killed run leaves no stale lock;
//     the file itself is removed when the folder is released.
#pragma once

#include <string>

namespace proxsim {

struct ClaimOptions {
  std::string command = "run";  ///< for the lock file and messages: "run", "study", "plot"
  bool create = true;           ///< create the folder when missing (plot: it must exist)
  bool check_contents = true;   ///< refuse a non-empty folder that is not a previous proxsim output
  bool force = false;           ///< accept a non-empty folder anyway (never "/" or the home folder)
  std::string ours = "manifest.json";  ///< the file that marks a previous output of this command
};

class OutputFolder {
 public:
  /// Claims `dir` (see above); throws InputError when refused or held by another process.
  OutputFolder(const std::string& dir, const ClaimOptions& options);
  /// Removes the lock file and releases the lock.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  /// The folder's real path (no link in it): every output is named from it.
  const std::string& path() const { return path_; }

  static constexpr const char* kLockName = ".proxsim.lock";

 private:
  std::string path_;
  int dir_fd_ = -1;
  int lock_fd_ = -1;
};

}  // namespace proxsim
