// Light linking (scene/light_links.h) in both integrators, with both backends: a light excluded
// from an object leaves that object's pixels bit for bit as the same scene without the light, a
// light excluded from every object leaves the whole path-traced image so (the linked light set
// picks as the smaller scene's would, and rays from the objects pass the excluded area light), and
// an object that casts no shadows from a light lets that light's shadow rays through, only its.
#include "rtpro/backend/backend.h"
#include "rtpro/render/environment_light.h"
#include "light_set.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include "test_paths.h"

#include <gtest/gtest.h>

#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace rtpro {
namespace light_linking_test {

Image render(const std::string& yaml, BackendKind kind, const std::vector<std::string>& overrides = {}) {
  const RenderScene scene = build_render_scene(parse_scene_text(yaml, "linking.yaml", overrides));
  const auto backend = make_backend(kind, scene, {});
  std::optional<EnvironmentLight> environment;
  if (scene.environment) environment.emplace(*scene.environment, Image(), environment_sampling_for(scene.render));
  RenderOptions options;
  options.environment = environment ? &*environment : nullptr;
  return render_image(scene, *backend, options).image;
}

// Pixels whose bits differ (a NaN equals itself here, +0 and -0 differ).
int differing_pixels(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  int differing = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float va = a.at(x, y, c), vb = b.at(x, y, c);
        if (std::memcmp(&va, &vb, sizeof va) != 0) {
          ++differing;
          break;
        }
      }
  return differing;
}

double sum(const Image& image) {
  double total = 0.0;
  for (const float v : image.data) total += v;
  return total;
}

// A ground sphere, a ball on it and a small lamp (an emissive sphere), under a constant sky, a key
// point light, a spot and the area light A (a quad above the ball, facing down). `links` holds
// the light_linking / shadow_linking keys of the ground, the ball and the lamp.
struct Links {
  std::string ground, ball, lamp;
};

const std::string kLightA =
    "  - {type: quad, name: A, position: [0.5, 3.5, 0], edge1: [1.5, 0, 0], edge2: [0, 0, 1.5], intensity: 6}\n";

std::string scene(const std::string& camera, int max_depth, const Links& links, bool with_a,
                  const std::string& integrator = "path") {
  const auto entry = [](const std::string& keys) { return keys.empty() ? std::string() : ", " + keys; };
  return "rtpro: 1\n"
         "camera: " +
         camera +
         "\n"
         "render: {integrator: " +
         integrator + ", spp: 6, max_depth: " + std::to_string(max_depth) +
         ", background: [0, 0, 0], ambient: 0}\n"
         "environment: {color: [0.15, 0.2, 0.3]}\n"
         "materials:\n"
         "  clay: {type: diffuse, color: [0.7, 0.5, 0.4]}\n"
         "  chrome: {type: conductor, roughness: 0.2, color: [0.9, 0.9, 0.9]}\n"
         "  lamp: {type: diffuse, color: [0, 0, 0], emission: [6, 4, 2]}\n"
         "lights:\n"
         "  - {type: point, name: key, position: [3, 5, -4], intensity: 30}\n" +
         (with_a ? kLightA : std::string()) +
         "  - {type: spot, name: rim, position: [-3, 4, 3], look_at: [0, 1, 0], intensity: 40, outer_angle: 25}\n"
         "world:\n"
         "  - {type: sphere, center: [0, -1000, 0], radius: 1000, material: clay" +
         entry(links.ground) +
         "}\n"
         "  - {type: sphere, center: [0, 1, 0], radius: 1, material: chrome" +
         entry(links.ball) +
         "}\n"
         "  - {type: sphere, center: [2.2, 0.4, 1.5], radius: 0.4, material: lamp" +
         entry(links.lamp) + "}\n";
}

// Only the ground in view (looking down beside the ball), or the ball and what surrounds it.
const std::string kGroundView = "{position: [-3, 2.5, -3], look_at: [-2.6, 0, -1.5], fov: 30, resolution: [40, 30]}";
const std::string kBallView = "{position: [0, 1.6, -4.5], look_at: [0, 0.9, 0], fov: 40, resolution: [40, 30]}";

class LightLinking : public ::testing::TestWithParam<BackendKind> {};

// Direct light only (max_depth 1): what reaches the ground is its emission and its own light
// samples, so with A excluded from the ground its pixels are those of the scene without A; the
// ball, which A still lights, shows that A is there.
TEST_P(LightLinking, AnExcludedLightLeavesTheObjectAsTheSceneWithoutIt) {
  for (const char* sampler : {"tree", "power"}) {
    SCOPED_TRACE(sampler);
    const std::vector<std::string> set{std::string("render.light_sampler=") + sampler};
    const Links links{"light_linking: {not_illuminated_by: [A]}", "", ""};
    const Image linked = render(scene(kGroundView, 1, links, true), GetParam(), set);
    const Image without_a = render(scene(kGroundView, 1, {}, false), GetParam(), set);
    const Image with_a = render(scene(kGroundView, 1, {}, true), GetParam(), set);
    EXPECT_EQ(differing_pixels(linked, without_a), 0);
    EXPECT_GT(differing_pixels(with_a, without_a), 600) << "A must light the ground unless it is linked away";

    const Image ball_linked = render(scene(kBallView, 1, links, true), GetParam(), set);
    const Image ball_without_a = render(scene(kBallView, 1, {}, false), GetParam(), set);
    EXPECT_GT(differing_pixels(ball_linked, ball_without_a), 100) << "A still lights the ball";
  }
}

// Every bounce: A excluded from every object, in as many spellings as there are objects (and a
// shadow linking of A, which then has no shadow rays), is the scene without A in every pixel.
TEST_P(LightLinking, ALightExcludedEverywhereIsTheSceneWithoutIt) {
  const Links links{"light_linking: {not_illuminated_by: [A]}", "light_linking: {illuminated_by: [key, rim]}",
                    "light_linking: {illuminated_by: [rim, key]}, shadow_linking: {no_shadows_from: [A]}"};
  for (const char* sampler : {"tree", "power"}) {
    SCOPED_TRACE(sampler);
    const std::vector<std::string> set{std::string("render.light_sampler=") + sampler};
    const Image linked = render(scene(kBallView, 8, links, true), GetParam(), set);
    const Image without_a = render(scene(kBallView, 8, {}, false), GetParam(), set);
    const Image with_a = render(scene(kBallView, 8, {}, true), GetParam(), set);
    EXPECT_EQ(differing_pixels(linked, without_a), 0);
    EXPECT_GT(differing_pixels(with_a, without_a), 600);
  }
}

TEST_P(LightLinking, WhittedLeavesAnExcludedLightsObjectAsTheSceneWithoutIt) {
  const Links links{"light_linking: {illuminated_by: [key, rim]}", "", ""};
  const Image linked = render(scene(kGroundView, 1, links, true, "whitted"), GetParam());
  const Image without_a = render(scene(kGroundView, 1, {}, false, "whitted"), GetParam());
  const Image with_a = render(scene(kGroundView, 1, {}, true, "whitted"), GetParam());
  EXPECT_EQ(differing_pixels(linked, without_a), 0);
  EXPECT_GT(differing_pixels(with_a, without_a), 600);
}

// A ground lit by a distant point light (the sun), seen from above, and a ball out of view that
// shades part of it; a second light (the bulb) behind the ball on the same line. Direct light
// only, and nothing but the lights lights the ground. (Point lights: a directional light's share
// of the picks would depend on the scene's bounds, which the ball changes.)
std::string shadow_scene(const std::string& integrator, const std::string& ball_keys, bool ball, bool second_light) {
  return "rtpro: 1\n"
         "camera: {position: [0, 6, 0], look_at: [0, 0, 0], up: [0, 0, 1], fov: 50, resolution: [40, 40]}\n"
         "render: {integrator: " +
         integrator +
         ", spp: 4, max_depth: 1, background: [0, 0, 0], ambient: 0}\n"
         "materials:\n"
         "  white: {type: diffuse, color: [0.8, 0.8, 0.8]}\n"
         "lights:\n"
         "  - {type: point, name: sun, position: [-20, 20, 0], intensity: 800}\n" +
         (second_light ? "  - {type: point, name: bulb, position: [-8, 8, 0], intensity: 60}\n" : "") +
         "world:\n"
         "  - {type: sphere, center: [0, -1000, 0], radius: 1000, material: white}\n" +
         (ball ? "  - {type: sphere, center: [-5, 5, 0], radius: 1.5, material: white" +
                     (ball_keys.empty() ? std::string() : ", " + ball_keys) + "}\n"
               : std::string());
}

TEST_P(LightLinking, AnObjectThatCastsNoShadowsFromALightIsTransparentToItsShadowRaysOnly) {
  for (const char* integrator : {"path", "whitted"}) {
    SCOPED_TRACE(integrator);
    const Image no_ball = render(shadow_scene(integrator, "", false, false), GetParam());
    const Image shading = render(shadow_scene(integrator, "", true, false), GetParam());
    ASSERT_GT(differing_pixels(shading, no_ball), 100) << "the ball must shade the ground in view";
    EXPECT_LT(sum(shading), sum(no_ball));
    const Image passing =
        render(shadow_scene(integrator, "shadow_linking: {no_shadows_from: [sun]}", true, false), GetParam());
    EXPECT_EQ(differing_pixels(passing, no_ball), 0);
    const Image blocking =
        render(shadow_scene(integrator, "shadow_linking: {shadows_from: [sun]}", true, false), GetParam());
    EXPECT_EQ(differing_pixels(blocking, shading), 0);

    // With a second light the ball still shades: transparent to the sun's shadow rays only.
    const Image both_no_ball = render(shadow_scene(integrator, "", false, true), GetParam());
    const Image both_passing_sun =
        render(shadow_scene(integrator, "shadow_linking: {shadows_from: [bulb]}", true, true), GetParam());
    const Image both_passing_all =
        render(shadow_scene(integrator, "shadow_linking: {shadows_from: []}", true, true), GetParam());
    EXPECT_EQ(differing_pixels(both_passing_all, both_no_ball), 0);
    EXPECT_LT(sum(both_passing_sun), sum(both_no_ball) - 1e-3);  // the bulb's shadow of the ball
  }
}

// The light set's view of a group: its lights' pick probabilities sum to 1 at any point, an
// excluded light's is 0 and so is its pdf, and each is what the scene without the excluded light
// gives the same light.
TEST(LinkedLightSet, AGroupPicksAmongItsLightsAsTheSceneWithoutTheOthers) {
  const Links links{"light_linking: {not_illuminated_by: [A]}", "light_linking: {illuminated_by: [rim]}", ""};
  for (const char* sampler : {"tree", "power"}) {
    SCOPED_TRACE(sampler);
    const std::vector<std::string> set{std::string("render.light_sampler=") + sampler};
    const RenderScene linked = build_render_scene(parse_scene_text(scene(kBallView, 8, links, true), "l.yaml", set));
    const RenderScene without_a = build_render_scene(parse_scene_text(scene(kBallView, 8, {}, false), "w.yaml", set));
    const EnvironmentLight linked_sky(*linked.environment, Image(), EnvironmentSampling::kWhole),
        sky(*without_a.environment, Image(), EnvironmentSampling::kWhole);
    const LightSet lights(linked, &linked_sky), fewer(without_a, &sky);
    ASSERT_EQ(linked.links.groups.size(), 3u);
    ASSERT_EQ(lights.lights().size(), fewer.lights().size() + 1);
    const std::uint32_t ground = linked.links.group_of(0, 0), ball = linked.links.group_of(0, 1);
    EXPECT_EQ(linked.links.group_of(0, 2), 0u);
    for (const Vec3& p : {Vec3(0.0f, 0.0f, -2.0f), Vec3(1.0f, 2.0f, 0.5f), Vec3(-3.0f, 0.1f, 2.0f)}) {
      double all = 0.0, ground_sum = 0.0, ball_sum = 0.0;
      for (std::uint32_t i = 0; i < lights.lights().size(); ++i) {
        all += lights.pick_probability(i, p);
        ground_sum += lights.pick_probability(i, p, ground);
        ball_sum += lights.pick_probability(i, p, ball);
      }
      EXPECT_NEAR(all, 1.0, 1e-5);
      EXPECT_NEAR(ground_sum, 1.0, 1e-5);
      EXPECT_NEAR(ball_sum, 1.0, 1e-5);
      EXPECT_EQ(lights.pick_probability(1, p, ground), 0.0f);  // A
      EXPECT_EQ(lights.pdf(1, p, Vec3(0.5f, 3.5f, 0.0f), ground), 0.0f);
      EXPECT_EQ(lights.pick_probability(0, p, ball), 0.0f);  // key
      EXPECT_EQ(lights.pick_probability(1, p, ball), 0.0f);
      // The ground's group against the scene without A, light by light (A is index 1 there).
      for (std::uint32_t i = 0; i < fewer.lights().size(); ++i)
        EXPECT_EQ(lights.pick_probability(i < 1 ? i : i + 1, p, ground), fewer.pick_probability(i, p)) << i;
      EXPECT_EQ(lights.environment_pdf(Vec3(0, 1, 0), ground), fewer.environment_pdf(Vec3(0, 1, 0)));
    }
    EXPECT_GT(lights.pick_probability(2, Vec3(0.0f, 1.0f, 0.0f), ball), 0.0f);  // rim, on its axis
    // A ray from the ground through A passes it; the camera's (group 0) sees it.
    const Ray up{Vec3(0.5f, 1.0f, 0.0f), 0.0f, Vec3(0.0f, 1.0f, 0.0f)};
    EXPECT_TRUE(lights.seen_light(up, 100.0f));
    EXPECT_FALSE(lights.seen_light(up, 100.0f, ground));
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, LightLinking, ::testing::Values(BackendKind::kEmbree, BackendKind::kNative),
                         [](const auto& info) { return info.param == BackendKind::kEmbree ? "embree" : "native"; });

}  // namespace light_linking_test
}  // namespace rtpro
