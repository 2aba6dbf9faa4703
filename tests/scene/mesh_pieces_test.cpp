// order_in_pieces: a large mesh's triangles reordered so that each run of `piece_triangles` is a
// compact piece, every triangle kept with its material, and meshes it must not touch left alone.
#include "rtpro/scene/mesh_pieces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <tuple>
#include <vector>

namespace rtpro {
namespace mesh_pieces_test {

// An n × n grid of unit squares in z = 0, two triangles each, in shuffled order; each triangle's
// material is its number before the shuffle, so the test can follow it.
TriangleMesh shuffled_grid(int n, std::uint32_t seed) {
  TriangleMesh mesh;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) mesh.vertices.push_back({float(x), float(y), 0.0f});
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const auto a = std::uint32_t(y * (n + 1) + x), b = a + 1, c = a + std::uint32_t(n + 1), d = c + 1;
      mesh.triangles.push_back({a, b, d});
      mesh.triangles.push_back({a, d, c});
    }
  std::mt19937 rng(seed);
  std::shuffle(mesh.triangles.begin(), mesh.triangles.end(), rng);
  for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) mesh.triangle_materials.push_back(t);
  return mesh;
}

using Corner = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>;

std::vector<Corner> triangles_with_materials(const TriangleMesh& mesh) {
  std::vector<Corner> out;
  for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t)
    out.emplace_back(mesh.triangles[t].v0, mesh.triangles[t].v1, mesh.triangles[t].v2, mesh.triangle_materials[t]);
  std::sort(out.begin(), out.end());
  return out;
}

// The summed areas (in the grid's plane) of the boxes around each run's triangle centroids.
double summed_piece_area(const TriangleMesh& mesh, std::uint32_t piece) {
  double sum = 0.0;
  for (std::size_t first = 0; first < mesh.triangle_count(); first += piece) {
    BBox box;
    for (std::size_t t = first; t < std::min<std::size_t>(first + piece, mesh.triangle_count()); ++t) {
      const TriangleIndices& tri = mesh.triangles[t];
      box.extend((mesh.vertex(tri.v0) + mesh.vertex(tri.v1) + mesh.vertex(tri.v2)) / 3.0f);
    }
    sum += double(box.upper.x - box.lower.x) * double(box.upper.y - box.lower.y);
  }
  return sum;
}

TEST(MeshPieces, EveryTriangleKeepsItsMaterialAndEachRunIsACompactPiece) {
  TriangleMesh mesh = shuffled_grid(100, 3);  // 20,000 triangles: 5 pieces of 4096 (the last 3616)
  const std::vector<Corner> before = triangles_with_materials(mesh);
  const VertexArray vertices = mesh.vertices;
  const double shuffled_area = summed_piece_area(mesh, kMinPieceTriangles);

  order_in_pieces(mesh, kMinPieceTriangles);
  EXPECT_EQ(mesh.piece_triangles, kMinPieceTriangles);
  EXPECT_EQ(triangles_with_materials(mesh), before);
  ASSERT_EQ(mesh.vertices.size(), vertices.size());
  EXPECT_TRUE(std::equal(vertices.begin(), vertices.end(), mesh.vertices.begin(),
                         [](const auto& a, const auto& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }));
  // Centroids lie in [1/3, 99 + 2/3]²: pieces that tile the grid sum to about that square, where
  // runs of the shuffled order each span nearly all of it.
  const double grid_area = (99.0 + 1.0 / 3.0) * (99.0 + 1.0 / 3.0);
  EXPECT_GT(shuffled_area, 4.5 * grid_area);
  EXPECT_LT(summed_piece_area(mesh, kMinPieceTriangles), 1.01 * grid_area);
}

TEST(MeshPieces, SmallAndMovingMeshesAreLeftAlone) {
  TriangleMesh small = shuffled_grid(40, 7);  // 3,200 triangles: one piece
  const std::vector<std::uint32_t> small_order = small.triangle_materials;
  order_in_pieces(small, kMinPieceTriangles);
  EXPECT_EQ(small.piece_triangles, 0u);
  EXPECT_EQ(small.triangle_materials, small_order);

  TriangleMesh moving = shuffled_grid(100, 9);
  moving.vertex_steps = {moving.vertices, moving.vertices};
  const std::vector<std::uint32_t> moving_order = moving.triangle_materials;
  order_in_pieces(moving, kMinPieceTriangles);
  EXPECT_EQ(moving.piece_triangles, 0u);
  EXPECT_EQ(moving.triangle_materials, moving_order);
}

TEST(MeshPieces, APieceSizeBelowTheFloorIsRaisedToIt) {
  TriangleMesh mesh = shuffled_grid(100, 11);
  order_in_pieces(mesh, 10);
  EXPECT_EQ(mesh.piece_triangles, kMinPieceTriangles);
}

}  // namespace mesh_pieces_test
}  // namespace rtpro
