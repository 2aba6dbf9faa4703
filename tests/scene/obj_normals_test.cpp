// Normals of OBJ files: the file's own, and those smoothing groups make.
#include "rtpro/scene/mesh_loader.h"
#include "obj_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace rtpro {
namespace obj_normals_test {

using test::corner_normal;
using test::has_warning_containing;
using test::write_file;

void expect_unit_normals(const TriangleMesh& mesh) {
  ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
  for (const Vec3& n : mesh.normals) EXPECT_NEAR(length(n), 1.0f, 1e-6f);
}

TEST(ObjLoader, FileNormalsAreUsedAndSplitVerticesWhereCornersDiffer) {
  // Two triangles sharing the edge 2-3 but with different normals there: 4 positions, 6 vertices.
  const LoadedMesh loaded = load_mesh_file(write_file("normals.obj", R"(v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
vt 0 0
vn 0 0 2
vn 0 1 1
f 1//1 2//1 3//1
f 2/1/2 4/1/2 3/1/2
)"));
  EXPECT_FALSE(loaded.stats.normals_generated);
  EXPECT_EQ(loaded.mesh.vertices.size(), 6u);
  ASSERT_EQ(loaded.mesh.triangles.size(), 2u);
  expect_unit_normals(loaded.mesh);
  EXPECT_EQ(corner_normal(loaded.mesh, 0, 1), Vec3(0, 0, 1));
  const float s = 1.0f / std::sqrt(2.0f);
  EXPECT_NEAR(corner_normal(loaded.mesh, 1, 0).y, s, 1e-6f);
  EXPECT_NEAR(corner_normal(loaded.mesh, 1, 0).z, s, 1e-6f);
  EXPECT_EQ(loaded.mesh.vertex(loaded.mesh.triangles[1].v0), loaded.mesh.vertex(loaded.mesh.triangles[0].v1));
}

// A fan of four triangles around (0, 0, 0) bent into a shallow dome, with the file's tilted
// normals at the rim and a zero-length one at the centre: the centre vertex alone gets the normal
// of the faces around it (straight up, by symmetry), the rim keeps the file's (assimp's
// spider.obj rendered faceted for one such normal).
constexpr const char* kDome = R"(v 0 0 0.5
v 1 0 0
v 0 1 0
v -1 0 0
v 0 -1 0
vn 0 0 0
vn 1 0 1
vn 0 1 1
vn -1 0 1
vn 0 -1 1
f 1//1 2//2 3//3
f 1//1 3//3 4//4
f 1//1 4//4 5//5
f 1//1 5//5 2//2
)";

TEST(ObjLoader, AZeroNormalIsReplacedForItsVertexAloneWithAWarningAtItsLine) {
  const LoadedMesh loaded = load_mesh_file(write_file("dome.obj", kDome));
  EXPECT_TRUE(has_warning_containing(
      loaded.stats,
      "dome.obj:6: 1 vertex normal is zero or not finite; replaced by the normals of the faces around it"));
  expect_unit_normals(loaded.mesh);
  const Vec3 centre = corner_normal(loaded.mesh, 0, 0);
  EXPECT_NEAR(centre.z, 1.0f, 1e-6f);
  const float s = 1.0f / std::sqrt(2.0f);
  EXPECT_NEAR(corner_normal(loaded.mesh, 0, 1).x, s, 1e-6f);  // the file's, kept
  EXPECT_NEAR(corner_normal(loaded.mesh, 0, 1).z, s, 1e-6f);
  // PLY the same way: the one zero normal replaced, the others kept.
  const LoadedMesh ply = load_mesh_file(
      write_file("dome.ply",
                 "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                 "property float nx\nproperty float ny\nproperty float nz\nelement face 4\n"
                 "property list uchar int vertex_indices\nend_header\n"
                 "0 0 0.5 0 0 0\n1 0 0 1 0 1\n0 1 0 0 1 1\n-1 0 0 -1 0 1\n0 -1 0 0 -1 1\n"
                 "3 0 1 2\n3 0 2 3\n3 0 3 4\n3 0 4 1\n"));
  EXPECT_TRUE(has_warning_containing(ply.stats, "dome.ply: 1 vertex normal is zero or not finite"));
  ASSERT_EQ(ply.mesh.normals.size(), 5u);
  EXPECT_NEAR(ply.mesh.normals[0].z, 1.0f, 1e-6f);
  EXPECT_NEAR(ply.mesh.normals[1].x, s, 1e-6f);
}

TEST(ObjLoader, NormalsMissingOnSomeCornersAreSetAsideWithAWarning) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n";
  const LoadedMesh loaded = load_mesh_file(write_file("partial.obj", text));
  EXPECT_TRUE(has_warning_containing(loaded.stats, "the file's normals are not used"));
  EXPECT_TRUE(loaded.mesh.normals.empty());  // no smoothing group: flat
  const LoadedMesh smooth = load_mesh_file(write_file("partial.obj", "s 1\n" + text));
  EXPECT_TRUE(smooth.stats.normals_generated);
  expect_unit_normals(smooth.mesh);
}

// Two triangles sharing the edge (1,0,0)-(0,1,0), folded along it.
constexpr const char* kFold = R"(v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 1
)";

TEST(ObjLoader, OneSmoothingGroupSharesAndAveragesNormalsAlongTheEdge) {
  const LoadedMesh loaded = load_mesh_file(write_file("smooth.obj", std::string(kFold) + "s 1\nf 1 2 3\nf 2 4 3\n"));
  EXPECT_EQ(loaded.mesh.vertices.size(), 4u);
  expect_unit_normals(loaded.mesh);
  const Vec3 shared_in_first = corner_normal(loaded.mesh, 0, 1);
  const Vec3 shared_in_second = corner_normal(loaded.mesh, 1, 0);
  EXPECT_EQ(shared_in_first, shared_in_second);
  // The average of the two face normals, (0,0,1) and (-1,-1,1)/sqrt(3), weighted by area.
  const Vec3 face_a(0, 0, 1), face_b = normalize(Vec3(-1, -1, 1));
  EXPECT_GT(dot(shared_in_first, face_a), 0.5f);
  EXPECT_GT(dot(shared_in_first, face_b), 0.5f);
  EXPECT_LT(dot(shared_in_first, face_a), 0.999f);
}

TEST(ObjLoader, FlatFacesKeepTheirFaceNormals) {
  const LoadedMesh loaded =
      load_mesh_file(write_file("flat.obj", std::string(kFold) + "s 1\nf 1 2 3\ns off\nf 2 4 3\n"));
  EXPECT_EQ(loaded.mesh.vertices.size(), 6u);
  expect_unit_normals(loaded.mesh);
  EXPECT_EQ(corner_normal(loaded.mesh, 0, 1), Vec3(0, 0, 1));
  for (int corner = 0; corner < 3; ++corner) {
    const Vec3 n = corner_normal(loaded.mesh, 1, corner);
    EXPECT_NEAR(dot(n, normalize(Vec3(-1, -1, 1))), 1.0f, 1e-6f);
  }
}

TEST(ObjLoader, DifferentSmoothingGroupsDoNotShareVertices) {
  const LoadedMesh loaded =
      load_mesh_file(write_file("groups.obj", std::string(kFold) + "s 1\nf 1 2 3\ns 2\nf 2 4 3\n"));
  EXPECT_EQ(loaded.mesh.vertices.size(), 6u);
  EXPECT_EQ(corner_normal(loaded.mesh, 0, 1), Vec3(0, 0, 1));
}

TEST(ObjLoader, AnAllFlatMeshHasNoNormals) {
  const LoadedMesh loaded = load_mesh_file(write_file("allflat.obj", std::string(kFold) + "s off\nf 1 2 3\nf 2 4 3\n"));
  EXPECT_TRUE(loaded.mesh.normals.empty());
  EXPECT_FALSE(loaded.stats.normals_generated);
  EXPECT_EQ(loaded.mesh.vertices.size(), 4u);
}

TEST(ObjLoader, HugeAndTinyTrianglesStillGetUnitNormals) {
  // Cross products of 1e15 and 1e-19 coordinates square beyond and below float range.
  const LoadedMesh huge = load_mesh_file(write_file("huge.obj", "s 1\nv 0 0 0\nv 1e15 0 0\nv 0 1e15 0\nf 1 2 3\n"));
  const LoadedMesh tiny = load_mesh_file(write_file("tiny.obj", "s 1\nv 0 0 0\nv 1e-19 0 0\nv 0 1e-19 0\nf 1 2 3\n"));
  for (const LoadedMesh* loaded : {&huge, &tiny}) {
    ASSERT_EQ(loaded->mesh.normals.size(), 3u);
    for (const Vec3& n : loaded->mesh.normals) EXPECT_EQ(n, Vec3(0, 0, 1));
  }
}

}  // namespace obj_normals_test
}  // namespace rtpro
