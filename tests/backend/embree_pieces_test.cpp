// A top-level mesh ordered in pieces (scene/mesh_pieces.h) is built by the Embree backend one
// piece at a time, each its own BVH under the top one: every ray must get exactly the answer of
// the same mesh built whole, reported as the mesh's own hit (its geometry and triangle number, no
// instance), while the build holds less memory at once.
#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/scene/mesh_pieces.h"
#include "same_hit.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <random>
#include <variant>
#include <vector>

namespace rtpro {
namespace embree_pieces_test {

constexpr int kTriangles = 30000;  // 8 pieces of 4096 (the last 1328)

// Spheres, a mesh of scattered small triangles and instances of a prototype, the mesh ordered
// in pieces; `whole` keeps that order but builds the mesh in one.
RenderScene scene_in_pieces(bool whole) {
  RenderScene scene = test::random_mixed_scene(21, 200, kTriangles, 10);
  auto& mesh = std::get<TriangleMesh>(scene.top.geometries[1]);
  order_in_pieces(mesh, kMinPieceTriangles);
  if (whole) mesh.piece_triangles = 0;
  return scene;
}

class EmbreePieces : public ::testing::Test {
 protected:
  void SetUp() override { set_tracing_fp_mode(); }
};

TEST_F(EmbreePieces, EveryRayGetsTheWholeMeshsAnswer) {
  const RenderScene pieces = scene_in_pieces(false), whole = scene_in_pieces(true);
  ASSERT_EQ(std::get<TriangleMesh>(pieces.top.geometries[1]).piece_triangles, kMinPieceTriangles);
  const auto in_pieces = make_backend(BackendKind::kEmbree, pieces, {});
  const auto in_one = make_backend(BackendKind::kEmbree, whole, {});
  const std::vector<Ray> rays = test::scattered_rays(4, 4000, 2.0f);
  int mesh_hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Hit a, b;
    in_pieces->intersect(rays[i], a);
    in_one->intersect(rays[i], b);
    test::expect_same_hit(a, b, i);
    mesh_hits += a.valid() && a.geom_id == 1 && a.inst_id == kInvalidId;
    EXPECT_EQ(in_pieces->occluded(rays[i]), in_one->occluded(rays[i])) << i;
  }
  EXPECT_GT(mesh_hits, 400);  // the pieces were hit, across the mesh's triangle numbers

  test::expect_same_batch_answers(*in_pieces, *in_one, rays);
}

TEST_F(EmbreePieces, TheBuildHoldsLessAtOnce) {
  const RenderScene pieces = scene_in_pieces(false), whole = scene_in_pieces(true);
  const BackendStats in_pieces = make_backend(BackendKind::kEmbree, pieces, {})->stats();
  const BackendStats in_one = make_backend(BackendKind::kEmbree, whole, {})->stats();
  ASSERT_GT(in_one.build_peak_bytes, 0u);
  // Embree's primitive records alone are 32 bytes a triangle: 0.96 MB whole, 0.13 MB a piece.
  EXPECT_LT(in_pieces.build_peak_bytes + 500'000, in_one.build_peak_bytes)
      << in_pieces.build_peak_bytes << " vs " << in_one.build_peak_bytes;
}

}  // namespace embree_pieces_test
}  // namespace rtpro
