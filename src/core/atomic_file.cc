#include "core/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>

namespace proxsim {

namespace {
constexpr std::size_t kBufferBytes = 1 << 20;

[[noreturn]] void Fail(const std::string& what, const std::string& path) {
  throw std::runtime_error("cannot " + what + " " + path + ": " + std::strerror(errno));
}

// the folders whose commits are recorded, and what was committed there
std::mutex g_tracking_mutex;
std::map<std::string, std::set<std::string>>& Tracked() {
  static std::map<std::string, std::set<std::string>> tracked;
  return tracked;
}

void RecordCommit(const std::string& path) {
  std::lock_guard lock(g_tracking_mutex);
  for (auto& [dir, files] : Tracked()) {
    if (path.size() > dir.size() + 1 && path.starts_with(dir) && path[dir.size()] == '/') {
      files.insert(path.substr(dir.size() + 1));
    }
  }
}

std::string WithoutTrailingSlash(std::string dir) {
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  return dir;
}
}  // namespace

std::string ReplaceableFileProblem(const std::string& path) {
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0 || S_ISREG(info.st_mode) || S_ISLNK(info.st_mode)) return "";
  const char* kind = S_ISDIR(info.st_mode)  ? "a folder"
                     : S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode) ? "a device"
                     : S_ISFIFO(info.st_mode) ? "a FIFO"
                                              : "a socket";
  return path + ": " + kind + ", not a regular file; proxsim never replaces one (give the path of a new or regular file)";
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  // the folder, never through a link: O_NOFOLLOW refuses a folder that is one
  const std::size_t slash = path_.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path_.substr(0, slash));
  name_ = slash == std::string::npos ? path_ : path_.substr(slash + 1);
  tmp_name_ = name_ + ".tmp";
  dir_fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (dir_fd_ < 0) {
    if (errno == ELOOP || errno == ENOTDIR) {
      throw std::runtime_error("cannot create " + path_ + ": its folder " + dir +
                               " is a symbolic link or not a folder; proxsim never writes through a link");
    }
    Fail("open the folder of", path_);
  }
  // the final name: a device, FIFO or socket there is never replaced (a folder there makes the rename fail)
  if (struct stat final_info {}; ::fstatat(dir_fd_, name_.c_str(), &final_info, AT_SYMLINK_NOFOLLOW) == 0 &&
                                 !S_ISREG(final_info.st_mode) && !S_ISLNK(final_info.st_mode) &&
                                 !S_ISDIR(final_info.st_mode)) {
    ::close(dir_fd_);
    dir_fd_ = -1;
    throw std::runtime_error("cannot create " + path_ + ": " + ReplaceableFileProblem(path_));
  }
  // the temporary name, created afresh: never a planted link, never another file's content
  int fd = -1;
  for (int attempt = 0; attempt < 2 && fd < 0; ++attempt) {
    fd = ::openat(dir_fd_, tmp_name_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd >= 0 || errno != EEXIST) break;
    struct stat info {};
    if (::fstatat(dir_fd_, tmp_name_.c_str(), &info, AT_SYMLINK_NOFOLLOW) == 0 && !S_ISREG(info.st_mode)) {
      ::close(dir_fd_);
      dir_fd_ = -1;
      throw std::runtime_error("cannot create " + path_ + ".tmp: it exists and is a symbolic link or not a "
                               "regular file; proxsim never writes through one (remove it)");
    }
    ::unlinkat(dir_fd_, tmp_name_.c_str(), 0);  // a regular file left by a killed run
  }
  if (fd < 0) {
    const int open_errno = errno;
    ::close(dir_fd_);
    dir_fd_ = -1;
    errno = open_errno;
    Fail("create", path_ + ".tmp");
  }
  file_ = ::fdopen(fd, "wb");
  if (file_ == nullptr) {
    ::close(fd);
    ::unlinkat(dir_fd_, tmp_name_.c_str(), 0);
    ::close(dir_fd_);
    dir_fd_ = -1;
    Fail("create", path_ + ".tmp");
  }
  std::setvbuf(file_, nullptr, _IOFBF, kBufferBytes);
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) {
    std::fclose(file_);
    ::unlinkat(dir_fd_, tmp_name_.c_str(), 0);
  }
  if (dir_fd_ >= 0) ::close(dir_fd_);
}

void AtomicFile::Write(std::string_view text) {
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) Fail("write", path_ + ".tmp");
}

void AtomicFile::Write(char c) {
  if (std::fputc(c, file_) == EOF) Fail("write", path_ + ".tmp");
}

void AtomicFile::Commit() {
  // fclose flushes; a full disk often shows only here
  const bool flushed = std::fflush(file_) == 0 && !std::ferror(file_);
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) {
    const int write_errno = errno;
    ::unlinkat(dir_fd_, tmp_name_.c_str(), 0);
    errno = write_errno;
    Fail("write", path_ + ".tmp");
  }
  // renameat replaces whatever holds the final name (a link included) without following it
  if (::renameat(dir_fd_, tmp_name_.c_str(), dir_fd_, name_.c_str()) != 0) {
    const int rename_errno = errno;
    ::unlinkat(dir_fd_, tmp_name_.c_str(), 0);
    errno = rename_errno;
    Fail("rename into place", path_);
  }
  RecordCommit(path_);
}

void WriteFileAtomically(const std::string& path, std::string_view content) {
  AtomicFile file(path);
  file.Write(content);
  file.Commit();
}

void TrackCommitsUnder(const std::string& dir) {
  std::lock_guard lock(g_tracking_mutex);
  Tracked()[WithoutTrailingSlash(dir)].clear();
}

std::vector<std::string> CommittedUnder(const std::string& dir) {
  std::lock_guard lock(g_tracking_mutex);
  const auto it = Tracked().find(WithoutTrailingSlash(dir));
  if (it == Tracked().end()) return {};
  return {it->second.begin(), it->second.end()};
}

void StopTrackingCommits(const std::string& dir) {
  std::lock_guard lock(g_tracking_mutex);
  Tracked().erase(WithoutTrailingSlash(dir));
}

}  // namespace proxsim
