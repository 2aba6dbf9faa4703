// make_surfaces groups plain triangle hits of flat meshes and of smooth ones apart (four flat ones
// skip the normals): a batch mixing both, hit for hit in any order, must still be make_surface's.
#include "surface_batch.h"

#include "test_scenes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

namespace rtpro {
namespace surface_batch_test {

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

void expect_same_vector(const Vec3& actual, const Vec3& expected, const char* what, int hit) {
  for (int axis = 0; axis < 3; ++axis)
    ASSERT_EQ(bits(actual[axis]), bits(expected[axis])) << what << " axis " << axis << " of hit " << hit;
}

// Hit records drawn on a flat and a smooth top-level mesh (some vertex normals zero), with misses
// among them, made as one batch and one at a time.
TEST(SurfaceBatch, FlatAndSmoothMeshHitsInOneBatchAreMakeSurfaceOfEachHit) {
  std::mt19937 rng(17);
  RenderScene scene = test::empty_scene();
  scene.top.geometries.emplace_back(test::random_triangles(rng, 100, 4.0f));
  TriangleMesh smooth = test::random_triangles(rng, 100, 4.0f);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (std::size_t i = 0; i < smooth.vertices.size(); ++i)
    smooth.normals.push_back(i % 5 == 0 ? Vec3() : Vec3{unit(rng), unit(rng), unit(rng)});
  scene.top.geometries.emplace_back(std::move(smooth));

  std::vector<Ray> rays;
  std::vector<Hit> hits;
  for (int i = 0; i < 4001; ++i) {
    Hit hit;
    if (i % 9 != 0) {
      hit.geom_id = static_cast<std::uint32_t>(rng() % 2);
      hit.prim_id = static_cast<std::uint32_t>(rng() % 100);
      hit.u = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
      hit.v = std::uniform_real_distribution<float>(0.0f, 1.0f - hit.u)(rng);
      hit.t = 1.0f;
    }
    rays.push_back(test::random_ray(rng, 4.0f));
    hits.push_back(hit);
  }
  SurfacePoint untouched;
  untouched.material = 12345;
  std::vector<SurfacePoint> batch(hits.size(), untouched);
  make_surfaces(scene, true, rays, hits, batch);

  int on_mesh[2] = {0, 0};
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const int hit = static_cast<int>(i);
    if (!hits[i].valid()) {
      ASSERT_EQ(batch[i].material, 12345u) << hit;
      continue;
    }
    ++on_mesh[hits[i].geom_id];
    const SurfacePoint one = make_surface(scene, rays[i], hits[i]);
    ASSERT_NO_FATAL_FAILURE(expect_same_vector(batch[i].position, one.position, "position", hit));
    ASSERT_NO_FATAL_FAILURE(expect_same_vector(batch[i].geometric_normal, one.geometric_normal, "normal", hit));
    ASSERT_NO_FATAL_FAILURE(expect_same_vector(batch[i].shading_normal, one.shading_normal, "shading", hit));
    ASSERT_EQ(batch[i].front_face, one.front_face) << hit;
    ASSERT_EQ(bits(batch[i].position_error), bits(one.position_error)) << hit;
    ASSERT_EQ(batch[i].material, one.material) << hit;
    ASSERT_EQ(batch[i].object_id, one.object_id) << hit;
  }
  EXPECT_GT(on_mesh[0], 1000) << "flat";
  EXPECT_GT(on_mesh[1], 1000) << "smooth";
}

}  // namespace surface_batch_test
}  // namespace rtpro
