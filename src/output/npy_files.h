// Writing NumPy .npy files (format 1.0) for the per-sensor array folders
// (zones/, echoes/): the header, a whole array at once, and a sensor's folder name.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/atomic_file.h"

namespace proxsim {

/// The .npy (format 1.0) header of an array of dtype `descr` and `shape`, padded to a multiple of 64 bytes.
std::string NpyArrayHeader(const char* descr, const std::vector<std::int64_t>& shape);

/// A sensor's name as a folder when it is a plain file name, else "sensor_INDEX".
std::string NpyFolderFor(const std::string& name, std::size_t index);

/// Writes `values` (row-major, little-endian as the machine's) as an array of `descr` and `shape` to `path`.
template <typename T>
void WriteNpyArray(const std::string& path, const char* descr, const std::vector<std::int64_t>& shape,
                   const std::vector<T>& values) {
  std::string bytes = NpyArrayHeader(descr, shape);
  bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  WriteFileAtomically(path, bytes);
}

}  // namespace proxsim
