// Emissive triangles' samples against their pdf (light_set_chi2_support.h): one-sided and
// two-sided, in a mesh and under a mirroring instance.
#include "light_set_chi2_support.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace emissive_triangle_chi2_test {

using namespace light_set_test;

TEST(LightSetChi2, EmissiveTrianglesSamplerMatchesPdf) {
  TestScene scene;
  add_emissive_triangles(scene, Vec3(0.0f));
  const auto& [a, b, c] = kSmallTriangle;
  const Vec3 small_middle = (a + b + c) * (1.0f / 3.0f);
  const Vec3 small_normal = normalize(cross(b - a, c - a));
  expect_light_sampler_matches_pdf("emissive triangles", scene,
                                   {{"origin", Vec3(0.0f)},
                                    {"0.03 behind the small two-sided one", small_middle - small_normal * 0.03f},
                                    {"behind the large one", Vec3(0.0f, 3.2f, 0.3f)}});
}

}  // namespace emissive_triangle_chi2_test
}  // namespace rtpro
