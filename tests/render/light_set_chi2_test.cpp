// The light set picking among every kind of light at once: its samples against its pdf
// (light_set_chi2_support.h), a point light's share of the picks returning delta samples, and,
// under the power picker, each light picked in proportion to its power.
#include "light_set_chi2_support.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <iostream>
#include <optional>
#include <vector>

namespace rtpro {
namespace light_set_chi2_test {

using namespace light_set_test;

// Every kind at once, with a point light: its share of the picks returns delta samples.
TestScene mixed_scene() {
  TestScene scene;
  scene.add_point_light(Vec3(1.0f, -1.5f, -1.8f), Color(5.0f, 4.0f, 6.0f));
  scene.add_quad_light(kQuadCorner, kQuadEdge1, kQuadEdge2, Color(4.0f, 3.0f, 2.0f));
  scene.add_sphere_light(Vec3(-1.5f, -2.0f, -1.0f), 0.5f, Color(6.0f, 6.0f, 5.0f));
  add_emissive_triangles(scene, Vec3(0.0f, 0.5f, 0.0f));
  add_emissive_spheres(scene, Vec3(-0.5f, -1.0f, 2.5f));
  return scene;
}

TEST(LightSetChi2, MixedLightsSamplerMatchesPdf) {
  expect_light_sampler_matches_pdf("mixed lights", mixed_scene(),
                                   {{"origin", Vec3(0.0f)},
                                    {"behind the quad", Vec3(2.5f, 0.2f, 0.6f)},
                                    {"inside the sphere light", Vec3(-1.4f, -2.1f, -1.0f)}});
}

// Under render.light_sampler: power, over a fine grid of u_pick, each light is picked with its
// share of the power, and a delta sample reports exactly that share as its pdf.
TEST(LightSetChi2, PicksLightsInProportionToPower) {
  const TestScene scene = mixed_scene();
  RenderScene by_power = scene.scene();
  by_power.render.light_sampler = LightSamplerKind::kPower;
  const LightSet set(by_power);
  const std::vector<TestLight>& lights = scene.lights();
  ASSERT_EQ(set.lights().size(), lights.size());
  const Vec3 from(0.0f);
  for (const TestLight& light : lights)
    if (!light.delta()) {
      ASSERT_TRUE(sends_light_to(light, from)) << light.name;
    }
  const double total = total_power(lights);
  std::vector<double> share(lights.size(), 0.0);
  for (const TestLight& light : lights) share[index_of(set, light)] = light.power / total;
  constexpr int kPicks = 1 << 18;
  std::vector<int> picked(lights.size(), 0);
  for (int i = 0; i < kPicks; ++i) {
    const float u_pick = (static_cast<float>(i) + 0.5f) / kPicks;
    const std::optional<PathLightSample> s = set.sample(from, u_pick, {0.37f, 0.61f});
    ASSERT_TRUE(s) << "u_pick " << i;
    ASSERT_LT(s->light, picked.size());
    ++picked[s->light];
    if (s->delta) {
      ASSERT_NEAR(s->pdf, share[s->light], 1e-6 * share[s->light]);
    }
  }
  for (const TestLight& light : lights) {
    const std::uint32_t index = index_of(set, light);
    const double frequency = static_cast<double>(picked[index]) / kPicks;
    std::cout << "[pick] " << light.name << ": power share " << share[index] << ", picked " << frequency << "\n";
    EXPECT_NEAR(frequency, share[index], static_cast<double>(lights.size()) / kPicks + 1e-6) << light.name;
  }
}

}  // namespace light_set_chi2_test
}  // namespace rtpro
