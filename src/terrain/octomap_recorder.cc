#include "terrain/octomap_recorder.h"

#include <sstream>
#include <stdexcept>

#include <octomap/OcTree.h>

#include "core/atomic_file.h"

namespace proxsim {

namespace {

octomap::point3d Point(const Vec3& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
}

}  // namespace

struct OctomapRecorder::Impl {
  explicit Impl(double resolution_m) : tree(resolution_m) {}
  // frees the voxels from a to b, b's own voxel excluded (OctoMap's ray convention)
  void Free(const Vec3& a, const Vec3& b) {
    if (!tree.computeRayKeys(Point(a), Point(b), keys)) return;  // outside the tree's range
    for (const octomap::OcTreeKey& key : keys) tree.updateNode(key, false, /*lazy_eval=*/true);
    dirty = true;
  }
  mutable octomap::OcTree tree;
  octomap::KeyRay keys;
  mutable bool dirty = false;
};

OctomapRecorder::OctomapRecorder(double resolution_m) : impl_(std::make_unique<Impl>(resolution_m)) {}
OctomapRecorder::~OctomapRecorder() = default;

void OctomapRecorder::Add(const RayEvidence& evidence) {
  if (evidence.bounds_height && evidence.free_end_m > evidence.free_begin_m) {
    impl_->Free(evidence.free_begin_W(), evidence.free_end_W());
  }
  if (evidence.detected) {
    impl_->tree.updateNode(Point(evidence.point_W()), true, /*lazy_eval=*/true);
    impl_->dirty = true;
  }
}

void OctomapRecorder::WriteBinary(const std::string& path) const {
  if (impl_->dirty) {
    // lazy updates leave the inner nodes stale: bring them up to date once
    impl_->tree.updateInnerOccupancy();
    impl_->tree.prune();  // merges children that agree: a smaller file, the same occupancy
    impl_->dirty = false;
  }
  // OctoMap's .bt layout as its writeBinaryConst writes it: the header, then
  // the nodes through writeBinaryData (a template compiled here). The
  // library's own writeBinaryConst is compiled without NDEBUG in Debian's
  // package and prints " done." on stderr at every call. The bytes go
  // through AtomicFile (never through a link), not an ofstream of our own.
  const octomap::OcTree& tree = impl_->tree;
  std::ostringstream bytes(std::ios::binary);
  bytes << "# Octomap OcTree binary file\n"
        << "# (feel free to add / change comments, but leave the first line as it is!)\n#\n"
        << "id " << tree.getTreeType() << "\n"
        << "size " << tree.size() << "\n"
        << "res " << tree.getResolution() << "\n"
        << "data\n";
  tree.writeBinaryData(bytes);
  if (!bytes) throw std::runtime_error("cannot write the OctoMap tree " + path);
  WriteFileAtomically(path, bytes.str());
}

std::size_t OctomapRecorder::leaf_count() const { return impl_->tree.getNumLeafNodes(); }

bool OctomapRecorder::IsOccupied(const Vec3& p_W) const {
  const octomap::OcTreeNode* node = impl_->tree.search(Point(p_W));
  return node != nullptr && impl_->tree.isNodeOccupied(node);
}

bool OctomapRecorder::IsFree(const Vec3& p_W) const {
  const octomap::OcTreeNode* node = impl_->tree.search(Point(p_W));
  return node != nullptr && !impl_->tree.isNodeOccupied(node);
}

void OctomapRecorder::Clear() {
  impl_->tree.clear();
  impl_->dirty = false;
}

}  // namespace proxsim
