#include "core/output_folder.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "core/input_error.h"

namespace proxsim {

namespace {

namespace fs = std::filesystem;

// The folder's entries other than the lock file; "." and ".." aside.
std::vector<std::string> EntriesOf(int dir_fd) {
  std::vector<std::string> names;
  const int fd = ::dup(dir_fd);
  DIR* dir = fd >= 0 ? ::fdopendir(fd) : nullptr;
  if (dir == nullptr) {
    if (fd >= 0) ::close(fd);
    return names;
  }
  ::rewinddir(dir);
  while (const dirent* entry = ::readdir(dir)) {
    const std::string name = entry->d_name;
    if (name != "." && name != ".." && name != OutputFolder::kLockName) names.push_back(name);
  }
  ::closedir(dir);
  return names;
}

std::string ReadSmall(int fd) {
  char text[256] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  std::string holder(text, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!holder.empty() && (holder.back() == '\n' || holder.back() == '\0')) holder.pop_back();
  return holder.empty() ? "another proxsim process" : holder;
}

}  // namespace

OutputFolder::OutputFolder(const std::string& dir, const ClaimOptions& options) {
  const std::string flag = options.command == "plot" ? "the folder" : "--out";
  if (dir.empty()) throw InputError(flag + ": an empty path; give the folder for the " + options.command + "'s files");

  // "/" and the home folder: never a run's folder, whatever --force says
  std::error_code ec;
  const fs::path given(dir);
  const fs::path resolved = fs::weakly_canonical(fs::absolute(given, ec), ec);
  const char* home = std::getenv("HOME");
  const bool is_home = home != nullptr && *home != '\0' && resolved == fs::weakly_canonical(fs::path(home), ec);
  if (resolved == resolved.root_path() || is_home) {
    throw InputError(flag + " " + dir + ": refused, it is " + (is_home ? "the home folder" : "the root folder") +
                     "; a " + options.command + " writes and removes files in its folder: give a folder of its own");
  }

  if (options.create) fs::create_directories(given);  // a filesystem_error (exit 1) when impossible
  path_ = fs::canonical(given).string();               // resolved once, no link below it from here on
  dir_fd_ = ::open(path_.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (dir_fd_ < 0) throw std::runtime_error("cannot open the output folder " + path_ + ": " + std::strerror(errno));

  // the lock first: a second process gets "in use", not "not ours"
  for (int attempt = 0; attempt < 8 && lock_fd_ < 0; ++attempt) {
    const int fd = ::openat(dir_fd_, kLockName, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) {
      const int open_errno = errno;
      ::close(dir_fd_);
      throw std::runtime_error("cannot create the lock file " + path_ + "/" + kLockName + ": " +
                               std::strerror(open_errno) + (open_errno == ELOOP ? " (it is a symbolic link)" : ""));
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const std::string holder = ReadSmall(fd);
      ::close(fd);
      ::close(dir_fd_);
      throw InputError(dir + ": in use by " + holder + " (lock " + path_ + "/" + kLockName +
                       "); wait for it to end or give another folder");
    }
    // the holder before us may have removed the file we opened: lock the one under the name
    struct stat opened {}, named {};
    if (::fstat(fd, &opened) == 0 && ::fstatat(dir_fd_, kLockName, &named, AT_SYMLINK_NOFOLLOW) == 0 &&
        opened.st_ino == named.st_ino && opened.st_dev == named.st_dev) {
      lock_fd_ = fd;
    } else {
      ::close(fd);
    }
  }
  if (lock_fd_ < 0) {
    ::close(dir_fd_);
    throw std::runtime_error("cannot lock the output folder " + path_ + " (its lock file keeps changing)");
  }
  const std::string holder = "pid " + std::to_string(::getpid()) + ": proxsim " + options.command + "\n";
  if (::ftruncate(lock_fd_, 0) != 0 || ::pwrite(lock_fd_, holder.data(), holder.size(), 0) < 0) {
    // the lock holds without its text; only the message of a second process is poorer
  }

  // a folder with anything in it must be a previous output of ours
  if (options.check_contents && !options.force) {
    const std::vector<std::string> entries = EntriesOf(dir_fd_);
    struct stat marker {};
    const bool ours = ::fstatat(dir_fd_, options.ours.c_str(), &marker, AT_SYMLINK_NOFOLLOW) == 0 &&
                      S_ISREG(marker.st_mode);
    if (!entries.empty() && !ours) {
      const std::string example = entries.front();
      ::unlinkat(dir_fd_, kLockName, 0);
      ::close(lock_fd_);
      ::close(dir_fd_);
      throw InputError(flag + " " + dir + ": the folder holds " + std::to_string(entries.size()) + " entr" +
                       (entries.size() == 1 ? "y" : "ies") + " ('" + example + "'" + (entries.size() > 1 ? ", …" : "") +
                       ") and no " + options.ours + " of a previous proxsim " + options.command +
                       "; give an empty or new folder, or --force to write among them (they are never removed)");
    }
  }
}

OutputFolder::~OutputFolder() {
  // the name first, then the lock: a process that opened the old file re-checks (see above)
  ::unlinkat(dir_fd_, kLockName, 0);
  ::close(lock_fd_);
  ::close(dir_fd_);
}

}  // namespace proxsim
