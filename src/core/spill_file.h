// A scratch file for what a long run must keep but need not hold in memory
// (the terrain map's retired tiles, its track, the OctoMap's retired
// subtrees): an anonymous temporary file (std::tmpfile: no name in any folder,
// gone when closed or when the process ends), appended to during the run and
// read back at the end. I/O errors throw std::runtime_error naming `what`.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace proxsim {

class SpillFile {
 public:
  explicit SpillFile(std::string what);
  ~SpillFile();
  SpillFile(const SpillFile&) = delete;
  SpillFile& operator=(const SpillFile&) = delete;

  /// Appends bytes; returns the offset they start at.
  std::uint64_t Append(std::string_view bytes);
  /// Reads `n` bytes at `offset` into `out` (the file must hold them).
  void ReadAt(std::uint64_t offset, void* out, std::size_t n) const;
  std::uint64_t size() const { return size_; }
  /// Empties the file.
  void Clear();

 private:
  std::string what_;
  std::FILE* file_ = nullptr;
  std::uint64_t size_ = 0;
};

}  // namespace proxsim
