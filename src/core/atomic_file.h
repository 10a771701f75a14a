// An output file that only appears under its real name once it is complete:
// it is written to "NAME.tmp" and renamed by Commit(). A run that fails or is
// killed leaves no file that looks finished. Write errors (a full disk, an
// unwritable folder) throw std::runtime_error naming the file.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

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
  std::string tmp_path_;
  std::FILE* file_ = nullptr;
};

/// Writes a whole file atomically.
void WriteFileAtomically(const std::string& path, std::string_view content);

}  // namespace proxsim
