// Tests of LoadMeshFile on small hand-made files in tests/data/meshes: the
// triangle counts, the scale, the node transforms of a glTF, and an
// InputError naming the file for every kind of bad input.
#include "scene/mesh_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/input_error.h"

namespace proxsim {
namespace {

std::string MeshPath(const std::string& name) { return std::string(PROXSIM_TEST_DATA_DIR) + "/meshes/" + name; }

/// Axis-aligned bounds of the loaded vertices.
Eigen::AlignedBox3f Bounds(const TriangleMesh& mesh) {
  Eigen::AlignedBox3f box;
  for (const Vec3f& v : mesh.vertices_O) box.extend(v);
  return box;
}

/// Expects LoadMeshFile to throw an InputError whose message names the file
/// and contains `what`.
void ExpectInputError(const std::string& path, const std::string& what, const Vec3& scale = Vec3::Ones()) {
  try {
    LoadMeshFile(path, scale);
    ADD_FAILURE() << "no InputError for " << path;
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }
}

TEST(MeshLoaderTest, ObjCubeHasTwelveTrianglesAndIsScaled) {
  const auto cube = LoadMeshFile(MeshPath("cube.obj"), Vec3(2, 3, 4));
  ASSERT_NE(cube, nullptr);
  EXPECT_EQ(cube->triangles.size(), 12u);
  EXPECT_EQ(cube->vertices_O.size(), 8u) << "identical vertices joined";
  const auto bounds = Bounds(*cube);
  EXPECT_TRUE(bounds.min().isApprox(Vec3f(-1, -1.5, -2)));
  EXPECT_TRUE(bounds.max().isApprox(Vec3f(1, 1.5, 2)));
  for (const auto& triangle : cube->triangles) {
    for (std::uint32_t index : triangle) EXPECT_LT(index, cube->vertices_O.size());
  }
}

TEST(MeshLoaderTest, ObjCubeKeepsOutwardWinding) {
  // every triangle's right-hand normal points away from the centre
  const auto cube = LoadMeshFile(MeshPath("cube.obj"), Vec3::Ones());
  for (const auto& t : cube->triangles) {
    const Vec3f a = cube->vertices_O[t[0]], b = cube->vertices_O[t[1]], c = cube->vertices_O[t[2]];
    const Vec3f normal = (b - a).cross(c - a);
    EXPECT_GT(normal.dot((a + b + c) / 3), 0.0f);
  }
}

TEST(MeshLoaderTest, StlTetrahedronHasFourTriangles) {
  const auto tetrahedron = LoadMeshFile(MeshPath("tetrahedron.stl"), Vec3::Constant(0.5));
  EXPECT_EQ(tetrahedron->triangles.size(), 4u);
  const auto bounds = Bounds(*tetrahedron);
  EXPECT_TRUE(bounds.min().isApprox(Vec3f(0, 0, 0)));
  EXPECT_TRUE(bounds.max().isApprox(Vec3f(0.5, 0.5, 0.5)));
}

TEST(MeshLoaderTest, AsciiAndBinaryPlyLoad) {
  const auto square = LoadMeshFile(MeshPath("square.ply"), Vec3::Ones());
  EXPECT_EQ(square->triangles.size(), 2u) << "the quad is triangulated";
  EXPECT_TRUE(Bounds(*square).max().isApprox(Vec3f(1, 1, 0)));
  const auto tetrahedron = LoadMeshFile(MeshPath("tetrahedron_binary.ply"), Vec3::Ones());
  EXPECT_EQ(tetrahedron->triangles.size(), 4u);
  EXPECT_TRUE(Bounds(*tetrahedron).max().isApprox(Vec3f(1, 1, 1)));
}

TEST(MeshLoaderTest, GltfNodeTransformsAreApplied) {
  // one triangle used by two nodes: as is, and scaled by 2 then moved to x = 5
  const auto mesh = LoadMeshFile(MeshPath("two_nodes.gltf"), Vec3::Ones());
  EXPECT_EQ(mesh->triangles.size(), 2u);
  const auto bounds = Bounds(*mesh);
  EXPECT_TRUE(bounds.min().isApprox(Vec3f(0, 0, 0)));
  EXPECT_TRUE(bounds.max().isApprox(Vec3f(7, 2, 0)));
}

TEST(MeshLoaderTest, MissingFileThrowsNamingIt) {
  ExpectInputError(MeshPath("no_such_mesh.obj"), "not found");
}

TEST(MeshLoaderTest, DirectoryThrowsNamingIt) { ExpectInputError(MeshPath(""), "directory"); }

TEST(MeshLoaderTest, UnparseableFilesThrowNamingThem) {
  ExpectInputError(MeshPath("broken.stl"), "cannot read");
  // PLY files that hang or crash Assimp 5.2 are caught before it sees them
  ExpectInputError(MeshPath("no_end_header.ply"), "end_header");
  ExpectInputError(MeshPath("truncated.ply"), "truncated");
}

TEST(MeshLoaderTest, FileWithoutTrianglesThrowsNamingIt) {
  ExpectInputError(MeshPath("lines_only.obj"), "no triangles");
}

TEST(MeshLoaderTest, NonFiniteVerticesThrowNamingTheFile) {
  ExpectInputError(MeshPath("non_finite.obj"), "not finite");
  // a finite file made infinite by its scale (beyond float range)
  ExpectInputError(MeshPath("cube.obj"), "not finite", Vec3(1e39, 1, 1));
}

}  // namespace
}  // namespace proxsim
