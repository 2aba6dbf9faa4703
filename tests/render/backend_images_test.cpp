// Both backends feed the same camera, sampler, shading and film: on a scene of top-level spheres
// the images must be bit-identical, whatever the backend and thread count.
#include "rtpro/backend/backend.h"
#include "rtpro/render/renderer.h"
#include "test_scenes.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>
#include <random>

namespace rtpro {
namespace backend_images_test {

Image render(const RenderScene& scene, BackendKind kind, int threads) {
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, threads);
  BackendOptions options;
  options.threads = threads;
  const auto backend = make_backend(kind, scene, options);
  return render_image(scene, *backend, {}).image;
}

TEST(BackendImages, RandomSpheresGiveFourIdenticalImages) {
  std::mt19937 rng(2024);
  RenderScene scene = test::empty_scene(96, 64);
  scene.render.spp = 4;
  scene.render.max_depth = 4;
  scene.top.geometries.emplace_back(test::random_spheres(rng, 3000, 4.0f));
  const Image reference = render(scene, BackendKind::kNative, 1);
  float sum = 0;
  for (float v : reference.data) sum += v;
  ASSERT_GT(sum, 100.0f);
  for (BackendKind kind : {BackendKind::kNative, BackendKind::kEmbree})
    for (int threads : {1, 2}) {
      const Image image = render(scene, kind, threads);
      ASSERT_EQ(image.data.size(), reference.data.size());
      EXPECT_EQ(std::memcmp(image.data.data(), reference.data.data(), image.data.size() * sizeof(float)), 0)
          << backend_name(kind) << " at " << threads << " threads";
    }
}

}  // namespace backend_images_test
}  // namespace rtpro
