#include "core/regular_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

namespace proxsim {

std::string RegularFileProblem(const std::string& path, unsigned long long max_bytes) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return path + ": not found (" + std::strerror(errno) + ")";
  if (S_ISDIR(info.st_mode)) return path + ": is a folder, expected a file";
  if (!S_ISREG(info.st_mode)) return path + ": not a regular file (a device, FIFO or socket is never read)";
  if (static_cast<unsigned long long>(info.st_size) > max_bytes) {
    return path + ": " + std::to_string(info.st_size) + " bytes, beyond the limit of " + std::to_string(max_bytes) +
           " bytes (docs/trust.md)";
  }
  return "";
}

}  // namespace proxsim
