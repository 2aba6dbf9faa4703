#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace rtpro {
namespace subdivision_surface_test {

// A unit cube cage, faces wound outwards.
constexpr const char* kCube =
    "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
    "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
// One quad in the plane y = 0, wound so its normal is +y.
constexpr const char* kPlane =
    "v -1 0 -1\nv -1 0 1\nv 1 0 1\nv 1 0 -1\nvt 0 0\nvt 0 1\nvt 1 1\nvt 1 0\n"
    "f 1/1 2/2 3/3 4/4\n";

RenderScene scene_with(const std::string& obj, const std::string& entry) {
  const auto mesh = test::write_file("cage.obj", obj);
  const auto file = test::write_file(
      "scene.yaml",
      "rtpro: 1\ncamera: {position: [0, 0, -5], look_at: [0, 0, 0]}\nworld:\n  - {type: mesh, file: cage.obj, " +
          entry + "}\n");
  return build_render_scene(parse_scene_file(file));
}

class SubdivisionSurface : public ::testing::TestWithParam<BackendKind> {
 protected:
  void SetUp() override { set_tracing_fp_mode(); }
};

// Rays from inside the refined cube in many directions all hit it: the triangles leave no crack.
TEST_P(SubdivisionSurface, IsWatertight) {
  const RenderScene scene = scene_with(kCube, "subdivision: {scheme: catmull-clark, level: 3}");
  const auto backend = make_backend(GetParam(), scene, {});
  std::mt19937 rng(3);
  std::normal_distribution<float> normal;
  for (int i = 0; i < 4000; ++i) {
    Ray ray;
    ray.org = Vec3(0.05f, -0.03f, 0.02f) * float(i % 3);
    ray.dir = normalize(Vec3{normal(rng), normal(rng), normal(rng)});
    Hit hit;
    ASSERT_TRUE(backend->intersect(ray, hit)) << i;
    EXPECT_LT(hit.t, 0.9f);
  }
}

// A constant displacement d moves every point of the plane by d along its normal (+y).
TEST_P(SubdivisionSurface, ConstantDisplacementMovesEveryHitByIt) {
  constexpr float d = 0.25f;
  const RenderScene flat = scene_with(kPlane, "subdivision: {level: 2}");
  const RenderScene raised = scene_with(kPlane, "subdivision: {level: 2}, displacement: {value: 0.5, scale: 0.5}");
  const auto flat_backend = make_backend(GetParam(), flat, {});
  const auto raised_backend = make_backend(GetParam(), raised, {});
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> across(-0.9f, 0.9f);
  for (int i = 0; i < 500; ++i) {
    Ray ray;
    ray.org = Vec3{across(rng), 1.0f, across(rng)};
    ray.dir = normalize(Vec3{across(rng) * 0.1f, -1.0f, across(rng) * 0.1f});
    Hit a, b;
    ASSERT_TRUE(flat_backend->intersect(ray, a)) << i;
    ASSERT_TRUE(raised_backend->intersect(ray, b)) << i;
    EXPECT_NEAR(ray.at(a.t).y, 0.0f, 1e-5f);
    EXPECT_NEAR(ray.at(b.t).y, d, 1e-5f);
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, SubdivisionSurface, ::testing::Values(BackendKind::kNative, BackendKind::kEmbree),
                         [](const auto& info) { return std::string(backend_name(info.param)); });

}  // namespace subdivision_surface_test
}  // namespace rtpro
