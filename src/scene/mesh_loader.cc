// Loads triangle meshes through Assimp, whatever the format (OBJ, STL, PLY,
// glTF, Collada ...), into one flat triangle soup in the mesh's own frame.
//
// Assimp triangulates polygons, merges identical vertices and bakes the node
// hierarchy's transforms into the vertices (aiProcess_PreTransformVertices),
// so a multi-part file comes out as the parts where the file puts them. Points
// and lines are dropped. Every failure is the user's input, so it is an
// InputError that names the file: missing, unreadable or unparseable, without
// a single triangle, or with a non-finite vertex (after scaling).
//
// Assimp 5.2's PLY reader loops forever on a header without `end_header` and
// can crash on a truncated binary body, so PLY files get a header check of
// our own first (CheckPlyFile); other formats go to Assimp as they are.
#include "scene/mesh_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/input_error.h"

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
/// header ends with `end_header`, names only known types, and (binary) the body
/// holds at least the bytes the header promises (lists counted as empty).
void CheckPlyFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) return;  // not PLY: Assimp decides

  // walk the header, adding up the least size of a binary body
  constexpr std::size_t kMaxHeaderBytes = 1 << 16;
  bool binary = false, ended = false;
  std::size_t element_count = 0, least_body_bytes = 0;
  while (static_cast<std::size_t>(in.tellg()) < kMaxHeaderBytes && std::getline(in, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") {
      ended = true;
      break;
    }
    if (keyword == "format") {
      std::string format;
      words >> format;
      binary = format.rfind("binary", 0) == 0;
    } else if (keyword == "element") {
      std::string name;
      words >> name >> element_count;
    } else if (keyword == "property") {
      std::string type;
      words >> type;
      if (type == "list") words >> type;  // the list's count type: at least one per element
      if (PlyTypeSize(type) == 0) throw InputError(path + ": PLY property of unknown type '" + type + "'");
      least_body_bytes += element_count * PlyTypeSize(type);
    }
  }
  if (!ended) throw InputError(path + ": PLY header has no end_header line");

  // a binary body shorter than the header promises is truncated
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
  if (!std::ifstream(path).good()) throw InputError(path + ": mesh file cannot be opened for reading");

  CheckPlyFile(path);

  // parse (points and lines are skipped below, so that a file of lines only
  // reports "no triangles")
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices);
  if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
    throw InputError(path + ": cannot read the mesh file (" + importer.GetErrorString() + ")");
  }

  // gather every mesh's triangles into one soup, scaling the vertices
  auto mesh = std::make_shared<TriangleMesh>();
  for (unsigned int m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& part = *scene->mMeshes[m];
    const auto first_vertex = static_cast<std::uint32_t>(mesh->vertices_O.size());
    for (unsigned int v = 0; v < part.mNumVertices; ++v) {
      const aiVector3D& p = part.mVertices[v];
      const Vec3f p_O = Vec3(p.x, p.y, p.z).cwiseProduct(scale).cast<float>();
      if (!p_O.allFinite()) {
        throw InputError(path + ": vertex " + std::to_string(v) + " of mesh " + std::to_string(m) +
                         " is not finite (after scaling)");
      }
      mesh->vertices_O.push_back(p_O);
    }
    for (unsigned int f = 0; f < part.mNumFaces; ++f) {
      const aiFace& face = part.mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh->triangles.push_back({first_vertex + face.mIndices[0], first_vertex + face.mIndices[1],
                                 first_vertex + face.mIndices[2]});
    }
  }
  if (mesh->triangles.empty()) throw InputError(path + ": the mesh file has no triangles");
  return mesh;
}

}  // namespace proxsim
