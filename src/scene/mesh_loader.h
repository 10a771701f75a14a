// Triangle meshes from files, through Assimp (OBJ, STL, PLY, glTF, Collada …).
#pragma once

#include <memory>
#include <string>

#include "scene/shape.h"

namespace proxsim {

/// Loads every triangle of every mesh in `path` (node transforms applied),
/// multiplies vertices by `scale`. Throws InputError naming the file when it is
/// missing, unreadable, has no triangles or has non-finite vertices.
std::shared_ptr<const TriangleMesh> LoadMeshFile(const std::string& path, const Vec3& scale);

/// The Assimp library's version, "major.minor.patch" (summary.json's versions).
std::string AssimpVersion();

}  // namespace proxsim
