// Rays with a time in scenes that move during the shutter: batches (the native backend's packets
// with a time per lane) answer exactly what single rays at the same times answer, on both
// backends; and the native backend's motion BVH (nodes with linear bounds, the moving triangle
// rows) finds exactly the hits of the same scene frozen at each ray's time, so no box culls a
// primitive that is there at that time. The motion is not linear (three steps that turn back), so
// the bounds' middle-step padding is needed too.
#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/scene/motion.h"
#include "same_hit.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace rtpro {
namespace motion_traversal_test {

constexpr std::array<float, 5> kTimes = {0.0f, 0.13f, 0.5f, 0.77f, 1.0f};

// One draw per coordinate, in order (argument evaluation order is unspecified).
Vec3 offset(std::mt19937& rng, float extent) {
  std::uniform_real_distribution<float> along(-extent, extent);
  const float x = along(rng);
  const float y = along(rng);
  const float z = along(rng);
  return {x, y, z};
}

// Spheres, triangles and `instances` instances, each moving through three steps (out, then partly
// back) by a good fraction of their size. (The Embree backend traces coherent rays with a time as
// streams only in a scene without moving instances.)
RenderScene moving_scene(int instances = 6) {
  RenderScene scene = test::random_mixed_scene(21, 300, 300, instances);
  std::mt19937 rng(5);
  auto& spheres = std::get<SphereSet>(scene.top.geometries[0]);
  spheres.step_count = 3;
  for (const Sphere& sphere : spheres.spheres) {
    const Vec3 away = offset(rng, 0.4f);
    spheres.center_steps.insert(spheres.center_steps.end(),
                                {sphere.center, sphere.center + away, sphere.center - away * 0.5f});
  }
  auto& mesh = std::get<TriangleMesh>(scene.top.geometries[1]);
  VertexArray out = mesh.vertices, back = mesh.vertices;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3 away = offset(rng, 0.3f);
    const Vec3 p = mesh.vertices[i].position();
    out[i] = {p.x + away.x, p.y + away.y, p.z + away.z};
    back[i] = {p.x - away.z, p.y + away.x, p.z};
  }
  mesh.vertex_steps = {mesh.vertices, out, back};
  for (std::size_t g = 2; g < scene.top.geometries.size(); ++g) {
    auto& instance = std::get<Instance>(scene.top.geometries[g]);
    const Vec3 slide = offset(rng, 0.8f);
    instance.object_to_world_steps = {instance.object_to_world,
                                      compose(Affine::translate(slide), instance.object_to_world),
                                      compose(Affine::rotate(Vec3(0, 1, 0), 40.0f), instance.object_to_world)};
  }
  return scene;
}

// `scene` as it stands at ray time `time`, with nothing moving.
RenderScene frozen_at(const RenderScene& scene, float time) {
  RenderScene frozen = scene;
  auto& spheres = std::get<SphereSet>(frozen.top.geometries[0]);
  for (std::uint32_t i = 0; i < spheres.spheres.size(); ++i) spheres.spheres[i].center = spheres.center_at(i, time);
  spheres.center_steps.clear();
  spheres.step_count = 0;
  auto& mesh = std::get<TriangleMesh>(frozen.top.geometries[1]);
  for (std::uint32_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3 p = mesh.vertex_at(i, time);
    mesh.vertices[i] = {p.x, p.y, p.z};
  }
  mesh.vertex_steps.clear();
  for (std::size_t g = 2; g < frozen.top.geometries.size(); ++g) {
    auto& instance = std::get<Instance>(frozen.top.geometries[g]);
    const InstancePlacement placement = *placement_at(instance, time);
    instance.object_to_world = placement.object_to_world;
    instance.world_to_object = placement.world_to_object;
    instance.object_to_world_steps.clear();
  }
  return frozen;
}

struct TimedRays {
  std::vector<Ray> rays;
  std::vector<float> times;
};

TimedRays timed_rays() {
  std::mt19937 rng(12);
  TimedRays out;
  for (int i = 0; i < 4000; ++i) {
    Ray ray = test::random_ray(rng, 6.0f);
    if (i % 3 == 1) ray.tfar = 2.5f;
    out.rays.push_back(ray);
    out.times.push_back(kTimes[static_cast<std::size_t>(i) % kTimes.size()]);
  }
  return out;
}

class MotionTraversal : public ::testing::TestWithParam<BackendKind> {
 protected:
  void SetUp() override { set_tracing_fp_mode(); }
};

TEST_P(MotionTraversal, TimedBatchesAnswerAsSingleRaysAtTheirTimes) {
  const TimedRays timed = timed_rays();
  for (const int instances : {0, 6})
    for (const RayCoherence coherence : {RayCoherence::kCoherent, RayCoherence::kIncoherent}) {
      SCOPED_TRACE(std::to_string(instances) + " instances, coherent " +
                   std::to_string(coherence == RayCoherence::kCoherent));
      const RenderScene scene = moving_scene(instances);
      const auto backend = make_backend(GetParam(), scene, {});
      std::vector<Hit> hits(timed.rays.size());
      backend->intersect(timed.rays, timed.times, hits, coherence);
      std::vector<std::uint8_t> occluded(timed.rays.size(), 7);
      backend->occluded(timed.rays, timed.times, occluded, coherence);
      int found = 0, blocked = 0;
      for (std::size_t i = 0; i < timed.rays.size(); ++i) {
        Hit single;
        if (!backend->intersect(timed.rays[i], timed.times[i], single)) single = Hit{};
        test::expect_same_hit(hits[i], single, i);
        found += hits[i].valid() ? 1 : 0;
        ASSERT_EQ(occluded[i] == 1, backend->occluded(timed.rays[i], timed.times[i])) << "ray " << i;
        blocked += occluded[i];
      }
      EXPECT_GT(found, 400);
      EXPECT_GT(blocked, 400);
    }
}

TEST(NativeMotionTraversal, FindsTheHitsOfTheSceneFrozenAtEachRaysTime) {
  set_tracing_fp_mode();
  const RenderScene scene = moving_scene();
  const auto moving = make_backend(BackendKind::kNative, scene, {});
  const TimedRays timed = timed_rays();
  std::vector<Hit> hits(timed.rays.size());
  moving->intersect(timed.rays, timed.times, hits, RayCoherence::kIncoherent);
  int checked = 0;
  for (const float time : kTimes) {
    const RenderScene frozen = frozen_at(scene, time);
    const auto still = make_backend(BackendKind::kNative, frozen, {});
    for (std::size_t i = 0; i < timed.rays.size(); ++i) {
      if (timed.times[i] != time) continue;
      Hit expected;
      if (!still->intersect(timed.rays[i], expected)) expected = Hit{};
      test::expect_same_hit(hits[i], expected, i);
      EXPECT_EQ(moving->occluded(timed.rays[i], time), still->occluded(timed.rays[i])) << "ray " << i;
      checked += expected.valid() ? 1 : 0;
    }
  }
  EXPECT_GT(checked, 400);
}

INSTANTIATE_TEST_SUITE_P(Backends, MotionTraversal, ::testing::Values(BackendKind::kNative, BackendKind::kEmbree),
                         [](const auto& info) { return std::string(backend_name(info.param)); });

}  // namespace motion_traversal_test
}  // namespace rtpro
