// Writing NumPy .npy files (format 1.0) for the per-sensor array folders
// (zones/, echoes/): the header and a whole array at once (a sensor's folder: SensorFolderName).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/text_fields.h"

namespace proxsim {

/// The .npy (format 1.0) header of an array of dtype `descr` and `shape`, padded to a multiple of 64 bytes.
std::string NpyArrayHeader(const char* descr, const std::vector<std::int64_t>& shape);


/// Throws std::runtime_error when `dir` (zones/, echoes/) or one of its
/// `folders` exists as a symbolic link or not a folder: files are written
/// below them by path, and a link there would take them outside the run's
/// folder. Called before the run writes anything, and again before the arrays.
void RefuseLinkedFolders(const std::string& dir, const std::vector<std::string>& folders);

/// RefuseLinkedFolders for the `.folder` of each of `sensors`.
template <typename Sensors>
void RefuseLinkedSensorFolders(const std::string& dir, const Sensors& sensors) {
  std::vector<std::string> folders;
  for (const auto& sensor : sensors) folders.push_back(sensor.folder);
  RefuseLinkedFolders(dir, folders);
}

/// Writes `values` (row-major, little-endian as the machine's) as an array of `descr` and `shape` to `path`.
template <typename T>
void WriteNpyArray(const std::string& path, const char* descr, const std::vector<std::int64_t>& shape,
                   const std::vector<T>& values) {
  std::string bytes = NpyArrayHeader(descr, shape);
  bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  WriteFileAtomically(path, bytes);
}

}  // namespace proxsim
