// hit_prefetch_pays counts the shading data of every group a hit can name, the prototypes'
// included, at every motion step, against kHitPrefetchFromBytes.
#include "hit_prefetch.h"

#include "test_scenes.h"

#include <gtest/gtest.h>

#include <random>

namespace rtpro {
namespace hit_prefetch_test {

TEST(HitPrefetch, PaysOnlyWhereTheShadingDataOutgrowsTheCache) {
  std::mt19937 rng(5);
  RenderScene scene = test::empty_scene();
  SphereSet spheres;
  spheres.spheres.resize(8);
  scene.top.geometries.emplace_back(std::move(spheres));
  scene.top.geometries.emplace_back(test::random_triangles(rng, 100, 1.0f));
  EXPECT_FALSE(hit_prefetch_pays(scene));

  // A mesh above the threshold, first at the top level, then only as an instance's prototype.
  const TriangleMesh large = test::random_triangles(rng, 20000, 1.0f);
  ASSERT_GT(large.memory_bytes(), kHitPrefetchFromBytes);
  RenderScene top = scene;
  top.top.geometries.emplace_back(large);
  EXPECT_TRUE(hit_prefetch_pays(top));
  RenderScene instanced = scene;
  instanced.prototypes.emplace_back().geometries.emplace_back(large);
  instanced.top.geometries.emplace_back(Instance{0, Affine::identity(), Affine::identity()});
  EXPECT_TRUE(hit_prefetch_pays(instanced));
}

TEST(HitPrefetch, CountsEveryMotionStepOfASphereSet) {
  RenderScene scene = test::empty_scene();
  SphereSet spheres;
  spheres.spheres.resize(1000);
  ASSERT_LT(spheres.spheres.size() * sizeof(Sphere), kHitPrefetchFromBytes);
  spheres.step_count = 32;
  spheres.center_steps.resize(spheres.spheres.size() * spheres.step_count);
  ASSERT_GT(spheres.center_steps.size() * sizeof(Vec3), kHitPrefetchFromBytes);
  scene.top.geometries.emplace_back(std::move(spheres));
  EXPECT_TRUE(hit_prefetch_pays(scene));
}

}  // namespace hit_prefetch_test
}  // namespace rtpro
