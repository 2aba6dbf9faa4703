// Emissive spheres' samples against their pdf (light_set_chi2_support.h): from outside, on and
// inside a two-sided one, and inside a one-sided instanced one.
#include "light_set_chi2_support.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace emissive_sphere_chi2_test {

using namespace light_set_test;

TEST(LightSetChi2, EmissiveSpheresSamplerMatchesPdf) {
  TestScene scene;
  add_emissive_spheres(scene, Vec3(0.0f));
  const Vec3& c = kTwoSidedBall.center;
  const float r = kTwoSidedBall.radius;
  expect_light_sampler_matches_pdf(
      "emissive spheres", scene,
      {{"far", Vec3(-2.5f, 1.5f, 2.0f)},
       {"1.01 radii from the two-sided one", at_distance(c, 1.01f * r, Vec3(-1.0f, 0.4f, 0.3f))},
       {"on the two-sided one", at_distance(c, r, Vec3(0.2f, -1.0f, 0.5f))},
       {"inside the two-sided one", at_distance(c, 0.4f * r, Vec3(0.5f, 0.5f, -1.0f))},
       {"inside the one-sided instanced one", Vec3(2.6f, 1.1f, -0.4f)}});
}

}  // namespace emissive_sphere_chi2_test
}  // namespace rtpro
