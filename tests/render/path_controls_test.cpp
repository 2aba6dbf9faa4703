// The path integrator's Light Paths controls as Cycles has them (scene/render_settings.h,
// PathControls): per-lobe bounce limits against closed-sphere series with analytic sums, paths
// longer than the old limit of 64, the direct and indirect sample clamps, and Filter Glossy.
#include "path_integrator.h"

#include "rtpro/backend/backend.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace rtpro {
namespace path_controls_test {

Image render(const std::string& yaml, const std::vector<std::string>& overrides, BackendKind kind) {
  const RenderScene scene = build_render_scene(parse_scene_text(yaml, "test.yaml", overrides));
  const auto backend = make_backend(kind, scene, {});
  return render_image(scene, *backend, {}).image;
}

// The mean of every pixel's channels 0..2.
double mean_of(const Image& image) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) sum += image.at(x, y, c);
  return sum / (3.0 * image.width * image.height);
}

bool same_pixels(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return false;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c)
        if (a.at(x, y, c) != b.at(x, y, c)) return false;
  return true;
}

class PathControls : public ::testing::TestWithParam<BackendKind> {};

// pbrt-v4's closed sphere with the camera inside: a Lambertian wall of albedo a emitting Le. The
// radiance after at most N bounces is Le·(1 + a + ... + a^N), N being max_depth or, the sphere
// being all diffuse, max_diffuse_depth.
std::string closed_sphere(double albedo, double emission) {
  const std::string a = std::to_string(albedo), le = std::to_string(emission);
  return R"(
rtpro: 1
camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 90, resolution: [12, 12]}
render: {spp: 16, max_depth: 64, integrator: path}
materials:
  wall: {type: diffuse, color: [)" +
         a + ", " + a + ", " + a + "], emission: [" + le + ", " + le + ", " + le + R"(], emission_sides: both}
world: [{type: sphere, center: [0, 0, 0], radius: 1, material: wall}]
)";
}

double partial_sum(double albedo, double emission, int bounces) {
  double sum = 0.0, term = emission;
  for (int k = 0; k <= bounces; ++k, term *= albedo) sum += term;
  return sum;
}

TEST_P(PathControls, DiffuseDepthLimitSumsTheFirstBouncesOfTheClosedSphere) {
  const std::string scene = closed_sphere(0.5, 0.5);
  for (const int n : {1, 2, 3}) {
    SCOPED_TRACE(n);
    const Image limited = render(scene, {"render.max_diffuse_depth=" + std::to_string(n)}, GetParam());
    EXPECT_NEAR(mean_of(limited), partial_sum(0.5, 0.5, n), 0.01);
    // A path of diffuse bounces only ends where max_depth = N would end it, on the same numbers.
    EXPECT_TRUE(same_pixels(limited, render(scene, {"render.max_depth=" + std::to_string(n)}, GetParam())));
  }
}

TEST_P(PathControls, LimitsOfLobesAPathNeverTakesChangeNothing) {
  const std::string scene = closed_sphere(0.5, 0.5);
  const Image plain = render(scene, {"render.max_depth=6"}, GetParam());
  EXPECT_TRUE(same_pixels(
      plain, render(scene, {"render.max_depth=6", "render.max_glossy_depth=1", "render.max_transmission_depth=1"},
                    GetParam())));
  EXPECT_TRUE(same_pixels(plain, render(scene, {"render.max_depth=6", "render.max_diffuse_depth=6"}, GetParam())));
}

// A smooth glass sphere in the white furnace: a ray through it refracts twice. With one
// transmission bounce allowed, the path ends inside (the sphere shows only its Fresnel reflection
// of the sky, about 0.05 at its centre); with two it vanishes into the furnace.
TEST_P(PathControls, TransmissionLimitEndsPathsInsideGlass) {
  const std::string furnace = R"(
rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 8, resolution: [8, 8]}
render: {spp: 8, max_depth: 64, integrator: path}
materials:
  sky: {type: diffuse, color: [0, 0, 0], emission: [1, 1, 1], emission_sides: both}
  glass: {type: dielectric, ior: 1.5}
world:
  - {type: sphere, center: [0, 0, 0], radius: 20, material: sky}
  - {type: sphere, center: [0, 0, 0], radius: 1, material: glass}
)";
  EXPECT_LT(mean_of(render(furnace, {"render.max_transmission_depth=1"}, GetParam())), 0.1);
  EXPECT_GT(mean_of(render(furnace, {"render.max_transmission_depth=2"}, GetParam())), 0.9);
  // Reflections off glass are glossy bounces: one allowed keeps the light refracted straight
  // through and reflected once, and loses only what reflects inside the sphere.
  const double one_reflection = mean_of(render(furnace, {"render.max_glossy_depth=1"}, GetParam()));
  EXPECT_GT(one_reflection, 0.85);
  EXPECT_LT(one_reflection, mean_of(render(furnace, {}, GetParam())));
}

// Albedo 0.97 and Le = 0.03: the series converges to 1 only slowly, 1 − 0.97^(N+1) after N
// bounces: 0.862 at the old limit of 64, 0.99999 at 400. Russian roulette keeps at least 5% from
// going on at every bounce, so the few long paths weigh much: over seeds the mean of this image
// spreads with a standard deviation of about 0.017 (0.06 is 3.5 of them).
TEST_P(PathControls, PathsLongerThan64ReachTheAnalyticValue) {
  const std::string scene = closed_sphere(0.97, 0.03);
  const std::string size = "camera.resolution=[24, 24]";
  EXPECT_NEAR(mean_of(render(scene, {size, "render.max_depth=64"}, GetParam())), partial_sum(0.97, 0.03, 64), 0.06);
  EXPECT_NEAR(mean_of(render(scene, {size, "render.max_depth=400"}, GetParam())), 1.0, 0.06);
}

// A white floor and a white wall lit by a tiny, very bright bulb: the floor under it is a hot
// spot of radiance about 18, and the light it reflects onto the wall (and back) makes the
// fireflies of indirect light. With light sampling alone, a sample's direct light is one
// contribution (the first vertex's light sample, or the bulb seen by the camera) and, at
// max_depth 2, its indirect light one more (the second vertex's light sample).
std::string bulb_scene(const std::string& bulb_emission) {
  return R"(
rtpro: 1
camera: {position: [0, 1.5, -2], look_at: [0, 0.2, 0.6], fov: 60, resolution: [16, 16]}
render: {spp: 4, max_depth: 2, integrator: path, sampling: light}
materials:
  white: {type: diffuse, color: [0.8, 0.8, 0.8]}
  bulb: {type: diffuse, color: [0, 0, 0], emission: )" +
         bulb_emission + R"(}
world:
  - {type: sphere, center: [0, -1000, 0], radius: 1000, material: white}
  - {type: sphere, center: [0, 0, 1001], radius: 1000, material: white}
  - {type: sphere, center: [0, 0.3, 0.6], radius: 0.01, material: bulb}
)";
}

float largest_channel(const Image& image) {
  float largest = 0.0f;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) largest = std::max(largest, image.at(x, y, c));
  return largest;
}

// The largest difference b − a of a pixel channel.
float largest_increase(const Image& a, const Image& b) {
  float largest = -1e30f;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) largest = std::max(largest, b.at(x, y, c) - a.at(x, y, c));
  return largest;
}

TEST_P(PathControls, ClampDirectCapsEveryDirectContribution) {
  const std::string scene = bulb_scene("[20000, 20000, 20000]");
  const std::vector<std::string> direct_only = {"render.max_depth=1"};
  EXPECT_GT(largest_channel(render(scene, direct_only, GetParam())), 5.0f);
  std::vector<std::string> clamped = direct_only;
  clamped.push_back("render.clamp_direct=0.5");
  const Image image = render(scene, clamped, GetParam());
  EXPECT_LE(largest_channel(image), 0.5f * (1.0f + 1e-5f));
  EXPECT_GT(largest_channel(image), 0.45f);
  // The indirect clamp leaves direct light alone; 0 is off.
  EXPECT_TRUE(same_pixels(
      render(scene, direct_only, GetParam()),
      render(scene, {"render.max_depth=1", "render.clamp_indirect=0.5", "render.clamp_direct=0"}, GetParam())));
}

// The second vertex's light samples alone are the difference between max_depth 2 and 1: the
// first vertex's contributions are the same numbers in both.
TEST_P(PathControls, ClampIndirectCapsEveryIndirectContribution) {
  const std::string scene = bulb_scene("[20000, 20000, 20000]");
  const auto indirect_peak = [&](const std::vector<std::string>& clamp) {
    std::vector<std::string> one = {"render.max_depth=1"}, two = {"render.max_depth=2"};
    one.insert(one.end(), clamp.begin(), clamp.end());
    two.insert(two.end(), clamp.begin(), clamp.end());
    return largest_increase(render(scene, one, GetParam()), render(scene, two, GetParam()));
  };
  EXPECT_GT(indirect_peak({}), 1.0f);
  const float clamped = indirect_peak({"render.clamp_indirect=0.2"});
  EXPECT_LE(clamped, 0.2f + 1e-4f);
  EXPECT_GT(clamped, 0.05f);
  EXPECT_GT(indirect_peak({"render.clamp_direct=0.2"}), 1.0f);
}

// Cycles' rule: the channel mean is capped, the colour scaled as a whole. A bulb of colour 2:1:0
// clamped to 1 gives samples of (2, 1, 0): one channel above the clamp, the hue kept.
TEST_P(PathControls, ClampKeepsTheHueAndCapsTheChannelMean) {
  const Image image =
      render(bulb_scene("[20000, 10000, 0]"), {"render.max_depth=1", "render.clamp_direct=1"}, GetParam());
  float largest_red = 0.0f;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float r = image.at(x, y, 0), g = image.at(x, y, 1), b = image.at(x, y, 2);
      EXPECT_LE((r + g + b) / 3.0f, 1.0f + 1e-5f);
      EXPECT_EQ(b, 0.0f);
      if (r > 0.0f) {
        EXPECT_NEAR(g / r, 0.5f, 1e-4f);
      }
      largest_red = std::max(largest_red, r);
    }
  EXPECT_GT(largest_red, 1.5f);
}

// A diffuse wall lit by a small bulb through a sharp glossy floor (roughness 0.1): samples that
// bounce off the wall onto the floor find the bulb in its narrow reflection rarely, and then
// brightly (at 4 spp one pixel is off by 130 where the image is about 0.5). Filter Glossy widens
// the floor's lobe on such paths: the error against each setting's own 1024-spp image falls
// (measured: a mean absolute error of 4.3 times the image's mean without it, 0.57 with it).
TEST_P(PathControls, FilterGlossyTamesACausticSeenThroughADiffuseBounce) {
  const std::string scene = R"(
rtpro: 1
camera: {position: [0, 0.9, -1], look_at: [0, 0.9, 1], fov: 30, resolution: [8, 8]}
render: {spp: 4, max_depth: 3, integrator: path}
materials:
  wall: {type: diffuse, color: [0.8, 0.8, 0.8]}
  floor: {type: conductor, color: [1, 1, 1], roughness: 0.1}
  bulb: {type: diffuse, color: [0, 0, 0], emission: [500, 500, 500]}
world:
  - {type: sphere, center: [0, -1000, 0], radius: 1000, material: floor}
  - {type: sphere, center: [0, 0, 1001], radius: 1000, material: wall}
  - {type: sphere, center: [0, 0.3, -0.5], radius: 0.05, material: bulb}
)";
  // The mean absolute error of the 4-spp image against the 1024-spp one, over the latter's mean.
  const auto relative_error = [&](const std::vector<std::string>& filter) {
    std::vector<std::string> reference_settings = filter;
    reference_settings.push_back("render.spp=1024");
    const Image image = render(scene, filter, GetParam()), reference = render(scene, reference_settings, GetParam());
    double error = 0.0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int c = 0; c < 3; ++c) error += std::fabs(image.at(x, y, c) - reference.at(x, y, c));
    return error / (3.0 * image.width * image.height) / mean_of(reference);
  };
  const double off = relative_error({}), on = relative_error({"render.filter_glossy=1"});
  std::cout << "filter glossy: relative error " << off << " off, " << on << " on\n";
  EXPECT_LT(on, 0.25 * off);
  EXPECT_LT(on, 1.0);
  EXPECT_TRUE(same_pixels(render(scene, {}, GetParam()), render(scene, {"render.filter_glossy=0"}, GetParam())));
}

INSTANTIATE_TEST_SUITE_P(Backends, PathControls, ::testing::Values(BackendKind::kNative, BackendKind::kEmbree),
                         [](const auto& info) { return std::string(backend_name(info.param)); });

}  // namespace path_controls_test
}  // namespace rtpro
