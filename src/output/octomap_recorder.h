// The 3D reconstruction: every reading the map takes (ray_evidence.h) also
// goes into an OctoMap occupancy octree (Hornung et al. 2013) at the map's
// resolution: a detection marks its point occupied and the ray before it
// free; a silent ray frees the voxels it crossed, under the same rule as the
// elevation grid (only rays steep enough for a flat floor to have answered).
// Written as OctoMap's binary tree (terrain/map.bt), which octovis opens.
// This is the only file that includes OctoMap.
//
// Bounded over a long walk like the map: RetireOutside() takes the subtrees
// of 256 voxels a side (depth 8 of the tree's 16: 5.12 m at 2 cm) whose x-y
// square lies wholly outside the window, pruned, into a scratch file as
// OctoMap's own binary nodes, and frees them; WriteBinary() then writes the
// top of the tree itself around the held and the retired subtrees, node for
// node what OctoMap writes for the whole tree (a subtree retired and later
// grown again is written as it stands at the end).
//
// Frames: W world.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "core/geometry.h"
#include "knowledge/ray_evidence.h"

namespace proxsim {

class OctomapRecorder {
 public:
  explicit OctomapRecorder(double resolution_m);
  ~OctomapRecorder();
  OctomapRecorder(const OctomapRecorder&) = delete;
  OctomapRecorder& operator=(const OctomapRecorder&) = delete;

  /// Inserts one reading's ray; false (and counted in left_out()) when it
  /// reaches beyond the tree's keys, left out.
  bool Add(const RayEvidence& evidence);

  /// Writes the tree as a .bt file (maximum-likelihood occupancy); throws std::runtime_error on failure.
  void WriteBinary(const std::string& path) const;

  /// Moves the subtrees whose x-y square lies outside [lo_W, hi_W] out of memory.
  void RetireOutside(const Vec2& lo_W, const Vec2& hi_W);
  /// Readings left out because they reach beyond the tree's keys (±reach_m() of the origin).
  std::uint64_t left_out() const;
  /// How far from the origin OctoMap's 16-bit keys reach at this resolution, m.
  double reach_m() const;
  /// Subtrees retired so far.
  std::size_t retired_subtrees() const;
  /// Nodes held in memory.
  std::size_t node_count() const;

  /// Leaves of the tree, for tests and reports.
  std::size_t leaf_count() const;
  /// Whether the voxel holding p_W is known and occupied (for tests).
  bool IsOccupied(const Vec3& p_W) const;
  /// Whether the voxel holding p_W is known and free (for tests).
  bool IsFree(const Vec3& p_W) const;

  /// Forgets everything.
  void Clear();

 private:
  // WriteBinary() once subtrees were retired: the top of the tree written here
  void WriteWithRetired(const std::string& path) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace proxsim
