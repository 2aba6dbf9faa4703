// How OBJ files get their normals, texture coordinates and colours (obj_assembly.h, obj_parser.h).
#include "rtpro/scene/mesh_loader.h"
#include "obj_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace rtpro {
namespace obj_assembly_test {

using test::corner_normal;
using test::kCubeFaces;
using test::kCubePositions;
using test::write_file;

Vec3 face_normal(const TriangleMesh& mesh, std::uint32_t t) {
  const TriangleIndices& tri = mesh.triangles[t];
  return normalize(cross(mesh.vertex(tri.v1) - mesh.vertex(tri.v0), mesh.vertex(tri.v2) - mesh.vertex(tri.v0)));
}

bool is_axis(const Vec3& n) {
  const Vec3 a = abs(n);
  return (a == Vec3(1, 0, 0)) || (a == Vec3(0, 1, 0)) || (a == Vec3(0, 0, 1));
}

TEST(ObjNormals, CubeWithoutSmoothingGroupIsFlatWithExactFaceNormals) {
  const LoadedMesh loaded = load_mesh_file(write_file("flat.obj", std::string(kCubePositions) + kCubeFaces));
  ASSERT_EQ(loaded.mesh.triangles.size(), 12u);
  EXPECT_TRUE(loaded.mesh.normals.empty());
  // Shading falls back to each triangle's face normal: exactly an axis, pointing out.
  for (std::uint32_t t = 0; t < 12; ++t) {
    const Vec3 n = face_normal(loaded.mesh, t);
    EXPECT_TRUE(is_axis(n)) << t;
    const Vec3 centre =
        (loaded.mesh.vertex(loaded.mesh.triangles[t].v0) + loaded.mesh.vertex(loaded.mesh.triangles[t].v2)) * 0.5f;
    EXPECT_GT(dot(n, centre - Vec3(0.5f, 0.5f, 0.5f)), 0.0f) << t;
  }
}

TEST(ObjNormals, SmoothingGroupOneRoundsTheCubeAndFlatOverrideUndoesIt) {
  const std::string smooth_cube = std::string(kCubePositions) + "s 1\n" + kCubeFaces;
  const LoadedMesh smooth = load_mesh_file(write_file("smooth.obj", smooth_cube));
  ASSERT_EQ(smooth.mesh.normals.size(), 8u);
  EXPECT_TRUE(smooth.stats.normals_generated);
  // The corner (1,1,1) points out into its octant (area-weighted: the faces' diagonals decide
  // how much each face counts, so not exactly along the diagonal).
  const Vec3 corner = smooth.mesh.normals[6];
  EXPECT_GT(corner.x, 0.3f);
  EXPECT_GT(corner.y, 0.3f);
  EXPECT_GT(corner.z, 0.3f);

  const LoadedMesh flat = load_mesh_file(write_file("smooth.obj", smooth_cube), {NormalsMode::kFlat});
  EXPECT_TRUE(flat.mesh.normals.empty());
  const LoadedMesh forced =
      load_mesh_file(write_file("flat.obj", std::string(kCubePositions) + kCubeFaces), {NormalsMode::kSmooth});
  EXPECT_EQ(forced.mesh.normals, smooth.mesh.normals);
}

TEST(ObjNormals, SmoothingGroupsSmoothWithinAndSplitBetween) {
  // Top and front in group 1 share the edge y = 1, z = 1 smoothly; the side in group 2 meets
  // them at a crease; the bottom (s off) is flat.
  const std::string text =
      std::string(kCubePositions) + "s 1\nf 5 6 7 8\nf 3 4 8 7\ns 2\nf 2 3 7 6\ns off\nf 1 4 3 2\n";
  const LoadedMesh loaded = load_mesh_file(write_file("groups.obj", text));
  const TriangleMesh& mesh = loaded.mesh;
  ASSERT_EQ(mesh.triangles.size(), 8u);
  ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
  std::map<std::pair<int, int>, Vec3> normal_at;  // (group, position) -> normal
  const int group_of[8] = {1, 1, 1, 1, 2, 2, 0, 0};
  for (std::uint32_t t = 0; t < 8; ++t) {
    for (int c = 0; c < 3; ++c) {
      const TriangleIndices& tri = mesh.triangles[t];
      const std::uint32_t v = c == 0 ? tri.v0 : c == 1 ? tri.v1 : tri.v2;
      const Vec3 p = mesh.vertex(v);
      const int position = int(p.x) + 2 * int(p.y) + 4 * int(p.z);
      const Vec3 n = corner_normal(mesh, t, c);
      if (group_of[t] == 0) {
        EXPECT_EQ(n, face_normal(mesh, t));  // flat: its own face normal
        continue;
      }
      const auto [entry, inserted] = normal_at.emplace(std::make_pair(group_of[t], position), n);
      if (!inserted) {
        EXPECT_EQ(entry->second, n) << "a position shares one normal within its group";
      }
    }
  }
  // (1,1,1) is in groups 1 and 2 with different normals: a crease.
  EXPECT_NE(normal_at.at({1, 7}), normal_at.at({2, 7}));
  const Vec3 top_front = normal_at.at({1, 7});  // the +y and +z faces averaged
  EXPECT_EQ(top_front.x, 0.0f);
  EXPECT_GT(top_front.y, 0.3f);
  EXPECT_GT(top_front.z, 0.3f);
  EXPECT_EQ(normal_at.at({2, 7}), Vec3(1, 0, 0));
}

TEST(ObjNormals, FileModeNeedsTheFilesNormals) {
  const auto file = write_file("none.obj", std::string(kCubePositions) + kCubeFaces);
  EXPECT_THROW(load_mesh_file(file, {NormalsMode::kFile}), InputError);
  const LoadedMesh with = load_mesh_file(
      write_file("with.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 3\nf 1//1 2//1 3//1\n"), {NormalsMode::kFile});
  EXPECT_EQ(with.mesh.normals, (std::vector<Vec3>(3, Vec3(0, 0, 1))));
}

TEST(ObjAttributes, TextureCoordinatesSplitVerticesAtSeamsButNotSmoothNormals) {
  // Two triangles sharing an edge whose vertices have different uvs on each side.
  const LoadedMesh loaded = load_mesh_file(write_file("uv.obj", R"(s 1
v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0.5
vt 0 0
vt 1 0
vt 0 1
vt 0.5 0.5
vt 0.25 0.75
f 1/1 2/2 3/3
f 2/4 4/2 3/5
)"));
  const TriangleMesh& mesh = loaded.mesh;
  ASSERT_EQ(mesh.uvs.size(), mesh.vertices.size());
  EXPECT_EQ(mesh.vertices.size(), 6u);  // positions 2 and 3 split by the seam
  const TriangleIndices& first = mesh.triangles[0];
  const TriangleIndices& second = mesh.triangles[1];
  EXPECT_EQ(mesh.uvs[first.v1].u, 1.0f);
  EXPECT_EQ(mesh.uvs[second.v0].u, 0.5f);
  EXPECT_EQ(mesh.uvs[second.v2].v, 0.75f);
  // Across the seam the smooth normal is one normal: position 2 in both triangles.
  EXPECT_EQ(mesh.normals[first.v1], mesh.normals[second.v0]);
  EXPECT_EQ(mesh.normals[first.v2], mesh.normals[second.v2]);
}

TEST(ObjAttributes, VertexColoursAreKeptLinear) {
  const LoadedMesh loaded =
      load_mesh_file(write_file("colours.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0 0 0 1\nf 1 2 3\n"));
  ASSERT_EQ(loaded.mesh.colors.size(), 3u);
  EXPECT_EQ(loaded.mesh.colors[0], Color(1, 0, 0));
  EXPECT_NEAR(loaded.mesh.colors[1].y, 0.214f, 1e-3f);  // sRGB 0.5 decoded
  EXPECT_TRUE(loaded.mesh.uvs.empty());
  const LoadedMesh plain = load_mesh_file(write_file("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0 1\nf 1 2 3\n"));
  EXPECT_TRUE(plain.mesh.colors.empty());  // a 4th number is w, not a colour
}

TEST(ObjAttributes, KeyholePolygonFaceKeepsItsHole) {
  const LoadedMesh loaded = load_mesh_file(write_file("ring.obj", R"(v 0 0 0
v 4 0 0
v 4 4 0
v 0 4 0
v 1 1 0
v 1 3 0
v 3 3 0
v 3 1 0
f 1 2 3 4 1 5 6 7 8 5
)"));
  EXPECT_EQ(loaded.stats.concave_polygons, 1u);
  double area = 0;
  for (std::uint32_t t = 0; t < loaded.mesh.triangles.size(); ++t) {
    const TriangleIndices& tri = loaded.mesh.triangles[t];
    area += 0.5 * length(cross(loaded.mesh.vertex(tri.v1) - loaded.mesh.vertex(tri.v0),
                               loaded.mesh.vertex(tri.v2) - loaded.mesh.vertex(tri.v0)));
    const Vec3 centre = (loaded.mesh.vertex(tri.v0) + loaded.mesh.vertex(tri.v1) + loaded.mesh.vertex(tri.v2)) / 3.0f;
    EXPECT_FALSE(centre.x > 1 && centre.x < 3 && centre.y > 1 && centre.y < 3) << "a triangle in the hole";
  }
  EXPECT_NEAR(area, 12.0, 1e-5);
}

TEST(ObjAttributes, PolygonsKeepTheirPlaceBetweenMaterialsAndNormals) {
  // A polygon before a usemtl and a triangle after it: each keeps its own material and normals.
  write_file("two.mtl", "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\n");
  const LoadedMesh loaded = load_mesh_file(write_file("two.obj", R"(mtllib two.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vn 0 0 1
vn 0 0 -1
usemtl a
f 1//1 2//1 3//1 4//1
usemtl b
f 1//2 3//2 2//2
)"));
  const TriangleMesh& mesh = loaded.mesh;
  ASSERT_EQ(mesh.triangles.size(), 3u);
  ASSERT_EQ(mesh.triangle_materials.size(), 3u);
  EXPECT_EQ(mesh.triangle_materials, (std::vector<std::uint32_t>{0, 0, 1}));
  EXPECT_EQ(corner_normal(mesh, 1, 0), Vec3(0, 0, 1));
  EXPECT_EQ(corner_normal(mesh, 2, 0), Vec3(0, 0, -1));
}

}  // namespace obj_assembly_test
}  // namespace rtpro
