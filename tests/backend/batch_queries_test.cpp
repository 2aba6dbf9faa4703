#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

namespace rtpro {
namespace batch_queries_test {

// Which primitives the scene holds: with spheres alone (instances of spheres included) the Embree
// backend traces scattered rays in packets, with triangles one by one.
enum class SceneKind { kMixed, kSpheresOnly };

// Batches must answer exactly what single rays answer, for every backend, coherence hint and
// scene kind: the renderer traces everything in batches, the references were made with single
// rays, and a ray's answer must not depend on which rays share its batch (tiles, threads, ranks).
class BatchQueries : public ::testing::TestWithParam<std::tuple<BackendKind, RayCoherence, SceneKind>> {
 protected:
  void SetUp() override { set_tracing_fp_mode(); }

  static RenderScene scene(std::uint32_t seed) {
    const bool triangles = std::get<2>(GetParam()) == SceneKind::kMixed;
    return test::random_mixed_scene(seed, 500, triangles ? 500 : 0, 10);
  }
};

std::vector<Ray> test_rays() {
  std::mt19937 rng(11);
  std::vector<Ray> rays;
  for (int i = 0; i < 3000; ++i) {
    Ray ray = test::random_ray(rng, 6.0f);
    if (i % 3 == 1) ray.tfar = 2.0f;  // segments, like shadow rays to a point light
    rays.push_back(ray);
  }
  rays[17].org.x = std::numeric_limits<float>::quiet_NaN();  // untraceable: a miss, not a crash
  rays[18].dir = Vec3(0.0f);
  return rays;
}

TEST_P(BatchQueries, IntersectMatchesSingleRays) {
  const auto [kind, coherence] = std::pair(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const RenderScene scene = BatchQueries::scene(7);
  const auto backend = make_backend(kind, scene, {});
  const std::vector<Ray> rays = test_rays();
  std::vector<Hit> hits(rays.size());
  backend->intersect(rays, hits, coherence);
  int found = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Hit single;
    ASSERT_EQ(hits[i].valid(), backend->intersect(rays[i], single)) << i;
    if (!hits[i].valid()) continue;
    ++found;
    EXPECT_EQ(hits[i].t, single.t) << i;
    EXPECT_EQ(hits[i].u, single.u) << i;
    EXPECT_EQ(hits[i].v, single.v) << i;
    EXPECT_EQ(hits[i].inst_id, single.inst_id) << i;
    EXPECT_EQ(hits[i].geom_id, single.geom_id) << i;
    EXPECT_EQ(hits[i].prim_id, single.prim_id) << i;
  }
  EXPECT_GT(found, 300);
  EXPECT_LT(found, 2900);
}

TEST_P(BatchQueries, OccludedMatchesSingleRays) {
  const auto [kind, coherence] = std::pair(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const RenderScene scene = BatchQueries::scene(8);
  const auto backend = make_backend(kind, scene, {});
  const std::vector<Ray> rays = test_rays();
  std::vector<std::uint8_t> occluded(rays.size(), 7);
  backend->occluded(rays, occluded, coherence);
  int blocked = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    ASSERT_LE(occluded[i], 1) << i;
    ASSERT_EQ(occluded[i] == 1, backend->occluded(rays[i])) << i;
    blocked += occluded[i];
  }
  EXPECT_GT(blocked, 300);
  EXPECT_LT(blocked, 2900);
}

INSTANTIATE_TEST_SUITE_P(Backends, BatchQueries,
                         ::testing::Combine(::testing::Values(BackendKind::kNative, BackendKind::kEmbree),
                                            ::testing::Values(RayCoherence::kCoherent, RayCoherence::kIncoherent),
                                            ::testing::Values(SceneKind::kMixed, SceneKind::kSpheresOnly)),
                         [](const auto& info) {
                           return std::string(backend_name(std::get<0>(info.param))) +
                                  (std::get<1>(info.param) == RayCoherence::kCoherent ? "_coherent" : "_incoherent") +
                                  (std::get<2>(info.param) == SceneKind::kMixed ? "_mixed" : "_spheres");
                         });

}  // namespace batch_queries_test
}  // namespace rtpro
