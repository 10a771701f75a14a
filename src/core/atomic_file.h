// An output file that only appears under its real name once it is complete:
// it is written to "NAME.tmp" and renamed by Commit(). A run that fails or is
// killed leaves no file that looks finished. Write errors (a full disk, an
// unwritable folder) throw std::runtime_error naming the file.
//
// Never through a symbolic link (issue 23): the file's folder is opened with
// O_NOFOLLOW (a folder that is a link is refused), "NAME.tmp" is created with
// O_CREAT | O_EXCL | O_NOFOLLOW relative to that folder's descriptor (a link
// planted under that name is refused, never followed; a regular file left by
// a killed run is replaced) and renamed into place with renameat, which
// replaces a link under the final name rather than writing through it.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace proxsim {

class AtomicFile {
 public:
  /// Opens `path`.tmp for writing; throws if it cannot.
  explicit AtomicFile(std::string path);
  /// Removes the temporary file if Commit() was never called.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void Write(std::string_view text);
  void Write(char c);
  /// Flushes, closes and renames to the final name; throws on any I/O error.
  void Commit();

  const std::string& path() const { return path_; }
  std::FILE* stream() { return file_; }

 private:
  std::string path_;
  std::string name_, tmp_name_;  ///< within the folder
  int dir_fd_ = -1;              ///< the file's folder, opened without following a link
  std::FILE* file_ = nullptr;
};

/// "" when `path` may take a file proxsim writes: missing, a regular file or a
/// symbolic link (replaced, its target untouched); else why not, naming it: a
/// device, FIFO, socket or folder is never replaced (a device node renamed
/// over, as root, would break the machine).
std::string ReplaceableFileProblem(const std::string& path);

/// Writes a whole file atomically.
void WriteFileAtomically(const std::string& path, std::string_view content);

/// Starts recording the files committed under `dir` (a run's output folder,
/// as the writers name it): the run's manifest lists exactly those, so a
/// user's own files beside them are never taken for the run's.
void TrackCommitsUnder(const std::string& dir);
/// The files committed under `dir` since TrackCommitsUnder, relative to it.
std::vector<std::string> CommittedUnder(const std::string& dir);
/// Stops recording for `dir`.
void StopTrackingCommits(const std::string& dir);

}  // namespace proxsim
