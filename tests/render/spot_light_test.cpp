// Spot lights (scene/light.h) as shading and the path integrator see them: the cone's falloff,
// what a Whitted light sample and the light set return inside and outside the cone, the share of
// the picks a spot light gets among other lights, and the radiance of a white plane lit by one
// against the analytic answer, with both backends.
#include "rtpro/backend/backend.h"
#include "rtpro/render/camera.h"
#include "light_sample.h"
#include "light_set.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace rtpro {
namespace spot_light_test {

constexpr double kPi = std::numbers::pi;
constexpr double kRadiansPerDegree = kPi / 180.0;

SpotLight make_spot(const Vec3& position, const Vec3& axis, const Color& radiance, double inner_degrees,
                    double outer_degrees) {
  return SpotLight{position, normalize(axis), radiance, float(std::cos(inner_degrees * kRadiansPerDegree)),
                   float(std::cos(outer_degrees * kRadiansPerDegree))};
}

// pbrt-v4's falloff, in double: smoothstep(cos outer, cos inner, cos θ).
double expected_falloff(double theta_degrees, double inner_degrees, double outer_degrees) {
  const double c = std::cos(theta_degrees * kRadiansPerDegree);
  const double c_inner = std::cos(inner_degrees * kRadiansPerDegree),
               c_outer = std::cos(outer_degrees * kRadiansPerDegree);
  const double t = std::clamp((c - c_outer) / (c_inner - c_outer), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// A unit direction θ degrees off +z, in the xz plane.
Vec3 off_z(double theta_degrees) {
  return Vec3(float(std::sin(theta_degrees * kRadiansPerDegree)), 0.0f,
              float(std::cos(theta_degrees * kRadiansPerDegree)));
}

TEST(SpotLight, FallsOffAsASmoothStepInCosineBetweenItsCones) {
  const SpotLight spot = make_spot(Vec3(0.0f), Vec3(0, 0, 1), Color(1.0f), 20.0, 40.0);
  for (double theta = 0.0; theta <= 180.0; theta += 0.25)
    EXPECT_NEAR(spot.falloff(off_z(theta)), expected_falloff(theta, 20.0, 40.0), 2e-6) << theta << " degrees";
  EXPECT_EQ(spot.falloff(off_z(19.99)), 1.0f);  // full inside the inner cone
  EXPECT_EQ(spot.falloff(off_z(40.01)), 0.0f);  // exactly nothing outside the outer one
  EXPECT_EQ(spot.falloff(Vec3(0, 0, -1)), 0.0f);
  EXPECT_NEAR(spot.falloff(off_z(30.0)), expected_falloff(30.0, 20.0, 40.0), 1e-6);
}

TEST(SpotLight, EqualConesAreAHardEdgeAndAHemisphereIsAllowed) {
  const SpotLight hard = make_spot(Vec3(0.0f), Vec3(0, 0, 1), Color(1.0f), 30.0, 30.0);
  EXPECT_EQ(hard.falloff(off_z(29.9)), 1.0f);
  EXPECT_EQ(hard.falloff(off_z(30.1)), 0.0f);
  const SpotLight hemisphere = make_spot(Vec3(0.0f), Vec3(0, 0, 1), Color(1.0f), 0.0, 90.0);
  EXPECT_EQ(hemisphere.falloff(off_z(0.0)), 1.0f);
  EXPECT_NEAR(hemisphere.falloff(off_z(60.0)), expected_falloff(60.0, 0.0, 90.0), 1e-6);
  EXPECT_EQ(hemisphere.falloff(off_z(90.5)), 0.0f);
}

// Whitted: where a point light's sample goes, with its radiance times the falloff (no distance
// falloff under Whitted); one sample, never seen, emitting nothing a camera ray shows.
TEST(SpotLight, WhittedSampleIsThePointLightsTimesTheFalloff) {
  const Vec3 position(1.0f, 4.0f, -2.0f);
  const Light spot = make_spot(position, Vec3(0, -1, 0), Color(2.0f, 1.0f, 0.5f), 10.0, 35.0);
  const Light point = PointLight{position, Color(2.0f, 1.0f, 0.5f)};
  EXPECT_EQ(light_samples_per_axis(spot), 1);
  EXPECT_EQ(hit_light(spot, Ray{Vec3(1.0f, 0.0f, -2.0f), 0.0f, Vec3(0, 1, 0)}, 100.0f), kLightMissed);
  EXPECT_EQ(light_emission(spot), Color(0.0f));
  for (const double theta : {0.0, 5.0, 15.0, 25.0, 34.0, 36.0, 80.0}) {
    const float d = 3.0f;
    const Vec3 below =
        position +
        Vec3(float(std::sin(theta * kRadiansPerDegree)), -float(std::cos(theta * kRadiansPerDegree)), 0.0f) * d;
    const LightSample s = sample_light(spot, below, Sample2D{0.3f, 0.7f});
    const LightSample p = sample_light(point, below, Sample2D{0.3f, 0.7f});
    EXPECT_EQ(s.direction, p.direction);
    EXPECT_EQ(s.distance, p.distance);
    const double falloff = expected_falloff(theta, 10.0, 35.0);
    EXPECT_NEAR(s.radiance.x, 2.0 * falloff, 1e-5) << theta;
    EXPECT_NEAR(s.radiance.z, 0.5 * falloff, 1e-5) << theta;
    if (theta > 35.0) {
      EXPECT_EQ(s.radiance, Color(0.0f)) << theta;
    }
  }
}

// The path integrator's sample: intensity × falloff / d², a delta light (pdf 1 alone, no pdf for
// a BSDF sample), nothing outside the cone.
TEST(SpotLight, PathSampleFallsOffWithTheSquareOfDistanceAndIsADeltaLight) {
  RenderScene scene;
  const Vec3 position(0.0f, 5.0f, 0.0f);
  scene.lights.push_back(make_spot(position, Vec3(0, -1, 0), Color(6.0f, 3.0f, 3.0f), 15.0, 30.0));
  const LightSet set(scene);
  ASSERT_EQ(set.lights().size(), 1u);
  for (const double theta : {0.0, 10.0, 20.0, 25.0, 29.5, 30.5, 60.0, 120.0})
    for (const float d : {0.5f, 2.0f, 7.0f}) {
      SCOPED_TRACE(std::to_string(theta) + " degrees at " + std::to_string(d));
      const Vec3 outward(float(std::sin(theta * kRadiansPerDegree)), -float(std::cos(theta * kRadiansPerDegree)), 0.0f);
      const Vec3 from = position + outward * d;
      const std::optional<PathLightSample> s = set.sample(from, 0.5f, {0.25f, 0.75f});
      const double falloff = expected_falloff(theta, 15.0, 30.0);
      if (theta > 30.0) {
        EXPECT_FALSE(s);
        continue;
      }
      ASSERT_TRUE(s);
      EXPECT_TRUE(s->delta);
      EXPECT_EQ(s->pdf, 1.0f);
      EXPECT_EQ(s->light, 0u);
      EXPECT_NEAR(s->distance, d, 1e-5f * d);
      EXPECT_NEAR(dot(s->direction, -outward), 1.0f, 1e-6f);
      EXPECT_NEAR(s->radiance.x, 6.0 * falloff / (double(d) * d), 2e-5 * 6.0 / (double(d) * d));
      EXPECT_NEAR(s->radiance.y, 3.0 * falloff / (double(d) * d), 2e-5 * 3.0 / (double(d) * d));
      EXPECT_EQ(set.pdf(0, from, position), 0.0f);
    }
  EXPECT_FALSE(set.sample(position, 0.5f, {0.5f, 0.5f}));  // at the light itself
}

// pbrt-v4's power of a spot light: the inner cone at full intensity, the falloff band at half.
double spot_power(double intensity, double inner_degrees, double outer_degrees) {
  const double c_inner = std::cos(inner_degrees * kRadiansPerDegree),
               c_outer = std::cos(outer_degrees * kRadiansPerDegree);
  return 2.0 * kPi * intensity * ((1.0 - c_inner) + 0.5 * (c_inner - c_outer));
}

// Picked by power (render.light_sampler: power) among a point light and a quad light, over a fine
// grid of u_pick from a point every light reaches; a delta sample's pdf is its pick probability.
TEST(SpotLight, IsPickedInProportionToItsPower) {
  RenderScene scene;
  scene.render.light_sampler = LightSamplerKind::kPower;
  scene.lights.push_back(PointLight{Vec3(2.0f, 3.0f, 0.0f), Color(2.0f)});
  scene.lights.push_back(make_spot(Vec3(0.0f, 4.0f, 0.0f), Vec3(0, -1, 0), Color(30.0f, 20.0f, 10.0f), 15.0, 35.0));
  scene.lights.push_back(
      QuadLight{Vec3(-1.0f, 5.0f, -1.0f), Vec3(2, 0, 0), Vec3(0, 0, 2), Vec3(0, -1, 0), 4.0f, Color(1.5f), 1});
  const LightSet set(scene);
  const double power[3] = {4.0 * kPi * 2.0, spot_power(20.0, 15.0, 35.0), kPi * 4.0 * 1.5};
  const double total = power[0] + power[1] + power[2];
  constexpr int kPicks = 1 << 16;
  int picked[3] = {0, 0, 0};
  for (int i = 0; i < kPicks; ++i) {
    const std::optional<PathLightSample> s =
        set.sample(Vec3(0.1f, 0.0f, 0.2f), (float(i) + 0.5f) / kPicks, {0.4f, 0.6f});
    ASSERT_TRUE(s) << i;
    ASSERT_LT(s->light, 3u);
    ++picked[s->light];
    if (s->delta) {
      EXPECT_NEAR(s->pdf, power[s->light] / total, 1e-5 * power[s->light] / total);
    }
  }
  for (int l = 0; l < 3; ++l) EXPECT_NEAR(double(picked[l]) / kPicks, power[l] / total, 4.0 / kPicks) << "light " << l;
}

// The light tree never rules a spot light out where its cone reaches: from points inside it,
// some u_pick picks it, with the pdf the tree gives it.
TEST(SpotLight, TheLightTreePicksItWhereItsConeReaches) {
  RenderScene scene;
  scene.lights.push_back(PointLight{Vec3(3.0f, 3.0f, 3.0f), Color(50.0f)});
  scene.lights.push_back(make_spot(Vec3(0.0f, 4.0f, 0.0f), Vec3(0, -1, 0), Color(1.0f), 5.0, 25.0));
  const LightSet set(scene);
  for (const double theta : {0.0, 10.0, 20.0, 24.5}) {
    const Vec3 from =
        Vec3(0.0f, 4.0f, 0.0f) +
        Vec3(float(std::sin(theta * kRadiansPerDegree)), -float(std::cos(theta * kRadiansPerDegree)), 0.0f) * 3.0f;
    int spot_picks = 0;
    for (int i = 0; i < 4096; ++i) {
      const std::optional<PathLightSample> s = set.sample(from, (float(i) + 0.5f) / 4096.0f, {0.5f, 0.5f});
      if (s && s->light == 1u) ++spot_picks;
    }
    EXPECT_GT(spot_picks, 0) << theta << " degrees";
  }
}

// A white Lambertian plane y = 0 (two triangles, 100 units wide) under a spot light at height h
// pointing straight down, seen from straight above: with max_depth 1 only direct light counts,
// and at a point at distance r from the axis the radiance is (1/π)·I·falloff(θ)·cos θ / d²
// (d² = h² + r², cos θ = h/d) under `path`, and I·falloff(θ)·cos θ under `whitted` (no distance
// falloff there, no 1/π). Each pixel is the mean over its footprint (a rectangle on the plane):
// compared with that mean integrated finely, within a small part of how much the radiance
// varies across the pixel (the samples' own error).
constexpr float kHeight = 2.0f;
constexpr double kInner = 20.0, kOuter = 40.0, kIntensity = 3.0;

std::string lit_plane(const std::string& integrator, int spp) {
  const auto plane =
      test::write_file("plane.obj", "v -50 0 -50\nv -50 0 50\nv 50 0 50\nv 50 0 -50\nf 1 2 3\nf 1 3 4\n");
  return R"(rtpro: 1
camera: {position: [0, 6, 0], look_at: [0, 0, 0], up: [0, 0, 1], fov: 50, resolution: [64, 64]}
render: {integrator: )" +
         integrator + ", spp: " + std::to_string(spp) + R"(, max_depth: 1, ambient: 0, background: [0, 0, 0]}
materials:
  white: {type: diffuse, color: [1, 1, 1]}
lights:
  - {type: spot, position: [0, 2, 0], direction: [0, -1, 0], intensity: 3, inner_angle: 20, outer_angle: 40}
world:
  - {type: mesh, file: ")" +
         plane.string() +
         R"(", material: white}
)";
}

double plane_radiance(double x, double z, bool path) {
  const double d2 = double(kHeight) * kHeight + x * x + z * z;
  const double d = std::sqrt(d2);
  const double cos_theta = kHeight / d;
  const double theta = std::acos(cos_theta) / kRadiansPerDegree;
  const double arriving = kIntensity * expected_falloff(theta, kInner, kOuter) * cos_theta;
  return path ? arriving / d2 / kPi : arriving;
}

// Where the ray through film point (px, py) meets the plane.
Vec3 on_plane(const RenderCamera& camera, double px, double py) {
  const Ray ray = camera_ray(camera, float(px), float(py), Sample2D{0.5f, 0.5f});
  return ray.org + ray.dir * (-ray.org.y / ray.dir.y);
}

struct PixelCounts {
  int inside = 0, band = 0, outside = 0;
  double worst = 0.0;  // the largest error as a share of its tolerance
};

PixelCounts expect_plane_matches_the_analytic_radiance(const RenderScene& scene, const Image& image, bool path) {
  const double inner_radius = kHeight * std::tan(kInner * kRadiansPerDegree);
  const double outer_radius = kHeight * std::tan(kOuter * kRadiansPerDegree);
  PixelCounts counts;
  constexpr int kSteps = 24;  // per side of the pixel, for its mean
  for (int py = 0; py < image.height; ++py)
    for (int px = 0; px < image.width; ++px) {
      double mean = 0.0, lowest = 1e30, highest = 0.0, r_min = 1e30, r_max = 0.0;
      for (int j = 0; j < kSteps; ++j)
        for (int i = 0; i < kSteps; ++i) {
          const Vec3 q = on_plane(scene.camera, px + (i + 0.5) / kSteps, py + (j + 0.5) / kSteps);
          const double radiance = plane_radiance(q.x, q.z, path);
          mean += radiance / (kSteps * kSteps);
        }
      for (int j = 0; j <= kSteps; ++j)  // the extremes: the radiance falls with r, which is least or most on the edges
        for (int i = 0; i <= kSteps; ++i) {
          const Vec3 q = on_plane(scene.camera, px + double(i) / kSteps, py + double(j) / kSteps);
          const double r = std::hypot(double(q.x), double(q.z));
          r_min = std::min(r_min, r);
          r_max = std::max(r_max, r);
          const double radiance = plane_radiance(q.x, q.z, path);
          lowest = std::min(lowest, radiance);
          highest = std::max(highest, radiance);
        }
      const double value = image.at(px, py, 0);
      EXPECT_EQ(image.at(px, py, 1), value);  // white light, white plane
      if (r_min > outer_radius) {
        ++counts.outside;
        EXPECT_EQ(value, 0.0) << "pixel " << px << "," << py << " outside the outer cone";
        continue;
      }
      if (r_max < inner_radius) ++counts.inside;
      if (r_min > inner_radius && r_max < outer_radius) ++counts.band;
      const double tolerance = 0.1 * (highest - lowest) + 2e-4 * highest + 1e-6;
      EXPECT_NEAR(value, mean, tolerance) << "pixel " << px << "," << py << " at r " << r_min << ".." << r_max;
      counts.worst = std::max(counts.worst, std::fabs(value - mean) / tolerance);
    }
  return counts;
}

void expect_enough_of_each_part(const PixelCounts& counts) {
  std::cout << "[spot] pixels inside the inner cone " << counts.inside << ", in the falloff band " << counts.band
            << ", outside " << counts.outside << "; largest error " << counts.worst << " of its tolerance\n";
  EXPECT_GE(counts.inside, 150);
  EXPECT_GE(counts.band, 400);
  EXPECT_GE(counts.outside, 1000);
}

class SpotLitPlane : public ::testing::TestWithParam<BackendKind> {};

TEST_P(SpotLitPlane, PathTracedRadianceIsTheAnalyticOne) {
  const RenderScene scene = build_render_scene(parse_scene_text(lit_plane("path", 64), "plane.yaml"));
  const auto backend = make_backend(GetParam(), scene, {});
  const Image image = render_image(scene, *backend, {}).image;
  expect_enough_of_each_part(expect_plane_matches_the_analytic_radiance(scene, image, true));
}

TEST_P(SpotLitPlane, WhittedRadianceIsTheConeFactorWithoutDistanceFalloff) {
  const RenderScene scene = build_render_scene(parse_scene_text(lit_plane("whitted", 64), "plane.yaml"));
  const auto backend = make_backend(GetParam(), scene, {});
  const Image image = render_image(scene, *backend, {}).image;
  expect_enough_of_each_part(expect_plane_matches_the_analytic_radiance(scene, image, false));
}

INSTANTIATE_TEST_SUITE_P(Backends, SpotLitPlane, ::testing::Values(BackendKind::kEmbree, BackendKind::kNative),
                         [](const auto& info) { return info.param == BackendKind::kEmbree ? "embree" : "native"; });

}  // namespace spot_light_test
}  // namespace rtpro
