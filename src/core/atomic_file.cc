#include "core/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace proxsim {

namespace {
constexpr std::size_t kBufferBytes = 1 << 20;

[[noreturn]] void Fail(const std::string& what, const std::string& path) {
  throw std::runtime_error("cannot " + what + " " + path + ": " + std::strerror(errno));
}
}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), tmp_path_(path_ + ".tmp") {
  file_ = std::fopen(tmp_path_.c_str(), "wb");
  if (file_ == nullptr) Fail("create", tmp_path_);
  std::setvbuf(file_, nullptr, _IOFBF, kBufferBytes);
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) {
    std::fclose(file_);
    std::remove(tmp_path_.c_str());
  }
}

void AtomicFile::Write(std::string_view text) {
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) Fail("write", tmp_path_);
}

void AtomicFile::Write(char c) {
  if (std::fputc(c, file_) == EOF) Fail("write", tmp_path_);
}

void AtomicFile::Commit() {
  // fclose flushes; a full disk often shows only here
  const bool flushed = std::fflush(file_) == 0 && !std::ferror(file_);
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) {
    const int write_errno = errno;
    std::remove(tmp_path_.c_str());
    errno = write_errno;
    Fail("write", tmp_path_);
  }
  if (std::rename(tmp_path_.c_str(), path_.c_str()) != 0) {
    const int rename_errno = errno;
    std::remove(tmp_path_.c_str());
    errno = rename_errno;
    Fail("rename into place", path_);
  }
}

void WriteFileAtomically(const std::string& path, std::string_view content) {
  AtomicFile file(path);
  file.Write(content);
  file.Commit();
}

}  // namespace proxsim
