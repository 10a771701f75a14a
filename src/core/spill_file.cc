#include "core/spill_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <unistd.h>

namespace proxsim {

namespace {

[[noreturn]] void Fail(const std::string& what, const char* action) {
  throw std::runtime_error("cannot " + std::string(action) + " the scratch file of " + what + ": " + std::strerror(errno));
}

}  // namespace

SpillFile::SpillFile(std::string what) : what_(std::move(what)), file_(std::tmpfile()) {
  if (file_ == nullptr) Fail(what_, "create");
}

SpillFile::~SpillFile() { std::fclose(file_); }

std::uint64_t SpillFile::Append(std::string_view bytes) {
  const std::uint64_t offset = size_;
  if (std::fseek(file_, 0, SEEK_END) != 0 || std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) {
    Fail(what_, "write");
  }
  size_ += bytes.size();
  return offset;
}

void SpillFile::ReadAt(std::uint64_t offset, void* out, std::size_t n) const {
  // the stream's buffer holds what was appended last: flush it before reading the descriptor
  if (std::fflush(file_) != 0) Fail(what_, "flush");
  auto* bytes = static_cast<char*>(out);
  std::size_t done = 0;
  while (done < n) {
    const ssize_t got = ::pread(fileno(file_), bytes + done, n - done, static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) Fail(what_, "read");
    done += static_cast<std::size_t>(got);
  }
}

void SpillFile::Clear() {
  if (std::fflush(file_) != 0 || ::ftruncate(fileno(file_), 0) != 0) Fail(what_, "empty");
  size_ = 0;
}

}  // namespace proxsim
