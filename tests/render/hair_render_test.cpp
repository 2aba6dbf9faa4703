// The hair material rendered, on both backends (on a sphere: curves are not needed to shade hair,
// the fibre follows the sphere's tangent): without absorption it hides in a white furnace, paths
// entering the sphere through TT and leaving again with all their light; with melanin it is as
// brown as its Whitted colour says; and the whitted integrator shades it with that colour.
#include "rtpro/backend/backend.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro {
namespace hair_render_test {

class HairRender : public ::testing::TestWithParam<BackendKind> {};

Image render(const std::string& yaml, BackendKind kind, const std::vector<std::string>& overrides = {}) {
  const RenderScene scene = build_render_scene(parse_scene_text(yaml, "test.yaml", overrides));
  const auto backend = make_backend(kind, scene, {});
  std::optional<EnvironmentLight> environment;
  if (scene.environment) environment.emplace(*scene.environment, Image{}, environment_sampling_for(scene.render));
  RenderOptions options;
  options.environment = environment ? &*environment : nullptr;
  return render_image(scene, *backend, options).image;
}

Color mean_of(const Image& image) {
  double sum[3] = {0.0, 0.0, 0.0};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) sum[c] += image.at(x, y, c);
  const double n = static_cast<double>(image.width) * image.height;
  return {static_cast<float>(sum[0] / n), static_cast<float>(sum[1] / n), static_cast<float>(sum[2] / n)};
}

// A hair sphere filling the view in a constant environment of radiance 1.
std::string furnace(const std::string& hair) {
  return R"(
rtpro: 1
camera: {position: [0, 0, -2.2], look_at: [0, 0, 0], fov: 40, resolution: [16, 16]}
render: {spp: 16, max_depth: 64, integrator: path, sampling: bsdf}
materials:
  hair: )" +
         hair + R"(
environment: {color: [1, 1, 1]}
world: [{type: sphere, center: [0, 0, 0], radius: 1, material: hair}]
)";
}

TEST_P(HairRender, ClearHairHidesInAWhiteFurnace) {
  const Color mean = mean_of(render(furnace("{type: hair, sigma_a: [0, 0, 0], beta_m: 0.3, beta_n: 0.5}"), GetParam()));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], 1.0f, 0.02f);
}

TEST_P(HairRender, MelaninHairIsBrownAndDarkerThanTheFurnace) {
  const Color mean = mean_of(render(furnace("{type: hair, melanin: 1.3}"), GetParam()));
  EXPECT_GT(mean.x, mean.y);
  EXPECT_GT(mean.y, mean.z);
  EXPECT_GT(mean.z, 0.0f);
  EXPECT_LT(mean.x, 0.9f);
}

TEST_P(HairRender, TheWhittedIntegratorShadesItsColour) {
  const std::string lit = furnace("{type: hair, color: [0.7, 0.4, 0.2]}") +
                          "lights: [{type: directional, direction: [0, 0, 1], intensity: 1}]\n";
  const Color mean = mean_of(render(lit, GetParam(), {"render.integrator=whitted"}));
  EXPECT_GT(mean.x, mean.y);
  EXPECT_GT(mean.y, mean.z);
}

INSTANTIATE_TEST_SUITE_P(Backends, HairRender, ::testing::Values(BackendKind::kEmbree, BackendKind::kNative),
                         [](const auto& info) { return std::string(backend_name(info.param)); });

}  // namespace hair_render_test
}  // namespace rtpro
