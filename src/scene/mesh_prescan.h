// What proxsim checks of a mesh file before Assimp parses it (issue 23):
// Assimp recurses once per level of a glTF or Collada node tree, its
// rapidjson and pugixml once per level of nesting, and it allocates what a
// file declares (2e9 vertices in a 45-byte OFF file) before reading it. So,
// first, without recursion and without trusting any count:
//   - the file is a regular file (not a FIFO, /dev/zero, a folder) of at most
//     kMaxMeshFileBytes;
//   - XML (Collada): elements nested at most kMaxNestingDepth deep;
//   - JSON (glTF, and a GLB's JSON chunk): nesting at most kMaxNestingDepth,
//     a node tree at most that deep and without cycles, and every buffer,
//     buffer view and accessor fitting the bytes really there;
//   - OFF: the declared vertex and face counts fit the file's bytes.
// Files Assimp opens on its own (a glTF's buffers, an OBJ's mtllib) go through
// MeshIOSystem, which refuses anything not a regular file of bounded size.
#pragma once

#include <assimp/DefaultIOSystem.h>

#include <string>

#include "core/regular_file.h"

namespace proxsim {

/// Throws InputError naming the file and the limit it passes; see above.
void PrescanMeshFile(const std::string& path);

/// Assimp's file access, refusing non-regular and oversized files (a FIFO
/// would block Assimp's open forever, /dev/zero would never end).
class MeshIOSystem : public Assimp::DefaultIOSystem {
 public:
  bool Exists(const char* path) const override;
  Assimp::IOStream* Open(const char* path, const char* mode = "rb") override;
  /// Why the last refused file was refused; empty when none was.
  const std::string& refusal() const { return refusal_; }

 private:
  std::string refusal_;
};

}  // namespace proxsim
