#include "output/octomap_recorder.h"

#include <array>
#include <functional>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include <octomap/OcTree.h>

#include "core/atomic_file.h"
#include "core/spill_file.h"

namespace proxsim {

namespace {

octomap::point3d Point(const Vec3& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
}

using Node = octomap::OcTreeNode;

// The depth (from the root, of 16) of the subtrees that are retired whole.
constexpr unsigned kSubtreeDepth = 8;
constexpr unsigned kTreeDepth = 16;
constexpr std::int64_t kKeyCentre = 32768;  // OctoMap's key of coordinate 0

// A node's place at its depth: its key's top `depth` bits, per axis.
struct Prefix {
  std::uint32_t x = 0, y = 0, z = 0;
  Prefix Child(unsigned i) const { return {x * 2 + (i & 1), y * 2 + ((i >> 1) & 1), z * 2 + ((i >> 2) & 1)}; }
  Prefix Parent() const { return {x / 2, y / 2, z / 2}; }
  std::uint64_t Key() const { return (std::uint64_t{x} << 32) | (std::uint64_t{y} << 16) | z; }
};

// A subtree's root as its parent's binary node sees it: absent, a leaf (free or occupied) or inner.
enum class NodeKind : std::uint8_t { kInner, kLeaf };

// The record a retired subtree leaves in the scratch file before its bytes.
struct RetiredHeader {
  std::uint32_t x = 0, y = 0, z = 0;
  NodeKind kind = NodeKind::kInner;
  float log_odds = 0;        // a leaf's
  std::uint64_t nodes = 0;   // the subtree's nodes, its root included
  std::uint64_t bytes = 0;   // its binary nodes (an inner root only)
};

std::string HeaderBytes(const RetiredHeader& h) {
  std::string out(sizeof(RetiredHeader), '\0');
  std::memcpy(out.data(), &h, sizeof h);
  return out;
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
  // whether p is within the keys' reach (checked silently: OctoMap prints an error per point beyond it)
  bool Reaches(const Vec3& p) const {
    octomap::OcTreeKey key;
    return tree.coordToKeyChecked(Point(p), key);
  }
  std::uint64_t left_out = 0;  // readings beyond the keys' reach
  mutable octomap::OcTree tree;
  octomap::KeyRay keys;
  mutable bool dirty = false;
  // the retired subtrees, each a header and its binary nodes; and how many
  SpillFile retired{"the OctoMap tree"};
  std::size_t retired_count = 0;

  // merges children that agree, bottom up, within one subtree (what the
  // tree's prune() does there: the root of the tree is never pruned, a
  // subtree's root may be)
  void Prune(Node* node) {
    if (!tree.nodeHasChildren(node)) return;
    for (unsigned i = 0; i < 8; ++i) {
      if (tree.nodeChildExists(node, i)) Prune(tree.getNodeChild(node, i));
    }
    tree.pruneNode(node);
  }
  std::uint64_t CountNodes(const Node* node) const {
    std::uint64_t n = 1;
    for (unsigned i = 0; i < 8; ++i) {
      if (tree.nodeChildExists(node, i)) n += CountNodes(tree.getNodeChild(node, i));
    }
    return n;
  }
  // frees a node's descendants the only way OctoMap frees a children array:
  // by pruning, once every child is a leaf of one value
  void Collapse(Node* node) {
    if (!tree.nodeHasChildren(node)) return;
    for (unsigned i = 0; i < 8; ++i) {
      if (tree.nodeChildExists(node, i)) {
        Collapse(tree.getNodeChild(node, i));
      } else {
        tree.createNodeChild(node, i);
      }
      tree.getNodeChild(node, i)->setLogOdds(0.0f);
    }
    tree.pruneNode(node);
  }
  // the subtree roots at kSubtreeDepth under `node`, with the child indices leading to them
  template <class F>
  void ForEachSubtree(Node* node, unsigned depth, Prefix prefix, std::array<unsigned, kSubtreeDepth>& path, F&& f) {
    if (depth == kSubtreeDepth) {
      f(node, prefix, path);
      return;
    }
    for (unsigned i = 0; i < 8; ++i) {
      if (!tree.nodeChildExists(node, i)) continue;
      path[depth] = i;
      ForEachSubtree(tree.getNodeChild(node, i), depth + 1, prefix.Child(i), path, f);
    }
  }
  // x-y square of a subtree, world metres
  std::pair<Vec2, Vec2> Square(const Prefix& p) const {
    const double side_m = tree.getResolution() * (1u << (kTreeDepth - kSubtreeDepth));
    const Vec2 lo((static_cast<std::int64_t>(p.x) * 256 - kKeyCentre) * tree.getResolution(),
                  (static_cast<std::int64_t>(p.y) * 256 - kKeyCentre) * tree.getResolution());
    return {lo, lo + Vec2(side_m, side_m)};
  }
  // takes the subtree at `path` out of the tree, and the ancestors it leaves empty
  void Remove(const std::array<unsigned, kSubtreeDepth>& path) {
    std::array<Node*, kSubtreeDepth + 1> nodes{};
    nodes[0] = tree.getRoot();
    for (unsigned d = 0; d < kSubtreeDepth; ++d) nodes[d + 1] = tree.getNodeChild(nodes[d], path[d]);
    Collapse(nodes[kSubtreeDepth]);
    for (unsigned d = kSubtreeDepth; d > 0; --d) {
      Node* parent = nodes[d - 1];
      bool others = false;
      for (unsigned i = 0; i < 8; ++i) others = others || (i != path[d - 1] && tree.nodeChildExists(parent, i));
      if (others) {
        tree.deleteNodeChild(parent, path[d - 1]);
        return;
      }
      if (d == 1) {  // the root's last child: an empty tree
        tree.clear();
        return;
      }
      // a childless inner node would read as a pruned leaf: make it a leaf, and take it out in turn
      Collapse(parent);
    }
  }
};

OctomapRecorder::OctomapRecorder(double resolution_m) : impl_(std::make_unique<Impl>(resolution_m)) {}
OctomapRecorder::~OctomapRecorder() = default;

std::uint64_t OctomapRecorder::left_out() const { return impl_->left_out; }
double OctomapRecorder::reach_m() const { return impl_->tree.getResolution() * static_cast<double>(kKeyCentre); }

bool OctomapRecorder::Add(const RayEvidence& evidence) {
  const bool frees = evidence.bounds_height && evidence.free_end_m > evidence.free_begin_m;
  // beyond ±32768 voxels of the origin OctoMap has no key: left out and counted, once printed per point
  if ((frees && (!impl_->Reaches(evidence.free_begin_W()) || !impl_->Reaches(evidence.free_end_W()))) ||
      (evidence.detected && !impl_->Reaches(evidence.point_W()))) {
    ++impl_->left_out;
    return false;
  }
  if (frees) {
    impl_->Free(evidence.free_begin_W(), evidence.free_end_W());
  }
  if (evidence.detected) {
    impl_->tree.updateNode(Point(evidence.point_W()), true, /*lazy_eval=*/true);
    impl_->dirty = true;
  }
  return true;
}

namespace {

// The .bt header OctoMap's writeBinaryConst writes.
std::string BtHeader(const octomap::OcTree& tree, std::uint64_t nodes) {
  std::ostringstream out;
  out << "# Octomap OcTree binary file\n"
      << "# (feel free to add / change comments, but leave the first line as it is!)\n#\n"
      << "id " << tree.getTreeType() << "\n"
      << "size " << nodes << "\n"
      << "res " << tree.getResolution() << "\n"
      << "data\n";
  return out.str();
}

}  // namespace

void OctomapRecorder::WriteBinary(const std::string& path) const {
  if (impl_->retired_count > 0) {
    WriteWithRetired(path);
    return;
  }
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
  bytes << BtHeader(tree, tree.size());
  tree.writeBinaryData(bytes);
  if (!bytes) throw std::runtime_error("cannot write the OctoMap tree " + path);
  WriteFileAtomically(path, bytes.str());
}

void OctomapRecorder::WriteWithRetired(const std::string& path) const {
  Impl& m = *impl_;
  // the subtrees: those held (pruned as the tree's prune() would) and the
  // retired ones, the last retired where one was retired twice, the held one
  // where the robot came back
  struct Subtree {
    Node* held = nullptr;
    std::uint64_t offset = 0;  // of a retired one's bytes
    RetiredHeader header;
  };
  std::unordered_map<std::uint64_t, Subtree> subtrees;
  for (std::uint64_t at = 0; at < m.retired.size();) {
    Subtree s;
    m.retired.ReadAt(at, &s.header, sizeof s.header);
    s.offset = at + sizeof s.header;
    at = s.offset + s.header.bytes;
    subtrees[Prefix{s.header.x, s.header.y, s.header.z}.Key()] = s;
  }
  if (m.tree.getRoot() != nullptr) {
    std::array<unsigned, kSubtreeDepth> path{};
    m.ForEachSubtree(m.tree.getRoot(), 0, Prefix{}, path, [&](Node* node, const Prefix& prefix, const auto&) {
      m.Prune(node);
      Subtree s{node, 0, RetiredHeader{prefix.x, prefix.y, prefix.z,
                                       m.tree.nodeHasChildren(node) ? NodeKind::kInner : NodeKind::kLeaf,
                                       node->getLogOdds(), m.CountNodes(node), 0}};
      subtrees[prefix.Key()] = s;
    });
    m.dirty = false;
  }
  // the nodes above them, depth by depth: which exist, and which prune() makes
  // leaves (all eight children leaves of one value; never the root)
  struct Top {
    bool leaf = false;
    float log_odds = 0;
  };
  std::array<std::unordered_map<std::uint64_t, Top>, kSubtreeDepth> tops;
  for (const auto& [key, s] : subtrees) {
    Prefix p{s.header.x, s.header.y, s.header.z};
    for (int d = kSubtreeDepth - 1; d >= 0; --d) {
      p = p.Parent();
      tops[d].emplace(p.Key(), Top{});
    }
  }
  // a child's state as its parent's binary node writes it
  struct Child {
    bool exists = false, leaf = false;
    float log_odds = 0;
  };
  const auto child_of = [&](unsigned depth, const Prefix& p) {
    if (depth == kSubtreeDepth) {
      const auto it = subtrees.find(p.Key());
      if (it == subtrees.end()) return Child{};
      return Child{true, it->second.header.kind == NodeKind::kLeaf, it->second.header.log_odds};
    }
    const auto it = tops[depth].find(p.Key());
    return it == tops[depth].end() ? Child{} : Child{true, it->second.leaf, it->second.log_odds};
  };
  for (int d = kSubtreeDepth - 1; d >= 1; --d) {
    for (auto& [key, top] : tops[d]) {
      const Prefix p{static_cast<std::uint32_t>(key >> 32), static_cast<std::uint32_t>((key >> 16) & 0xFFFF),
                     static_cast<std::uint32_t>(key & 0xFFFF)};
      const Child first = child_of(d + 1, p.Child(0));
      bool collapsible = first.exists && first.leaf;
      for (unsigned i = 1; i < 8 && collapsible; ++i) {
        const Child c = child_of(d + 1, p.Child(i));
        collapsible = c.exists && c.leaf && c.log_odds == first.log_odds;
      }
      if (collapsible) top = Top{true, first.log_odds};
    }
  }
  // the nodes the file holds, then the file, depth first as writeBinaryNode goes
  const float occupied_log_odds = m.tree.getOccupancyThresLog();
  const std::function<std::uint64_t(unsigned, const Prefix&)> count = [&](unsigned depth, const Prefix& p) {
    std::uint64_t n = 1;
    const Child self = child_of(depth, p);
    if (self.leaf) return n;
    for (unsigned i = 0; i < 8; ++i) {
      const Prefix c = p.Child(i);
      if (depth + 1 == kSubtreeDepth) {
        const auto it = subtrees.find(c.Key());
        if (it != subtrees.end()) n += it->second.header.nodes;
      } else if (child_of(depth + 1, c).exists) {
        n += count(depth + 1, c);
      }
    }
    return n;
  };
  tops[0].emplace(Prefix{}.Key(), Top{});  // the root (never a leaf)
  AtomicFile file(path);
  file.Write(BtHeader(m.tree, count(0, Prefix{})));
  std::string bytes;
  const std::function<void(unsigned, const Prefix&)> emit = [&](unsigned depth, const Prefix& p) {
    unsigned char halves[2] = {0, 0};
    for (unsigned i = 0; i < 8; ++i) {
      const Child c = child_of(depth + 1, p.Child(i));
      // 2 bits per child, low bit first: 01 free leaf, 10 occupied leaf, 11 inner, 00 none
      const unsigned code = !c.exists ? 0u : !c.leaf ? 3u : c.log_odds >= occupied_log_odds ? 2u : 1u;
      halves[i / 4] = static_cast<unsigned char>(halves[i / 4] | (code << (2 * (i % 4))));
    }
    file.Write(std::string_view(reinterpret_cast<const char*>(halves), 2));
    for (unsigned i = 0; i < 8; ++i) {
      const Prefix c = p.Child(i);
      const Child child = child_of(depth + 1, c);
      if (!child.exists || child.leaf) continue;
      if (depth + 1 < kSubtreeDepth) {
        emit(depth + 1, c);
        continue;
      }
      const Subtree& s = subtrees.at(c.Key());
      if (s.held != nullptr) {
        std::ostringstream out(std::ios::binary);
        m.tree.writeBinaryNode(out, s.held);
        file.Write(out.str());
      } else {
        bytes.resize(s.header.bytes);
        m.retired.ReadAt(s.offset, bytes.data(), bytes.size());
        file.Write(bytes);
      }
    }
  };
  emit(0, Prefix{});
  file.Commit();
}

void OctomapRecorder::RetireOutside(const Vec2& lo_W, const Vec2& hi_W) {
  Impl& m = *impl_;
  if (m.tree.getRoot() == nullptr) return;
  std::vector<std::array<unsigned, kSubtreeDepth>> gone;
  std::array<unsigned, kSubtreeDepth> path{};
  m.ForEachSubtree(m.tree.getRoot(), 0, Prefix{}, path, [&](Node* node, const Prefix& prefix, const auto& at) {
    const auto [lo, hi] = m.Square(prefix);
    if (hi.x() > lo_W.x() && lo.x() < hi_W.x() && hi.y() > lo_W.y() && lo.y() < hi_W.y()) return;
    m.Prune(node);
    RetiredHeader header{prefix.x, prefix.y, prefix.z, NodeKind::kInner, node->getLogOdds(), m.CountNodes(node), 0};
    std::string bytes;
    if (m.tree.nodeHasChildren(node)) {
      std::ostringstream out(std::ios::binary);
      m.tree.writeBinaryNode(out, node);
      bytes = out.str();
    } else {
      header.kind = NodeKind::kLeaf;
    }
    header.bytes = bytes.size();
    m.retired.Append(HeaderBytes(header));
    m.retired.Append(bytes);
    ++m.retired_count;
    gone.push_back(at);
  });
  for (const auto& at : gone) m.Remove(at);
}

std::size_t OctomapRecorder::retired_subtrees() const { return impl_->retired_count; }

std::size_t OctomapRecorder::node_count() const { return impl_->tree.size(); }

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
  impl_->retired.Clear();
  impl_->retired_count = 0;
}

}  // namespace proxsim
