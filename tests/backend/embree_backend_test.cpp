// The Embree backend on hand-made scenes (each kept alive while its backend lives: the backend
// shares the scene's arrays) whose answers are known: sphere distances must be
// bit-identical to intersect_sphere's, triangle hits exact where the arithmetic is exact, and
// bad rays or budgets must become counted misses or RuntimeErrors, never an abort.
#include "rtpro/backend/backend.h"

#include "rtpro/core/error.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/core/ray.h"
#include "rtpro/geometry/sphere_intersect.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <thread>
#include <vector>

namespace rtpro {
namespace embree_backend_test {

constexpr float kInf = std::numeric_limits<float>::infinity();

RenderScene scene_with(std::vector<Geometry> top, std::vector<Group> prototypes = {}) {
  RenderScene scene = test::empty_scene();
  scene.top.geometries = std::move(top);
  scene.prototypes = std::move(prototypes);
  return scene;
}

SphereSet spheres(std::vector<Sphere> list) { return SphereSet{std::move(list)}; }

Ray make_ray(Vec3 org, Vec3 dir, float tnear = 0.0f, float tfar = kInf) { return Ray{org, tnear, dir, tfar}; }

// intersect_sphere's own answer for the interval (tnear, tfar].
std::optional<float> reference_t(const Sphere& s, const Ray& ray) {
  float t;
  if (!intersect_sphere(s.center, s.radius, ray.org, ray.dir, ray.tnear, ray.tfar, t)) return std::nullopt;
  return t;
}

// A unit right triangle in the z = 0 plane, two triangles forming the unit square.
TriangleMesh unit_square() {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
  return mesh;
}

class EmbreeBackendTest : public ::testing::Test {
 protected:
  void SetUp() override { set_tracing_fp_mode(); }
};

TEST_F(EmbreeBackendTest, SphereDistancesAreBitIdenticalToIntersectSphere) {
  const Sphere near_sphere{{0.1f, -0.2f, 3.0f}, 1.0f, 0};
  const Sphere far_small{{-3000.0f, 1000.0f, -20000.0f}, 0.001f, 0};
  const RenderScene scene = scene_with({spheres({near_sphere, far_small})});
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});

  const Vec3 to_far = far_small.center - Vec3(0.0f, 0.0f, -1.0f);
  const std::vector<std::pair<Ray, std::uint32_t>> cases = {
      {make_ray({0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, 1.0f}), 0},   // from outside
      {make_ray({0.1f, -0.2f, 3.3f}, {0.3f, 0.5f, -0.7f}), 0},  // from inside: far root
      {make_ray({1.1f, -5.0f, 3.0f}, {0.0f, 1.0f, 0.0f}), 0},   // tangent at x = 1.1
      {make_ray({0.0f, 0.0f, -1.0f}, normalize(to_far)), 1},    // far away, small
      {make_ray({0.0f, 0.0f, -1.0f}, to_far * 0.5f), 1},        // non-unit direction
  };
  const Sphere* list[] = {&near_sphere, &far_small};
  for (const auto& [ray, prim] : cases) {
    const std::optional<float> expected = reference_t(*list[prim], ray);
    Hit hit;
    const bool found = backend->intersect(ray, hit);
    ASSERT_EQ(found, expected.has_value()) << "prim " << prim;
    if (!found) continue;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(hit.t), std::bit_cast<std::uint32_t>(*expected));
    EXPECT_EQ(hit.prim_id, prim);
    EXPECT_EQ(hit.geom_id, 0u);
    EXPECT_EQ(hit.inst_id, kInvalidId);
    EXPECT_EQ(hit.u, 0.0f);
    EXPECT_EQ(hit.v, 0.0f);
  }
  EXPECT_EQ(backend->stats().rejected_rays, 0u);
}

TEST_F(EmbreeBackendTest, HitsExactlyAtTfarCountButNotBeyondIt) {
  const Sphere s{{0.0f, 0.0f, 5.0f}, 1.0f, 0};
  const RenderScene scene = scene_with({spheres({s})});
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  Hit hit;
  ASSERT_TRUE(backend->intersect(make_ray({0, 0, 0}, {0, 0, 1}), hit));
  ASSERT_EQ(hit.t, 4.0f);
  EXPECT_TRUE(backend->intersect(make_ray({0, 0, 0}, {0, 0, 1}, 0.0f, 4.0f), hit));
  EXPECT_FALSE(backend->intersect(make_ray({0, 0, 0}, {0, 0, 1}, 0.0f, std::nextafter(4.0f, 0.0f)), hit));
  // Ray starting inside the interval's open lower end: tnear = 4 skips the near root.
  ASSERT_TRUE(backend->intersect(make_ray({0, 0, 0}, {0, 0, 1}, 4.0f), hit));
  EXPECT_EQ(hit.t, 6.0f);
}

TEST_F(EmbreeBackendTest, EqualDistancesFollowTheTieRule) {
  // n identical spheres in one set, then the same sphere again in a second set: whatever order
  // Embree visits them in, geometry 0's primitive 0 must win.
  const Sphere s{{0.0f, 0.0f, 5.0f}, 1.0f, 0};
  for (std::size_t n : {2u, 5u, 9u, 33u}) {
    const RenderScene scene = scene_with({spheres(std::vector<Sphere>(n, s)), spheres({s})});
    const auto backend = make_backend(BackendKind::kEmbree, scene, {});
    for (int i = 0; i < 20; ++i) {
      const float x = -0.9f + 0.09f * static_cast<float>(i);
      Hit hit;
      ASSERT_TRUE(backend->intersect(make_ray({x, 0.1f, -3.0f}, {0, 0, 1}), hit));
      EXPECT_EQ(hit.geom_id, 0u) << n;
      EXPECT_EQ(hit.prim_id, 0u) << n;
    }
  }
}

TEST_F(EmbreeBackendTest, TrianglesReportTheirGroupIndexAndBarycentrics) {
  // Geometry 0 is an empty sphere set: ids must still be the group's indices.
  const RenderScene scene = scene_with({SphereSet{}, unit_square()});
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  Hit hit;
  ASSERT_TRUE(backend->intersect(make_ray({0.25f, 0.5f, -2.0f}, {0, 0, 1}), hit));
  EXPECT_FLOAT_EQ(hit.t, 2.0f);  // Embree divides with a refined reciprocal: a few ulps, not exact
  EXPECT_EQ(hit.geom_id, 1u);
  EXPECT_EQ(hit.prim_id, 0u);
  EXPECT_EQ(hit.inst_id, kInvalidId);
  EXPECT_NEAR(hit.u, 0.25f, 1e-6f);  // p = (1-u-v)·p0 + u·p1 + v·p2
  EXPECT_NEAR(hit.v, 0.5f, 1e-6f);

  ASSERT_TRUE(backend->intersect(make_ray({0.75f, 0.75f, 3.0f}, {0, 0, -1}), hit));  // back side
  EXPECT_FLOAT_EQ(hit.t, 3.0f);
  EXPECT_EQ(hit.prim_id, 1u);
  EXPECT_FALSE(backend->intersect(make_ray({1.5f, 0.5f, -2.0f}, {0, 0, 1}), hit));
}

TEST_F(EmbreeBackendTest, InstancedHitsNameTheInstanceAndThePrototypeGeometry) {
  Group prototype;
  prototype.geometries.emplace_back(unit_square());
  prototype.geometries.emplace_back(spheres({{{0.0f, 0.0f, 0.0f}, 0.5f, 0}, {{5.0f, 0.0f, 0.0f}, 0.5f, 0}}));
  // 90° about z then scale 2 then move to x = 10: the sphere of radius 0.5 at the prototype's
  // origin becomes a sphere of radius 1 at (10, 0, 0); prototype sphere 1 lands at (10, 10, 0).
  const Affine placement =
      compose(Affine::translate({10, 0, 0}), compose(Affine::scale({2, 2, 2}), Affine::rotate({0, 0, 1}, 90.0f)));
  const Instance instance{0, placement, *inverse(placement)};
  const RenderScene scene = scene_with({spheres({{{-10.0f, 0.0f, 0.0f}, 1.0f, 0}}), instance, instance}, {prototype});
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});

  Hit hit;
  ASSERT_TRUE(backend->intersect(make_ray({10.0f, 0.0f, -5.0f}, {0, 0, 1}), hit));
  EXPECT_NEAR(hit.t, 4.0f, 1e-5f);
  EXPECT_EQ(hit.inst_id, 1u);  // two identical instances: the lower id wins the tie
  EXPECT_EQ(hit.geom_id, 1u);
  EXPECT_EQ(hit.prim_id, 0u);

  ASSERT_TRUE(backend->intersect(make_ray({10.0f, 10.0f, -5.0f}, {0, 0, 1}), hit));
  EXPECT_NEAR(hit.t, 4.0f, 1e-5f);
  EXPECT_EQ(hit.geom_id, 1u);
  EXPECT_EQ(hit.prim_id, 1u);

  // The placement maps prototype (x, y, 0) to (10 - 2y, 2x, 0): prototype point (0.1, 0.6), inside
  // triangle 0 with u = 0.1, v = 0.6, appears at (8.8, 0.2), outside the instanced sphere.
  ASSERT_TRUE(backend->intersect(make_ray({8.8f, 0.2f, -5.0f}, {0, 0, 1}), hit));
  EXPECT_NEAR(hit.t, 5.0f, 1e-5f);
  EXPECT_EQ(hit.inst_id, 1u);
  EXPECT_EQ(hit.geom_id, 0u);
  EXPECT_EQ(hit.prim_id, 0u);
  EXPECT_NEAR(hit.u, 0.1f, 1e-5f);
  EXPECT_NEAR(hit.v, 0.6f, 1e-5f);

  ASSERT_TRUE(backend->intersect(make_ray({-10.0f, 0.0f, -5.0f}, {0, 0, 1}), hit));
  EXPECT_EQ(hit.inst_id, kInvalidId);
  EXPECT_EQ(hit.geom_id, 0u);
}

TEST_F(EmbreeBackendTest, OcclusionCoversTheOpenInterval) {
  const RenderScene scene = scene_with({spheres({{{-3, -3, 5}, 1.0f, 0}}), unit_square()});
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  const Vec3 org{-3, -3, 0};
  EXPECT_TRUE(backend->occluded(make_ray(org, {0, 0, 1})));
  EXPECT_FALSE(backend->occluded(make_ray(org, {0, 0, 1}, 0.0f, 3.9f)));
  EXPECT_FALSE(backend->occluded(make_ray(org, {0, 0, 1}, 0.0f, 4.0f)));  // ends on the sphere
  EXPECT_TRUE(backend->occluded(make_ray(org, {0, 0, 1}, 0.0f, std::nextafter(4.0f, kInf))));
  EXPECT_FALSE(backend->occluded(make_ray(org, {0, 0, -1})));
  // Embree's triangle distances are only accurate to an ulp or so: stay clear of the end points.
  EXPECT_FALSE(backend->occluded(make_ray({0.25f, 0.25f, -1.0f}, {0, 0, 1}, 0.0f, 0.999f)));
  EXPECT_TRUE(backend->occluded(make_ray({0.25f, 0.25f, -1.0f}, {0, 0, 1}, 0.0f, 1.001f)));
  EXPECT_FALSE(backend->occluded(make_ray({0.25f, 0.25f, -1.0f}, {0, 0, 1}, 1.001f, 2.0f)));
}

TEST_F(EmbreeBackendTest, UntraceableRaysAreCountedMisses) {
  const RenderScene scene = scene_with({spheres({{{0, 0, 5}, 1.0f, 0}})});
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<Ray> bad = {
      make_ray({nan, 0, 0}, {0, 0, 1}),
      make_ray({0, 0, 0}, {0, nan, 1}),
      make_ray({0, 0, 1e30f}, {0, 0, -1}),
      make_ray({0, 0, 0}, {0, 0, 1e30f}),
      make_ray({0, 0, 0}, {0, 0, 0}),
      make_ray({0, 0, 0}, {0, 0, 1}, -1.0f),
      make_ray({0, 0, 0}, {0, 0, 1}, 2.0f, 1.0f),
  };
  Hit hit;
  for (const Ray& ray : bad) {
    EXPECT_FALSE(backend->intersect(ray, hit));
    EXPECT_FALSE(backend->occluded(ray));
  }
  EXPECT_EQ(backend->stats().rejected_rays, 2 * bad.size());
  EXPECT_TRUE(backend->intersect(make_ray({0, 0, 0}, {0, 0, 1}), hit));
  EXPECT_EQ(backend->stats().rejected_rays, 2 * bad.size());
}

TEST_F(EmbreeBackendTest, MemoryLimitMakesTheBuildFail) {
  const RenderScene scene = test::random_mixed_scene(3, 2000, 2000, 5);
  BackendOptions options;
  options.max_memory_bytes = 1024;
  try {
    make_backend(BackendKind::kEmbree, scene, options);
    FAIL() << "a 1 KB budget cannot hold a BVH of 5000 primitives";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("--max-memory limit"), std::string::npos) << e.what();
  }
  // The device is fine afterwards, and a generous budget is not in the way.
  options.max_memory_bytes = std::size_t{1} << 30;
  const auto backend = make_backend(BackendKind::kEmbree, scene, options);
  EXPECT_GT(backend->stats().acceleration_bytes, 5000u * 16u);
  EXPECT_LT(backend->stats().acceleration_bytes, options.max_memory_bytes);
}

TEST_F(EmbreeBackendTest, ConcurrentBuildsKeepTheirOwnFailuresAndBytes) {
  const RenderScene scene = test::random_mixed_scene(4, 3000, 3000, 5);
  const std::size_t alone = make_backend(BackendKind::kEmbree, scene, {})->stats().acceleration_bytes;
  constexpr int kThreads = 6;
  std::vector<std::size_t> bytes(kThreads, 0);
  std::vector<int> failures(kThreads, 0);
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i) {
    threads.emplace_back([&, i] {
      BackendOptions options;
      options.max_memory_bytes = i % 2 ? 4096 : 0;  // every other build must fail, alone
      try {
        bytes[i] = make_backend(BackendKind::kEmbree, scene, options)->stats().acceleration_bytes;
      } catch (const RuntimeError&) {
        ++failures[i];
      }
    });
  }
  for (std::thread& t : threads) t.join();
  for (int i = 0; i < kThreads; ++i) {
    EXPECT_EQ(failures[i], i % 2) << i;
    // Embree hands each thread that joins a build its own allocation blocks, so the count moves by
    // a block or two with how many of TBB's workers a loaded machine lends the build (1.8% seen
    // under load); another build's bytes counted in would double it.
    if (i % 2 == 0) {
      EXPECT_NEAR(static_cast<double>(bytes[i]), static_cast<double>(alone), 0.05 * static_cast<double>(alone)) << i;
    }
  }
}

TEST_F(EmbreeBackendTest, GeometryEmbreeWouldDropIsRefused) {
  TriangleMesh bad_vertex = unit_square();
  bad_vertex.vertices[2].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(make_backend(BackendKind::kEmbree, scene_with({bad_vertex}), {}), RuntimeError);

  for (const float value : {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(), 1e20f,
                            -1e20f, kMaxTraceableMagnitude, -kMaxTraceableMagnitude}) {
    for (int axis = 0; axis < 3; ++axis) {
      TriangleMesh far_vertex = unit_square();
      float* xyz[3] = {&far_vertex.vertices.back().x, &far_vertex.vertices.back().y, &far_vertex.vertices.back().z};
      *xyz[axis] = value;
      EXPECT_THROW(make_backend(BackendKind::kEmbree, scene_with({far_vertex}), {}), RuntimeError)
          << value << " on axis " << axis;
    }
  }

  for (int corner = 0; corner < 3; ++corner) {
    TriangleMesh bad_index = unit_square();
    std::uint32_t* corners[3] = {&bad_index.triangles[1].v0, &bad_index.triangles[1].v1, &bad_index.triangles[1].v2};
    *corners[corner] = static_cast<std::uint32_t>(bad_index.vertices.size());
    EXPECT_THROW(make_backend(BackendKind::kEmbree, scene_with({bad_index}), {}), RuntimeError) << corner;
    *corners[corner] = 0xFFFFFFFFu;
    EXPECT_THROW(make_backend(BackendKind::kEmbree, scene_with({bad_index}), {}), RuntimeError) << corner;
  }
  // The last vertex is a vertex, and the edge of the range is not past it.
  TriangleMesh last_vertex = unit_square();
  last_vertex.triangles[0].v0 = static_cast<std::uint32_t>(last_vertex.vertices.size() - 1);
  last_vertex.vertices.back().x = std::nextafter(kMaxTraceableMagnitude, 0.0f);
  EXPECT_NO_THROW(make_backend(BackendKind::kEmbree, scene_with({last_vertex}), {}));

  EXPECT_THROW(make_backend(BackendKind::kEmbree, scene_with({spheres({{{1e20f, 0, 0}, 1.0f, 0}})}), {}), RuntimeError);
  EXPECT_THROW(make_backend(BackendKind::kEmbree, scene_with({Instance{3, {}, {}}}), {}), RuntimeError);
}

TEST_F(EmbreeBackendTest, OptionsChooseQualityAndThreads) {
  const RenderScene scene = test::random_mixed_scene(5, 300, 300, 4);
  std::mt19937 rng(5);
  std::vector<Ray> rays;
  for (int i = 0; i < 300; ++i) rays.push_back(test::random_ray(rng, 6.0f));

  const auto reference = make_backend(BackendKind::kEmbree, scene, {});
  for (const EmbreeBuildQuality quality : {EmbreeBuildQuality::kLow, EmbreeBuildQuality::kHigh}) {
    BackendOptions options;
    options.embree_quality = quality;
    options.threads = 1;
    const auto backend = make_backend(BackendKind::kEmbree, scene, options);
    for (const Ray& ray : rays) {
      Hit a, b;
      ASSERT_EQ(reference->intersect(ray, a), backend->intersect(ray, b)) << static_cast<int>(quality);
      EXPECT_EQ(a.geom_id, b.geom_id);
      EXPECT_EQ(a.prim_id, b.prim_id);
    }
  }
}

TEST_F(EmbreeBackendTest, EmptySceneMissesEverything) {
  const RenderScene scene = scene_with({});
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  Hit hit;
  EXPECT_FALSE(backend->intersect(make_ray({0, 0, 0}, {0, 0, 1}), hit));
  EXPECT_FALSE(backend->occluded(make_ray({0, 0, 0}, {0, 0, 1})));
  EXPECT_EQ(backend->name(), "embree");
}

}  // namespace embree_backend_test
}  // namespace rtpro
