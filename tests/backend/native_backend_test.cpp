// The native backend is the reference, so it is checked against the plainest possible answer:
// a loop over every primitive with the same intersectors and tie rule.
#include "rtpro/backend/backend.h"

#include "bvh.h"
#include "rtpro/geometry/sphere_intersect.h"
#include "rtpro/geometry/triangle_intersect.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <limits>

namespace rtpro {
namespace native_backend_test {

// Closest hit by testing every primitive of the group (and every instance's prototype).
void brute_force(const RenderScene& scene, const Group& group, const Ray& ray, std::uint32_t inst, Hit& best,
                 float& best_t) {
  for (std::uint32_t g = 0; g < group.geometries.size(); ++g) {
    const Geometry& geometry = group.geometries[g];
    if (const auto* set = std::get_if<SphereSet>(&geometry)) {
      for (std::uint32_t p = 0; p < set->spheres.size(); ++p) {
        float t;
        const Sphere& s = set->spheres[p];
        if (intersect_sphere(s.center, s.radius, ray.org, ray.dir, ray.tnear, best_t, t) &&
            is_closer(t, inst, g, p, best, best_t)) {
          best_t = t;
          best = {t, 0, 0, g, p, inst};
        }
      }
    } else if (const auto* mesh = std::get_if<TriangleMesh>(&geometry)) {
      for (std::uint32_t p = 0; p < mesh->triangles.size(); ++p) {
        const TriangleIndices& tri = mesh->triangles[p];
        TriangleHit h;
        if (intersect_triangle(mesh->vertex(tri.v0), mesh->vertex(tri.v1), mesh->vertex(tri.v2), ray.org, ray.dir,
                               ray.tnear, best_t, h) &&
            is_closer(h.t, inst, g, p, best, best_t)) {
          best_t = h.t;
          best = {h.t, h.u, h.v, g, p, inst};
        }
      }
    } else {
      const Instance& instance = std::get<Instance>(geometry);
      const Ray local{instance.world_to_object.apply_point(ray.org), ray.tnear,
                      instance.world_to_object.apply_vector(ray.dir), best_t};
      brute_force(scene, scene.prototypes[instance.prototype], local, g, best, best_t);
    }
  }
}

TEST(NativeBackend, AgreesExactlyWithBruteForce) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const RenderScene scene = test::random_mixed_scene(seed, 2000, 2000, 30);
    const auto backend = make_backend(BackendKind::kNative, scene, {});
    std::mt19937 rng(seed * 100);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
      const Ray ray = test::random_ray(rng, 6.0f);
      Hit expected;
      float expected_t = ray.tfar;
      brute_force(scene, scene.top, ray, kInvalidId, expected, expected_t);
      Hit got;
      const bool found = backend->intersect(ray, got);
      ASSERT_EQ(found, expected.valid()) << "ray " << i;
      ASSERT_EQ(backend->occluded(ray), expected.valid()) << "ray " << i;
      if (!found) continue;
      ++hits;
      EXPECT_EQ(got.t, expected_t);
      EXPECT_EQ(got.inst_id, expected.inst_id);
      EXPECT_EQ(got.geom_id, expected.geom_id);
      EXPECT_EQ(got.prim_id, expected.prim_id);
      EXPECT_EQ(got.u, expected.u);
      // A shadow ray stopping just before the hit is unoccluded only if nothing else is closer.
      Ray shorter = ray;
      shorter.tfar = expected_t * 0.999f;
      EXPECT_FALSE(backend->occluded(shorter));
    }
    EXPECT_GT(hits, 1000);
  }
}

TEST(NativeBackend, InstancedHitReportsInstanceAndPrototypeIds) {
  RenderScene scene = test::empty_scene();
  Group prototype;
  prototype.geometries.emplace_back(SphereSet{{{{0, 0, 0}, 1.0f, 0}}});
  scene.prototypes.push_back(std::move(prototype));
  scene.top.geometries.emplace_back(SphereSet{{{{0, 0, -100}, 1.0f, 0}}});
  const Affine placement = compose(Affine::translate({5, 0, 0}), Affine::scale({2, 2, 2}));
  scene.top.geometries.emplace_back(Instance{0, placement, *inverse(placement)});
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  Hit hit;
  ASSERT_TRUE(backend->intersect(Ray{{5, 0, 10}, 0.0f, {0, 0, -1}}, hit));
  EXPECT_EQ(hit.inst_id, 1u);
  EXPECT_EQ(hit.geom_id, 0u);
  EXPECT_EQ(hit.prim_id, 0u);
  EXPECT_NEAR(hit.t, 8.0f, 1e-5f);  // the scaled sphere has radius 2
}

TEST(NativeBackend, RejectsAndCountsUntraceableRays) {
  const RenderScene scene = test::random_mixed_scene(4, 10, 10, 1);
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Hit hit;
  EXPECT_FALSE(backend->intersect(Ray{{nan, 0, 0}, 0.0f, {0, 0, 1}}, hit));
  EXPECT_FALSE(backend->occluded(Ray{{1e30f, 0, 0}, 0.0f, {0, 0, 1}}));
  EXPECT_EQ(backend->stats().rejected_rays, 2u);
}

TEST(Bvh, IsDeterministicAndBoundsItsDepth) {
  const RenderScene scene = test::random_mixed_scene(9, 5000, 5000, 0);
  const Bvh a = build_bvh(scene.top, scene.prototype_bounds());
  const Bvh b = build_bvh(scene.top, scene.prototype_bounds());
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.refs.size(); ++i) {
    ASSERT_EQ(a.refs[i].geom, b.refs[i].geom);
    ASSERT_EQ(a.refs[i].prim, b.refs[i].prim);
  }
  EXPECT_EQ(a.refs.size(), 10000u);
  // Many identical spheres cannot be separated by SAH; the tree must still be finite and valid.
  RenderScene stacked = test::empty_scene();
  stacked.top.geometries.emplace_back(SphereSet{std::vector<Sphere>(20000, Sphere{{0, 0, 0}, 1.0f, 0})});
  const auto backend = make_backend(BackendKind::kNative, stacked, {});
  Hit hit;
  ASSERT_TRUE(backend->intersect(Ray{{0, 0, 5}, 0.0f, {0, 0, -1}}, hit));
  EXPECT_EQ(hit.prim_id, 0u);  // the tie rule picks the lowest id
}

}  // namespace native_backend_test
}  // namespace rtpro
