// Loads triangle meshes through Assimp, whatever the format (OBJ, STL, PLY,
// glTF, Collada ...), into one flat triangle soup in the mesh's own frame.
//
// Polygons are triangulated (fans), identical vertices merged and the node
// hierarchy's transforms baked into the vertices, so a multi-part file comes
// out as the parts where the file puts them; we do it ourselves rather than by
// Assimp's post-processing, which aborts on some malformed files. Points
// and lines are dropped. Every failure is the user's input, so it is an
// InputError that names the file: missing, unreadable or unparseable, without
// a single triangle, or with a non-finite vertex (after scaling).
//
// Assimp 5.2's PLY reader loops forever on a header without `end_header` and
// can crash on a truncated binary body, so PLY files get a header check of
// our own first (CheckPlyFile). Every file also passes PrescanMeshFile
// (mesh_prescan.h: a regular file, nesting depth, declared sizes) before
// Assimp sees it, and Assimp opens files only through MeshIOSystem.
#include "scene/mesh_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/version.h>

#include <assimp/Importer.hpp>
#include <array>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/input_error.h"
#include "core/input_limits.h"
#include "scene/mesh_prescan.h"

namespace proxsim {

namespace {

/// Bytes of a PLY scalar type; 0 for an unknown one.
std::size_t PlyTypeSize(const std::string& type) {
  static const std::map<std::string, std::size_t> kSizes = {
      {"char", 1},  {"int8", 1},   {"uchar", 1}, {"uint8", 1},   {"short", 2},  {"int16", 2},
      {"ushort", 2}, {"uint16", 2}, {"int", 4},   {"int32", 4},   {"uint", 4},   {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = kSizes.find(type);
  return it == kSizes.end() ? 0 : it->second;
}

/// For a file that starts with the PLY magic: throws InputError unless its
/// header is well formed — only the PLY keywords (format, comment, obj_info,
/// element NAME COUNT, property TYPE NAME, property list TYPE TYPE NAME,
/// end_header), printable text, known types — and (binary) the body holds at
/// least the bytes the header promises (lists counted as empty). Assimp 5.2's
/// PLY reader corrupts its heap on some malformed headers (found by fuzzing:
/// unknown keywords, control bytes in a property name), so nothing else
/// reaches it.
void CheckPlyFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) return;  // not PLY: Assimp decides

  // walk the header, adding up the least size of a binary body
  constexpr std::size_t kMaxHeaderBytes = 1 << 16;
  bool binary = false, ended = false, has_format = false, in_element = false;
  std::size_t element_count = 0, least_body_bytes = 0, least_ascii_entries = 0;
  int line_no = 1;
  const auto fail = [&](const std::string& why) {
    throw InputError(path + ":" + std::to_string(line_no) + ": PLY header: " + why);
  };
  while (static_cast<std::size_t>(in.tellg()) < kMaxHeaderBytes && std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    for (const char c : line) {
      if (static_cast<unsigned char>(c) < 0x20 && c != '\t') fail("a control byte in the header");
      if (static_cast<unsigned char>(c) >= 0x7f) fail("a non-ASCII byte in the header");
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") {
      ended = true;
      break;
    }
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      std::string format, version;
      words >> format >> version;
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        fail("format '" + format + "' (expected ascii, binary_little_endian or binary_big_endian)");
      binary = format != "ascii";
      has_format = true;
    } else if (keyword == "element") {
      std::string name;
      if (!(words >> name >> element_count)) fail("expected 'element NAME COUNT'");
      if (element_count > kMaxDeclaredElements) {
        fail("element '" + name + "' declares " + std::to_string(element_count) + " entries, beyond the limit of " +
             std::to_string(kMaxDeclaredElements));
      }
      in_element = true;
      least_ascii_entries += element_count;
    } else if (keyword == "property") {
      if (!in_element) fail("a property before any element");
      std::string type, name;
      words >> type;
      if (type == "list") {
        std::string count_type, item_type;
        words >> count_type >> item_type;
        if (PlyTypeSize(count_type) == 0 || PlyTypeSize(item_type) == 0)
          fail("list property of unknown types '" + count_type + "', '" + item_type + "'");
        type = count_type;  // at least the count, once per element
      } else if (PlyTypeSize(type) == 0) {
        throw InputError(path + ": PLY property of unknown type '" + type + "'");
      }
      if (!(words >> name)) fail("a property without a name");
      least_body_bytes += element_count * PlyTypeSize(type);
    } else {
      fail("unknown keyword '" + keyword + "'");
    }
  }
  if (ended && !has_format) fail("no format line");
  if (!ended) throw InputError(path + ": PLY header has no end_header line");

  // a body shorter than the header promises is truncated (an ASCII entry takes 2 bytes at least)
  if (!binary) {
    const std::streamoff body_start = in.tellg();
    in.seekg(0, std::ios::end);
    const auto body_bytes = static_cast<std::size_t>(in.tellg() - body_start);
    if (body_bytes < least_ascii_entries * 2) {
      throw InputError(path + ": PLY file is truncated (" + std::to_string(body_bytes) + " bytes of data for " +
                       std::to_string(least_ascii_entries) + " declared elements)");
    }
  }
  if (binary) {
    const std::streamoff body_start = in.tellg();
    in.seekg(0, std::ios::end);
    const auto body_bytes = static_cast<std::size_t>(in.tellg() - body_start);
    if (body_bytes < least_body_bytes) {
      throw InputError(path + ": PLY file is truncated (" + std::to_string(body_bytes) + " bytes of data, at least " +
                       std::to_string(least_body_bytes) + " expected)");
    }
  }
}

}  // namespace

std::shared_ptr<const TriangleMesh> LoadMeshFile(const std::string& path, const Vec3& scale) {
  // the file must exist and open before Assimp gets it, for a clear message
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw InputError(path + ": mesh file not found");
  if (std::filesystem::is_directory(path, error)) throw InputError(path + ": is a directory, expected a mesh file");
  PrescanMeshFile(path);  // a regular file, bounded nesting and sizes: before any parser
  if (!std::ifstream(path).good()) throw InputError(path + ": mesh file cannot be opened for reading");

  CheckPlyFile(path);

  // parse and validate only: Assimp 5.2's post-processing steps abort the
  // process (ai_assert) on some malformed files (Triangulate on faces of fewer
  // than three indices, found by fuzzing), so we triangulate, bake node
  // transforms and join identical vertices ourselves; ValidateDataStructure
  // refuses out-of-range indices and empty faces before we read them.
  Assimp::Importer importer;
  auto* io = new MeshIOSystem;  // the importer owns it
  importer.SetIOHandler(io);
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
    const std::string refused = io->refusal().empty() ? "" : "; " + io->refusal();
    throw InputError(path + ": cannot read the mesh file (" + importer.GetErrorString() + refused + ")");
  }

  // walk the node tree, baking each node's transform into the vertices of the
  // meshes it holds; faces of 3+ indices become triangle fans, points and
  // lines are dropped (a file of lines only reports "no triangles")
  auto mesh = std::make_shared<TriangleMesh>();
  std::map<std::array<float, 3>, std::uint32_t> vertex_index;  // identical vertices joined
  constexpr int kMaxDepth = kMaxNestingDepth;
  const auto add_node = [&](const auto& self, const aiNode& node, const aiMatrix4x4& X_parent, int depth) -> void {
    if (depth > kMaxDepth) throw InputError(path + ": node tree deeper than " + std::to_string(kMaxDepth));
    const aiMatrix4x4 X = X_parent * node.mTransformation;
    for (unsigned int k = 0; k < node.mNumMeshes; ++k) {
      const unsigned int m = node.mMeshes[k];
      if (m >= scene->mNumMeshes || !scene->mMeshes[m]) throw InputError(path + ": a node names a missing mesh");
      const aiMesh& part = *scene->mMeshes[m];
      std::vector<std::uint32_t> index_of(part.mNumVertices);
      for (unsigned int v = 0; v < part.mNumVertices; ++v) {
        const aiVector3D p = X * part.mVertices[v];
        const Vec3f p_O = Vec3(p.x, p.y, p.z).cwiseProduct(scale).cast<float>();
        if (!p_O.allFinite()) {
          throw InputError(path + ": vertex " + std::to_string(v) + " of mesh " + std::to_string(m) +
                           " is not finite (after scaling)");
        }
        // single-precision ray casting resolves no finer than ~1 cm beyond this
        if (p_O.cwiseAbs().maxCoeff() > kMaxCoordinate_m) {
          char where[96];
          std::snprintf(where, sizeof where, "(%g, %g, %g) m", p_O.x(), p_O.y(), p_O.z());
          throw InputError(path + ": vertex " + std::to_string(v) + " of mesh " + std::to_string(m) + " at " + where +
                           " (after scaling) is beyond the coordinate limit of ±" + std::to_string(int(kMaxCoordinate_m)) +
                           " m (rays are cast in single precision; docs/trust.md)");
        }
        const auto [it, added] = vertex_index.try_emplace({p_O.x(), p_O.y(), p_O.z()},
                                                           static_cast<std::uint32_t>(mesh->vertices_O.size()));
        if (added) mesh->vertices_O.push_back(p_O);
        index_of[v] = it->second;
      }
      for (unsigned int f = 0; f < part.mNumFaces; ++f) {
        const aiFace& face = part.mFaces[f];
        for (unsigned int i = 0; i < face.mNumIndices; ++i)
          if (face.mIndices[i] >= part.mNumVertices) throw InputError(path + ": a face names a missing vertex");
        for (unsigned int i = 1; i + 1 < face.mNumIndices; ++i) {
          mesh->triangles.push_back(
              {index_of[face.mIndices[0]], index_of[face.mIndices[i]], index_of[face.mIndices[i + 1]]});
        }
      }
    }
    for (unsigned int c = 0; c < node.mNumChildren; ++c)
      if (node.mChildren[c]) self(self, *node.mChildren[c], X, depth + 1);
  };
  add_node(add_node, *scene->mRootNode, aiMatrix4x4(), 0);
  if (mesh->triangles.empty()) throw InputError(path + ": the mesh file has no triangles");
  return mesh;
}

std::string AssimpVersion() {
  return std::to_string(aiGetVersionMajor()) + "." + std::to_string(aiGetVersionMinor()) + "." +
         std::to_string(aiGetVersionPatch());
}

}  // namespace proxsim
