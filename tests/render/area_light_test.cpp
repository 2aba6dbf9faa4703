// Area lights: what arrives from them against closed-form irradiance, soft-shadow penumbrae
// against the exactly integrated visible part of a sphere light, both backends.
#include "rtpro/backend/backend.h"
#include "rtpro/core/error.h"
#include "light_sample.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rtpro {
namespace area_light_test {

constexpr double kPi = std::numbers::pi;

// A 1×1 image seeing only the ground point at the origin (normal +z): its value is the
// irradiance there (albedo 1, no ambient, no highlights), averaged over `spp` camera samples.
RenderScene irradiance_probe(const Light& light, int spp) {
  RenderScene scene;
  CameraDesc camera;
  camera.position = {0.0f, 0.0f, 10.0f};
  camera.look_at = {0.0f, 0.0f, 0.0f};
  camera.up = {0.0f, 1.0f, 0.0f};
  camera.fov_degrees = 0.001f;
  camera.width = camera.height = 1;
  scene.camera = make_render_camera(camera);
  scene.render.spp = spp;
  scene.render.max_depth = 0;
  scene.render.ambient = 0.0f;
  scene.render.background = Color(0.0f);
  scene.materials.push_back(test::phong_material(Color(1.0f), 0.0f, 1.0f, 0.0f));
  scene.material_names = {"default"};
  scene.lights.push_back(light);
  SphereSet ground;
  // Not larger: a shadow ray starts an error bound off the surface, which grows with the sphere.
  ground.spheres.push_back({{0.0f, 0.0f, -50.0f}, 50.0f, 0});
  scene.top.geometries.emplace_back(std::move(ground));
  return scene;
}

// Adds a large horizontal blocker at height z covering x < edge.
void add_blocker(RenderScene& scene, float z, float edge) {
  TriangleMesh blocker;
  for (const auto& [x, y] : {std::pair{-100.0f, -100.0f}, {edge, -100.0f}, {edge, 100.0f}, {-100.0f, 100.0f}})
    blocker.vertices.push_back({x, y, z});
  blocker.triangles = {{0, 1, 2}, {0, 2, 3}};
  scene.top.geometries.emplace_back(std::move(blocker));
}

float render_probe(const RenderScene& scene, BackendKind kind) {
  const auto backend = make_backend(kind, scene, {});
  const RenderResult result = render_image(scene, *backend, {});
  return result.image.at(0, 0, 0);
}

SphereLight sphere_light(Vec3 center, float radius, int per_axis) {
  return std::get<SphereLight>(make_light(SphereLightDesc{center, radius, Color(1.0f), 1.0f, per_axis}));
}

// Irradiance at a point below the corner of an a × b rectangle at height h that emits radiance 1
// (the point-to-parallel-rectangle form factor, times π).
double corner_rectangle_irradiance(double a, double b, double h) {
  const double x = a / h, y = b / h;
  return 0.5 * (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y)));
}

TEST(AreaLight, SphereLightDeliversItsClosedFormIrradiance) {
  // A sphere light wholly above the horizon: E = π L (r/d)² cos β (Nusselt), exactly.
  const Vec3 center(1.5f, 0.5f, 4.0f);
  const float radius = 0.8f;
  const double d = length(center);
  const double expected = kPi * (radius * radius) / (d * d) * (center.z / d);
  for (BackendKind kind : {BackendKind::kNative, BackendKind::kEmbree}) {
    const float value = render_probe(irradiance_probe(sphere_light(center, radius, 8), 16), kind);
    EXPECT_NEAR(value, expected, 0.005 * expected);
  }
}

TEST(AreaLight, QuadLightDeliversItsClosedFormIrradiance) {
  // A 2 × 2 square at height 1.5, centred above the point and facing down: four corner rectangles.
  const Light quad =
      make_light(QuadLightDesc{{0.0f, 0.0f, 1.5f}, {0.0f, 2.0f, 0.0f}, {2.0f, 0.0f, 0.0f}, Color(1.0f), 1.0f, 8});
  ASSERT_LT(std::get<QuadLight>(quad).normal.z, -0.99f);  // edge1 × edge2 points down
  const double expected = 4.0 * corner_rectangle_irradiance(1.0, 1.0, 1.5);
  for (BackendKind kind : {BackendKind::kNative, BackendKind::kEmbree}) {
    const float value = render_probe(irradiance_probe(quad, 16), kind);
    EXPECT_NEAR(value, expected, 0.005 * expected);
  }
  // Facing up, away from the point (off to the side, so the camera does not see its front).
  const Light away =
      make_light(QuadLightDesc{{3.0f, 0.0f, 1.5f}, {2.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, Color(1.0f), 1.0f, 4});
  EXPECT_EQ(render_probe(irradiance_probe(away, 4), BackendKind::kNative), 0.0f);
}

// The cosine-weighted part of a sphere light that a blocker at height z covering x < edge leaves
// visible from the origin, integrated over the cone on a fine grid (equal solid-angle cells).
double visible_fraction(const Vec3& center, float radius, float z, float edge) {
  const double d = length(center);
  const double cos_max = std::sqrt(1.0 - radius * radius / (d * d));
  const Vec3 w = center / static_cast<float>(d);
  const Vec3 t1 = normalize(cross(std::abs(w.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0), w));
  const Vec3 t2 = cross(w, t1);
  double visible = 0.0, total = 0.0;
  constexpr int kSteps = 1200;
  for (int i = 0; i < kSteps; ++i)
    for (int j = 0; j < kSteps; ++j) {
      const double cos_t = 1.0 - (i + 0.5) / kSteps * (1.0 - cos_max);
      const double sin_t = std::sqrt(1.0 - cos_t * cos_t);
      const double phi = 2.0 * kPi * (j + 0.5) / kSteps;
      const double dx = t1.x * std::cos(phi) * sin_t + t2.x * std::sin(phi) * sin_t + w.x * cos_t;
      const double dz = t1.z * std::cos(phi) * sin_t + t2.z * std::sin(phi) * sin_t + w.z * cos_t;
      total += dz;
      if (dx / dz * z >= edge) visible += dz;  // where the direction crosses the blocker's plane
    }
  return visible / total;
}

TEST(AreaLight, PenumbraMatchesTheVisiblePartOfASphereLight) {
  const Vec3 center(-2.5f, 0.0f, 5.0f);
  const float radius = 1.5f, z = 2.5f;
  const SphereLight light = sphere_light(center, radius, 12);
  for (BackendKind kind : {BackendKind::kNative, BackendKind::kEmbree}) {
    const float open = render_probe(irradiance_probe(light, 16), kind);
    for (float edge : {-1.9f, -1.25f, -0.7f}) {
      RenderScene scene = irradiance_probe(light, 16);
      add_blocker(scene, z, edge);
      const double expected = visible_fraction(center, radius, z, edge);
      SCOPED_TRACE("edge at x = " + std::to_string(edge) + ", expected " + std::to_string(expected));
      ASSERT_GT(expected, 0.05);
      ASSERT_LT(expected, 0.95);
      EXPECT_NEAR(render_probe(scene, kind) / open, expected, 0.01);
    }
  }
}

TEST(AreaLight, CameraAndMirrorsSeeTheEmitterOnlyFromItsFront) {
  const Light sphere = sphere_light({0.0f, 0.0f, 3.0f}, 0.5f, 2);
  Ray towards;
  towards.org = {0.0f, 0.0f, 0.0f};
  towards.dir = {0.0f, 0.0f, 2.0f};  // not unit: t is in units of the direction's length
  EXPECT_FLOAT_EQ(hit_light(sphere, towards, 100.0f), 1.25f);
  EXPECT_EQ(hit_light(sphere, towards, 1.0f), kLightMissed);  // a surface in front hides it
  const Light quad =
      make_light(QuadLightDesc{{0.0f, 0.0f, 3.0f}, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, Color(2.0f), 1.0f, 2});
  EXPECT_FLOAT_EQ(hit_light(quad, towards, 100.0f), 1.5f);  // its normal faces -z, towards the ray
  EXPECT_EQ(light_emission(quad).x, 2.0f);
  Ray from_above = towards;
  from_above.org = {0.0f, 0.0f, 6.0f};
  from_above.dir = {0.0f, 0.0f, -1.0f};
  EXPECT_EQ(hit_light(quad, from_above, 100.0f), kLightMissed);  // its back
  Ray beside = towards;
  beside.org = {0.6f, 0.0f, 0.0f};
  EXPECT_EQ(hit_light(quad, beside, 100.0f), kLightMissed);
  EXPECT_EQ(hit_light(make_light(PointLightDesc{{0, 0, 3}, Color(1.0f), 1.0f}), towards, 100.0f), kLightMissed);
}

TEST(AreaLight, BadAreaLightsAreRefusedAtTheirLocation) {
  const auto error_of = [](const std::string& light) {
    try {
      parse_scene_text(
          "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0]}\nworld: []\nlights:\n  - " + light + "\n",
          "s.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("{type: sphere, center: [0, 1, 0], radius: -1}").find("s.yaml:5:"), std::string::npos);
  EXPECT_NE(error_of("{type: sphere, center: [0, 1, 0], radius: 1, samples: 0}").find("samples"), std::string::npos);
  EXPECT_NE(error_of("{type: sphere, center: [0, 1, 0], radius: 1, samples: 2.5}").find("whole number"),
            std::string::npos);
  EXPECT_NE(error_of("{type: quad, position: [0, 1, 0], edge1: [1, 0, 0], edge2: [2, 0, 0]}").find("parallel"),
            std::string::npos);
  EXPECT_NE(error_of("{type: quad, position: [0, 1, 0], edge1: [1, 0, 0], edge2: [0, 0, .nan]}").find("s.yaml:5:"),
            std::string::npos);
  EXPECT_NE(error_of("{type: sphere, center: [0, 1, 0], radius: 1, intensity: -2}").find("intensity"),
            std::string::npos);
  EXPECT_EQ(error_of("{type: quad, position: [0, 1, 0], edge1: [1, 0, 0], edge2: [0, 0, 1], samples: 3}"), "no error");
}

}  // namespace area_light_test
}  // namespace rtpro
