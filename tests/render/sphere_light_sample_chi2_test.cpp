// A sphere light's samples against its pdf, seen from far and from just outside it
// (light_set_chi2_support.h), and the nothing it sends inside or on itself.
#include "light_set_chi2_support.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace sphere_light_sample_chi2_test {

using namespace light_set_test;

const Vec3 kSphereLightCenter(0.5f, 1.5f, 0.8f);
constexpr float kSphereLightRadius = 0.7f;

TEST(LightSetChi2, SphereLightSamplerMatchesPdf) {
  TestScene scene;
  scene.add_sphere_light(kSphereLightCenter, kSphereLightRadius, Color(4.0f, 3.0f, 2.0f));
  const Vec3& c = kSphereLightCenter;
  const float r = kSphereLightRadius;
  expect_light_sampler_matches_pdf("sphere light", scene,
                                   {{"far", c + Vec3(-3.0f, -2.5f, 1.2f)},
                                    {"1.01 radii", at_distance(c, 1.01f * r, Vec3(-0.3f, 0.2f, 1.0f))},
                                    {"1.002 radii", at_distance(c, 1.002f * r, Vec3(0.6f, 0.7f, -0.2f))}});
}

// A sphere light emits outwards only: from inside it or on it nothing is sampled, seen or given a pdf.
TEST(LightSetChi2, SphereLightSendsNothingInsideOrOnIt) {
  TestScene scene;
  scene.add_sphere_light(kSphereLightCenter, kSphereLightRadius, Color(4.0f, 3.0f, 2.0f));
  const LightSet set(scene.scene());
  test::Uniforms uniforms(17);
  for (const float radii : {0.0f, 0.5f, 0.99f, 1.0f})
    for (int i = 0; i < 1000; ++i) {
      const Vec3 from = kSphereLightCenter + uniforms.next_direction() * (radii * kSphereLightRadius);
      const float u_pick = uniforms.next();
      EXPECT_FALSE(set.sample(from, u_pick, uniforms.next_2d())) << radii << " radii";
      const Vec3 w = uniforms.next_direction();
      EXPECT_FALSE(set.seen_light(Ray{from, 0.0f, w}, kInfinity)) << radii << " radii";
      EXPECT_EQ(set.pdf(0, from, kSphereLightCenter + w * kSphereLightRadius), 0.0f) << radii << " radii";
    }
}

}  // namespace sphere_light_sample_chi2_test
}  // namespace rtpro
