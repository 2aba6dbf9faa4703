// Instances that place their prototypes as is (Instance::places_as_is) take shortcuts: Embree
// gives their shapes to its top scene when every top-level instance does, and the native backend
// traces their prototypes with the rays themselves. Every ray must get exactly the answer it gets
// through the instances' transforms, reported as the instance's hit (its id, the shape's id in the
// prototype).
#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "same_hit.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <random>

namespace rtpro {
namespace identity_instances_test {

// A top-level sphere set, then two prototypes of meshes placed as is (a prototype with spheres
// keeps its instance: their tie rule reads Embree's ids). `with_far_copy` places prototype 1 once more, translated far from every test ray, so that
// no instance is inlined (a prototype placed twice keeps its instances).
RenderScene scene_with_identity_instances(bool with_far_copy) {
  std::mt19937 rng(8);
  RenderScene scene = test::empty_scene();
  scene.top.geometries.emplace_back(test::random_spheres(rng, 20, 4.0f));
  Group& first = scene.prototypes.emplace_back();
  first.geometries.emplace_back(test::random_triangles(rng, 200, 4.0f));
  first.geometries.emplace_back(test::random_triangles(rng, 300, 4.0f));
  Group& second = scene.prototypes.emplace_back();
  second.geometries.emplace_back(test::random_triangles(rng, 300, 4.0f));
  scene.top.geometries.emplace_back(Instance{0, Affine::identity(), Affine::identity()});
  scene.top.geometries.emplace_back(Instance{1, Affine::identity(), Affine::identity()});
  if (with_far_copy) {
    const Affine far = Affine::translate({1000.0f, 1000.0f, 1000.0f});
    scene.top.geometries.emplace_back(Instance{1, far, Affine::translate({-1000.0f, -1000.0f, -1000.0f})});
  }
  return scene;
}

class IdentityInstances : public ::testing::Test {
 protected:
  void SetUp() override { set_tracing_fp_mode(); }
};

TEST_F(IdentityInstances, EmbreeGetsTheInstancesAnswer) {
  const RenderScene inlined = scene_with_identity_instances(false), instanced = scene_with_identity_instances(true);
  ASSERT_TRUE(std::get<Instance>(inlined.top.geometries[1]).places_as_is());
  const auto in_top = make_backend(BackendKind::kEmbree, inlined, {});
  const auto through_instances = make_backend(BackendKind::kEmbree, instanced, {});
  const std::vector<Ray> rays = test::scattered_rays(12, 4000, 2.0f);
  int hits_by_instance[3] = {0, 0, 0};
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Hit a, b;
    in_top->intersect(rays[i], a);
    through_instances->intersect(rays[i], b);
    test::expect_same_hit(a, b, i);
    if (a.valid()) ++hits_by_instance[a.inst_id == kInvalidId ? 0 : a.inst_id];
    EXPECT_EQ(in_top->occluded(rays[i]), through_instances->occluded(rays[i])) << i;
  }
  // Hits on the top-level spheres and on both inlined instances, reported as the instances'.
  EXPECT_GT(hits_by_instance[0], 10);
  EXPECT_GT(hits_by_instance[1], 100);
  EXPECT_GT(hits_by_instance[2], 100);

  test::expect_same_batch_answers(*in_top, *through_instances, rays);
}

// The same scene placed by an identity whose translation has a −0: the same coordinates, but not
// placed as is, so the native backend transforms every ray that enters it.
RenderScene with_transformed_identities(RenderScene scene) {
  for (Geometry& geometry : scene.top.geometries)
    if (auto* instance = std::get_if<Instance>(&geometry); instance && instance->places_as_is())
      instance->object_to_world.m[0][3] = -0.0f;
  return scene;
}

TEST_F(IdentityInstances, NativeGetsTheTransformedRaysAnswer) {
  const RenderScene as_is = scene_with_identity_instances(false);
  const RenderScene transformed = with_transformed_identities(as_is);
  ASSERT_FALSE(std::get<Instance>(transformed.top.geometries[1]).places_as_is());
  const auto shortcut = make_backend(BackendKind::kNative, as_is, {});
  const auto through_transforms = make_backend(BackendKind::kNative, transformed, {});
  const std::vector<Ray> rays = test::scattered_rays(12, 4000, 2.0f);
  int instance_hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Hit a, b;
    shortcut->intersect(rays[i], a);
    through_transforms->intersect(rays[i], b);
    test::expect_same_hit(a, b, i);
    instance_hits += a.valid() && a.inst_id != kInvalidId;
    EXPECT_EQ(shortcut->occluded(rays[i]), through_transforms->occluded(rays[i])) << i;
  }
  EXPECT_GT(instance_hits, 200);
  test::expect_same_batch_answers(*shortcut, *through_transforms, rays);
}

TEST(InstancePlacement, OnlyAStaticBitForBitIdentityPlacesAsIs) {
  EXPECT_TRUE((Instance{0, Affine::identity(), Affine::identity()}.places_as_is()));
  Affine negative_zero = Affine::identity();
  negative_zero.m[0][3] = -0.0f;
  EXPECT_FALSE((Instance{0, negative_zero, Affine::identity()}.places_as_is()));
  EXPECT_FALSE((Instance{0, Affine::translate({0.0f, 1e-7f, 0.0f}), Affine::identity()}.places_as_is()));
  EXPECT_FALSE(
      (Instance{0, Affine::identity(), Affine::identity(), {Affine::identity(), Affine::identity()}}.places_as_is()));
}

}  // namespace identity_instances_test
}  // namespace rtpro
