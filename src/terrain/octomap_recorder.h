// The 3D reconstruction: every reading the map takes (ray_evidence.h) also
// goes into an OctoMap occupancy octree (Hornung et al. 2013) at the map's
// resolution: a detection marks its point occupied and the ray before it
// free; a silent ray frees the voxels it crossed, under the same rule as the
// elevation grid (only rays steep enough for a flat floor to have answered).
// Written as OctoMap's binary tree (terrain/map.bt), which octovis opens.
// This is the only file that includes OctoMap.
//
// Frames: W world.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "terrain/ray_evidence.h"

namespace proxsim {

class OctomapRecorder {
 public:
  explicit OctomapRecorder(double resolution_m);
  ~OctomapRecorder();
  OctomapRecorder(const OctomapRecorder&) = delete;
  OctomapRecorder& operator=(const OctomapRecorder&) = delete;

  /// Inserts one reading's ray.
  void Add(const RayEvidence& evidence);

  /// Writes the tree as a .bt file (maximum-likelihood occupancy); throws std::runtime_error on failure.
  void WriteBinary(const std::string& path) const;

  /// Leaves of the tree, for tests and reports.
  std::size_t leaf_count() const;
  /// Whether the voxel holding p_W is known and occupied (for tests).
  bool IsOccupied(const Vec3& p_W) const;
  /// Whether the voxel holding p_W is known and free (for tests).
  bool IsFree(const Vec3& p_W) const;

  /// Forgets everything.
  void Clear();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace proxsim
