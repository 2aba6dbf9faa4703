// The path integrator's lights: the pdf sample() reports is the one pdf() gives for the same
// point, the pick probabilities sum to 1, and the solid-angle pdf of each area kind integrates to
// the light's visible solid angle (checked by integrating over the sphere of directions).
#include "light_set.h"

#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>

namespace rtpro {
namespace light_set_test {

RenderScene lit_scene() {
  return build_render_scene(parse_scene_text(R"(
rtpro: 1
camera: {position: [0, 1, -5], look_at: [0, 1, 0]}
materials:
  lamp: {type: diffuse, color: [0, 0, 0], emission: [2, 1, 1]}
  both: {type: diffuse, color: [0, 0, 0], emission: [1, 1, 3], emission_sides: both}
lights:
  - {type: point, position: [0, 3, 0], intensity: 5}
  - {type: directional, direction: [0, -1, 0.2], intensity: 1}
  - {type: quad, position: [0, 4, 0], edge1: [1, 0, 0], edge2: [0, 0, -1], intensity: 4}
  - {type: sphere, center: [2, 2, 2], radius: 0.5, intensity: 3}
world:
  - {type: sphere, center: [-2, 2, 0], radius: 0.4, material: lamp}
  - {type: sphere, center: [0, 0, 0], radius: 0.5, material: both}
)",
                                             "lights.yaml"));
}

TEST(LightSet, HoldsTheSceneLightsAndItsEmissiveSpheres) {
  const RenderScene scene = lit_scene();
  const LightSet lights(scene);
  EXPECT_EQ(lights.lights().size(), 6u);
  EXPECT_TRUE(std::holds_alternative<EmissiveSphere>(lights.lights()[4]));
  Hit hit;
  hit.geom_id = 0;
  hit.prim_id = 1;
  EXPECT_EQ(lights.light_of_hit(hit), 5u);
  hit.inst_id = 3;
  EXPECT_EQ(lights.light_of_hit(hit), kInvalidId);  // instanced emitters are not sampled
}

// EnvironmentRadiance::kLater leaves an environment sample's radiance and the pdf of its direction
// to be found (the path integrator does once the shadow ray passes): its direction, and that
// radiance and pdf times the pick's once found, are kNow's sample bit for bit; every other light's
// sample is the same and says it has them (no environment), whichever is asked.
TEST(LightSet, AnEnvironmentSampleCanLeaveItsRadianceAndPdfForLater) {
  const RenderScene scene = lit_scene();
  Image sky(16, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) sky.at(x, y, c) = 0.1f + float((x * 7 + y * 3 + c) % 11);
  const EnvironmentLight environment(Environment{"sky.exr", Color(1.0f), Affine::identity(), true}, std::move(sky),
                                     EnvironmentSampling::kWhole);
  const LightSet lights(scene, &environment);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  int environment_samples = 0, others = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 from{uniform(rng) * 6.0f - 3.0f, uniform(rng) * 3.0f, uniform(rng) * 6.0f - 3.0f};
    const float u_pick = uniform(rng);
    const Sample2D u{uniform(rng), uniform(rng)};
    PathLightSample now, later;
    const bool found_now = lights.sample(from, u_pick, u, nullptr, 0, now, EnvironmentRadiance::kNow);
    const bool found_later = lights.sample(from, u_pick, u, nullptr, 0, later, EnvironmentRadiance::kLater);
    ASSERT_TRUE(found_later || !found_now);
    if (!found_now) {  // an environment direction of pdf 0 found again, which kNow gives no sample
      if (found_later) {
        ASSERT_EQ(later.environment, &environment);
        EXPECT_FALSE(environment.pdf(later.direction) > 0.0f);
      }
      continue;
    }
    EXPECT_EQ(now.environment, nullptr);
    EXPECT_EQ(later.direction, now.direction);
    EXPECT_EQ(later.distance, now.distance);
    EXPECT_EQ(later.delta, now.delta);
    EXPECT_EQ(later.light, now.light);
    if (std::holds_alternative<EnvironmentRef>(lights.lights()[now.light])) {
      ++environment_samples;
      ASSERT_EQ(later.environment, &environment);
      EXPECT_EQ(environment.radiance(later.direction), now.radiance);
      EXPECT_EQ(environment.pdf(later.direction) * later.pdf, now.pdf);
    } else {
      ++others;
      EXPECT_EQ(later.environment, nullptr);
      EXPECT_EQ(later.radiance, now.radiance);
      EXPECT_EQ(later.pdf, now.pdf);
    }
  }
  EXPECT_GT(environment_samples, 500);
  EXPECT_GT(others, 5000);
}

TEST(LightSet, SamplePdfIsThePdfOfTheSampledPoint) {
  const RenderScene scene = lit_scene();
  const LightSet lights(scene);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  int area_samples = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 from{uniform(rng) * 6.0f - 3.0f, uniform(rng) * 3.0f, uniform(rng) * 6.0f - 3.0f};
    const float u_pick = uniform(rng);
    const auto s = lights.sample(from, u_pick, {uniform(rng), uniform(rng)});
    if (!s || s->delta) continue;
    ++area_samples;
    const Vec3 on_light = from + s->direction * s->distance;
    const float pdf = lights.pdf(s->light, from, on_light);
    EXPECT_NEAR(pdf, s->pdf, 2e-3f * s->pdf)
        << "light " << s->light << " from " << from.x << "," << from.y << "," << from.z;
  }
  // The directional light takes half the picks (one share against the tree's), the point light
  // part of the rest: over a fifth are still area samples.
  EXPECT_GT(area_samples, 4000);
}

// ∫ pdf dω over the directions that reach a light is 1 for a light sampled by solid angle:
// estimated with directions uniform in a cone a little wider than the one the light fills, each
// direction's point on the light found by intersecting it.
TEST(LightSet, PdfOfASphereLightIntegratesToOne) {
  const Vec3 center(2.0f, 2.0f, 2.0f);
  const float radius = 0.5f;
  for (const Vec3 from : {Vec3(0.0f, 0.0f, 0.0f), Vec3(1.9f, 1.0f, 2.0f)}) {
    RenderScene scene;
    scene.lights.push_back(SphereLight{center, radius, Color(1.0f), 1});
    const LightSet lights(scene);
    const Vec3 axis = normalize(center - from);
    const float sin_light = radius / length(center - from);
    const float cos_cone = std::cos(std::min(1.2f * std::asin(sin_light), 1.5f));
    Vec3 t1 = std::fabs(axis.x) < 0.9f ? normalize(cross(axis, Vec3(1.0f, 0.0f, 0.0f)))
                                       : normalize(cross(axis, Vec3(0.0f, 1.0f, 0.0f)));
    const Vec3 t2 = cross(axis, t1);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    constexpr int kDirections = 200000;
    double integral = 0.0;
    for (int i = 0; i < kDirections; ++i) {
      const float cos_theta = 1.0f - uniform(rng) * (1.0f - cos_cone);
      const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
      const float phi = 2.0f * std::numbers::pi_v<float> * uniform(rng);
      const Vec3 direction = t1 * (sin_theta * std::cos(phi)) + t2 * (sin_theta * std::sin(phi)) + axis * cos_theta;
      const Ray ray{from, 0.0f, direction};
      if (const auto seen = lights.seen_light(ray, 1e30f)) integral += lights.pdf(seen->index, from, ray.at(seen->t));
    }
    integral *= 2.0 * std::numbers::pi * (1.0 - cos_cone) / kDirections;
    EXPECT_NEAR(integral, 1.0, 0.01);
  }
}

// A camera or BSDF ray sees the nearest light without geometry in (tnear, t_max) and no other: a
// quad in front of a sphere light hides it, a t_max at or before a light's surface hides that
// light, and a ray that starts past the quad sees the sphere.
TEST(LightSet, ARaySeesTheNearestLightWithoutGeometryBeforeItsEnd) {
  const RenderScene scene = build_render_scene(parse_scene_text(R"(
rtpro: 1
camera: {position: [0, 0, -5], look_at: [0, 0, 0]}
lights:
  - {type: quad, position: [0, 0, 3], edge1: [0, 1, 0], edge2: [1, 0, 0], intensity: 4}
  - {type: sphere, center: [0, 0, 5], radius: 1, intensity: 3}
world: []
)",
                                                                "seen.yaml"));
  const LightSet lights(scene);
  const Ray from_origin{Vec3(0.0f, 0.0f, 0.0f), 0.0f, Vec3(0.0f, 0.0f, 1.0f)};
  const std::optional<LightSet::SeenLight> quad = lights.seen_light(from_origin, 100.0f);
  ASSERT_TRUE(quad);
  EXPECT_EQ(quad->index, 0u);  // the sphere, met after it in the list, is farther
  EXPECT_FLOAT_EQ(quad->t, 3.0f);
  EXPECT_GT(quad->radiance.x, 0.0f);
  EXPECT_FALSE(lights.seen_light(from_origin, 3.0f));  // t_max at the quad: (tnear, t_max) is open
  EXPECT_FALSE(lights.seen_light(from_origin, 2.5f));

  const Ray past_the_quad{Vec3(0.0f, 0.0f, 3.5f), 0.0f, Vec3(0.0f, 0.0f, 1.0f)};
  const std::optional<LightSet::SeenLight> sphere = lights.seen_light(past_the_quad, 100.0f);
  ASSERT_TRUE(sphere);
  EXPECT_EQ(sphere->index, 1u);
  EXPECT_FLOAT_EQ(sphere->t, 0.5f);
  EXPECT_NE(sphere->radiance, quad->radiance);
  EXPECT_FALSE(lights.seen_light(past_the_quad, 0.5f));

  // The quad's back faces the sphere: a ray from the sphere towards it sees nothing.
  const Ray back{Vec3(0.0f, 0.0f, 3.5f), 0.0f, Vec3(0.0f, 0.0f, -1.0f)};
  EXPECT_FALSE(lights.seen_light(back, 100.0f));
}

// reads_pick_number and reads_point_numbers may say "no" only when sample() does not depend on
// that number: the path integrator then leaves it undrawn.
RenderScene scene_with_lights(const std::string& lights) {
  return build_render_scene(parse_scene_text(R"(
rtpro: 1
camera: {position: [0, 1, -5], look_at: [0, 1, 0]}
lights:
)" + lights + R"(
world:
  - {type: sphere, center: [0, 0, 0], radius: 0.5}
)",
                                             "lights.yaml"));
}

bool sample_depends_on(const LightSet& lights, bool vary_pick, bool vary_point) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    // Above and below the lights, on both sides of the one-sided quad.
    const Vec3 from{unit(rng) * 12.0f - 6.0f, unit(rng) * 12.0f - 6.0f, unit(rng) * 12.0f - 6.0f};
    const float pick = unit(rng);
    const Sample2D u{unit(rng), unit(rng)};
    const auto a = lights.sample(from, pick, u);
    const float other_pick = vary_pick ? unit(rng) : pick;
    const Sample2D other_u = vary_point ? Sample2D{unit(rng), unit(rng)} : u;
    const auto b = lights.sample(from, other_pick, other_u);
    if (a.has_value() != b.has_value()) return true;
    if (a && (a->light != b->light || a->direction.x != b->direction.x || a->direction.y != b->direction.y ||
              a->distance != b->distance || a->pdf != b->pdf))
      return true;
  }
  return false;
}

TEST(LightSet, SaysWhichOfItsRandomNumbersASampleReads) {
  const std::string point = "  - {type: point, position: [0, 3, 0], intensity: 5}\n";
  const std::string spot = "  - {type: spot, position: [1, 3, 0], direction: [0, -1, 0], intensity: 5}\n";
  const std::string sun = "  - {type: directional, direction: [0, -1, 0.2], intensity: 1}\n";
  const std::string quad = "  - {type: quad, position: [0, 4, 0], edge1: [1, 0, 0], edge2: [0, 0, -1], intensity: 4}\n";
  struct Case {
    std::string lights;
    bool pick, point;
  };
  for (const Case& c :
       {Case{point, false, false}, Case{spot, false, false}, Case{sun, false, false},
        Case{point + spot + sun, true, false}, Case{quad, false, true}, Case{point + quad, true, true}}) {
    const RenderScene scene = scene_with_lights(c.lights);
    const LightSet lights(scene);
    EXPECT_EQ(lights.reads_pick_number(), c.pick) << c.lights;
    EXPECT_EQ(lights.reads_point_numbers(), c.point) << c.lights;
    EXPECT_EQ(sample_depends_on(lights, true, false), c.pick) << c.lights;
    EXPECT_EQ(sample_depends_on(lights, false, true), c.point) << c.lights;
  }
}

}  // namespace light_set_test
}  // namespace rtpro
