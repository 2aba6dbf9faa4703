// The path integrator lit by an environment, with both backends: the white furnace through the
// environment (a constant one of radiance 1 hides a white Lambertian sphere, with every estimator
// and rotated), camera visibility, the Whitted integrator's view of it, and MIS, environment
// sampling alone and BSDF sampling alone agreeing under a real HDRI with a sun (sunset.exr), MIS
// with the environment sampled above its mean and whole agreeing on principled layers.
#include "rtpro/backend/backend.h"
#include "rtpro/image/image_io.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace rtpro {
namespace environment_render_test {

class EnvironmentRender : public ::testing::TestWithParam<BackendKind> {};

// `sampling`: the environment's, or the one the render settings choose.
Image render(const std::string& yaml, BackendKind kind, const std::vector<std::string>& overrides = {},
             std::optional<EnvironmentSampling> sampling = std::nullopt) {
  const RenderScene scene = build_render_scene(parse_scene_text(yaml, test::scenes_dir() / "test.yaml", overrides));
  const auto backend = make_backend(kind, scene, {});
  Image image;
  if (scene.environment && !scene.environment->file.empty()) image = read_image(scene.environment->file);
  std::optional<EnvironmentLight> environment;
  if (scene.environment)
    environment.emplace(*scene.environment, std::move(image),
                        sampling.value_or(environment_sampling_for(scene.render)));
  RenderOptions options;
  options.environment = environment ? &*environment : nullptr;
  return render_image(scene, *backend, options).image;
}

struct Channels {
  double mean = 0.0, min = 1e30, max = -1e30;
};

Channels stats_of(const Image& image) {
  Channels s;
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double v = image.at(x, y, c);
        sum += v;
        s.min = std::min(s.min, v);
        s.max = std::max(s.max, v);
      }
  s.mean = sum / (3.0 * image.width * image.height);
  return s;
}

// A white Lambertian sphere filling most of the view in a constant environment of radiance 1: a
// convex object reflects what arrives once, so every pixel is exactly 1 in expectation.
const std::string kFurnace = R"(
rtpro: 1
camera: {position: [0, 0, -3], look_at: [0, 0, 0], fov: 45, resolution: [24, 24]}
render: {spp: 64, max_depth: 8, integrator: path}
materials:
  white: {type: diffuse, color: [1, 1, 1]}
environment: {color: [1, 1, 1]}
world: [{type: sphere, center: [0, 0, 0], radius: 1, material: white}]
)";

TEST_P(EnvironmentRender, BsdfSamplingHidesAWhiteSphereInEveryPixel) {
  // Cosine sampling a white Lambertian surface carries weight exactly 1: no noise at all.
  for (const char* rotation : {"[0, 0, 0]", "[30, 60, 10]"}) {
    const Channels s = stats_of(
        render(kFurnace, GetParam(), {"render.sampling=bsdf", std::string("environment.rotation=") + rotation}));
    EXPECT_NEAR(s.min, 1.0, 0.003) << rotation;
    EXPECT_NEAR(s.max, 1.0, 0.003) << rotation;
  }
}

TEST_P(EnvironmentRender, MisAndEnvironmentSamplingHideAWhiteSphereOnAverage) {
  for (const char* sampling : {"mis", "light"})
    for (const char* rotation : {"[0, 0, 0]", "[30, 60, 10]"}) {
      const Channels s = stats_of(
          render(kFurnace, GetParam(),
                 {std::string("render.sampling=") + sampling, std::string("environment.rotation=") + rotation}));
      EXPECT_NEAR(s.mean, 1.0, 0.003) << sampling << " " << rotation;
      EXPECT_GT(s.min, 0.8) << sampling << " " << rotation;
      EXPECT_LT(s.max, 1.2) << sampling << " " << rotation;
    }
}

TEST_P(EnvironmentRender, AnInvisibleEnvironmentStillLightsButTheCameraSeesTheBackground) {
  const Image image =
      render(kFurnace, GetParam(),
             {"render.sampling=bsdf", "environment.visible=false", "render.background=[0.25, 0.5, 0.75]"});
  // The corner misses the sphere, the centre sees it.
  EXPECT_FLOAT_EQ(image.at(0, 0, 0), 0.25f);
  EXPECT_FLOAT_EQ(image.at(0, 0, 2), 0.75f);
  EXPECT_NEAR(image.at(12, 12, 1), 1.0f, 0.003f);
}

TEST_P(EnvironmentRender, WhittedShowsTheEnvironmentWhereRaysEscape) {
  const std::string yaml = R"(
rtpro: 1
camera: {position: [0, 0, -3], look_at: [0, 0, 0], fov: 45, resolution: [16, 16]}
render: {spp: 1, integrator: whitted, background: [0, 0, 0]}
environment: {color: [0.25, 0.5, 0.75], intensity: 2}
)";
  const Channels red = stats_of(render(yaml, GetParam()));
  EXPECT_FLOAT_EQ(static_cast<float>(red.min), 0.5f);
  EXPECT_FLOAT_EQ(static_cast<float>(red.max), 1.5f);
  const Image hidden = render(yaml, GetParam(), {"environment.visible=false"});
  EXPECT_EQ(stats_of(hidden).max, 0.0);
}

// Image means and their standard error over independent seeds.
struct Estimate {
  double mean, standard_error;
};

Estimate mean_over_seeds(const std::string& yaml, BackendKind kind, const std::string& sampling, int seeds,
                         std::optional<EnvironmentSampling> environment_sampling = std::nullopt) {
  std::vector<double> means;
  for (int seed = 1; seed <= seeds; ++seed)
    means.push_back(stats_of(render(yaml, kind, {"render.sampling=" + sampling, "render.seed=" + std::to_string(seed)},
                                    environment_sampling))
                        .mean);
  double mean = 0.0;
  for (double m : means) mean += m;
  mean /= seeds;
  double variance = 0.0;
  for (double m : means) variance += (m - mean) * (m - mean);
  variance /= seeds - 1;
  return {mean, std::sqrt(variance / seeds)};
}

// Two estimates agree when their means are within three standard errors of their difference.
::testing::AssertionResult agree(const char* a_name, const Estimate& a, const char* b_name, const Estimate& b) {
  if (std::fabs(a.mean - b.mean) <= 3.0 * std::hypot(a.standard_error, b.standard_error))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a_name << " " << a.mean << " ± " << a.standard_error << " against " << b_name
                                       << " " << b.mean << " ± " << b.standard_error;
}

// Two spheres on a ground sphere of clay under sunset.exr (its sun turned to light them from the
// side), 32×20 at 32 spp: `materials` names `left` and `right`.
std::string two_spheres_under_a_sunset(const std::string& materials) {
  return R"(
rtpro: 1
camera: {position: [0, 0.6, -4], look_at: [0, 0.2, 0], fov: 40, resolution: [32, 20]}
render: {spp: 32, max_depth: 4, integrator: path}
materials:
  clay: {type: diffuse, color: [0.8, 0.6, 0.5]}
)" + materials +
         R"(
environment: {file: environments/sunset.exr, rotation: [0, 120, 0]}
world:
  - {type: sphere, center: [-0.6, 0, 0], radius: 0.55, material: left}
  - {type: sphere, center: [0.6, 0, 0], radius: 0.55, material: right}
  - {type: sphere, center: [0, -100.55, 0], radius: 100, material: clay}
)";
}

TEST_P(EnvironmentRender, EstimatorsAgreeUnderASunsetWithASun) {
  const std::string yaml = two_spheres_under_a_sunset(R"(
  left: {type: diffuse, color: [0.8, 0.6, 0.5]}
  right: {type: conductor, color: [0.9, 0.9, 0.9], roughness: 0.3})");
  constexpr int kSeeds = 6;
  const Estimate mis = mean_over_seeds(yaml, GetParam(), "mis", kSeeds);
  const Estimate light = mean_over_seeds(yaml, GetParam(), "light", kSeeds);
  const Estimate bsdf = mean_over_seeds(yaml, GetParam(), "bsdf", kSeeds);
  std::cout << "[estimators] mis " << mis.mean << " ± " << mis.standard_error << ", light " << light.mean << " ± "
            << light.standard_error << ", bsdf " << bsdf.mean << " ± " << bsdf.standard_error << "\n";
  EXPECT_TRUE(agree("mis", mis, "light", light));
  EXPECT_TRUE(agree("mis", mis, "bsdf", bsdf));
  // Environment sampling is what makes the sun tractable (the standard errors of six images'
  // means are themselves uncertain by about a third).
  EXPECT_LT(mis.standard_error * 2.0, bsdf.standard_error);
}

// Under MIS the environment's light samples leave the pixels below its mean to the BSDF samples,
// so MIS is unbiased only where those cover every direction the BSDF reflects or transmits into:
// the principled layers (coat, sheen, a half-metal base, transmission) under MIS with the
// environment sampled above its mean, against MIS with it sampled whole, which leans on no such
// cover (and against light samples alone, noisier).
TEST_P(EnvironmentRender, EstimatorsAgreeOnPrincipledLayersUnderASunset) {
  const std::string yaml = two_spheres_under_a_sunset(R"(
  left: {type: principled, color: [0.8, 0.5, 0.3], roughness: 0.4, metalness: 0.5, coat_weight: 0.7,
         coat_roughness: 0.1, fuzz_color: [0.6, 0.6, 0.9], fuzz_roughness: 0.5}
  right: {type: principled, color: [0.9, 0.9, 0.9], roughness: 0.3, transmission_weight: 0.6})");
  constexpr int kSeeds = 6;
  const Estimate above = mean_over_seeds(yaml, GetParam(), "mis", kSeeds, EnvironmentSampling::kAboveMean);
  const Estimate whole = mean_over_seeds(yaml, GetParam(), "mis", kSeeds, EnvironmentSampling::kWhole);
  const Estimate light = mean_over_seeds(yaml, GetParam(), "light", kSeeds);
  std::cout << "[estimators] mis above the mean " << above.mean << " ± " << above.standard_error << ", mis whole "
            << whole.mean << " ± " << whole.standard_error << ", light " << light.mean << " ± " << light.standard_error
            << "\n";
  EXPECT_TRUE(agree("above the mean", above, "whole", whole));
  EXPECT_TRUE(agree("above the mean", above, "light", light));
}

INSTANTIATE_TEST_SUITE_P(Backends, EnvironmentRender, ::testing::Values(BackendKind::kEmbree, BackendKind::kNative),
                         [](const auto& info) { return std::string(backend_name(info.param)); });

}  // namespace environment_render_test
}  // namespace rtpro
