// The path integrator against scenes with analytic answers (pbrt-v4's closed sphere, the white
// furnace), its three estimators against each other, and its determinism, with both backends.
#include "path_integrator.h"

#include "rtpro/backend/backend.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "test_fixtures.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace rtpro {
namespace path_integrator_test {

RenderScene scene_from(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  return build_render_scene(parse_scene_text(yaml, "test.yaml", overrides));
}

Image render(const RenderScene& scene, BackendKind kind) {
  const auto backend = make_backend(kind, scene, {});
  return render_image(scene, *backend, {}).image;
}

struct ImageStats {
  double mean = 0.0, min = 1e30, max = -1e30;
};

// Of every pixel's channels 0..2.
ImageStats stats_of(const Image& image, int x0 = 0, int y0 = 0, int x1 = -1, int y1 = -1) {
  if (x1 < 0) x1 = image.width;
  if (y1 < 0) y1 = image.height;
  ImageStats s;
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) {
        const double v = image.at(x, y, c);
        sum += v;
        s.min = std::min(s.min, v);
        s.max = std::max(s.max, v);
      }
  s.mean = sum / (3.0 * (x1 - x0) * (y1 - y0));
  return s;
}

class PathIntegrator : public ::testing::TestWithParam<BackendKind> {};

// pbrt-v4's closed sphere: the camera inside a Lambertian sphere of radius 1 and reflectance 0.5.
// Whatever lights it (a point light of intensity π at the centre, four of π/4, or the sphere
// itself emitting 0.5), the radiance everywhere inside is Le/(1 − ρ)-like: exactly 1.
const std::string kClosedSphere = R"(
rtpro: 1
camera: {position: [0, 0, 0], look_at: [0, 0, 1], fov: 90, resolution: [16, 16]}
render: {spp: 64, max_depth: 64, integrator: path}
materials:
  wall: {type: diffuse, color: [0.5, 0.5, 0.5]}
  glowing_wall: {type: diffuse, color: [0.5, 0.5, 0.5], emission: [0.5, 0.5, 0.5], emission_sides: both}
)";

TEST_P(PathIntegrator, ClosedSphereLitByAPointLightIsOneEverywhere) {
  const RenderScene scene = scene_from(kClosedSphere + R"(
lights: [{type: point, position: [0, 0, 0], intensity: 3.14159265}]
world: [{type: sphere, center: [0, 0, 0], radius: 1, material: wall}]
)");
  const ImageStats s = stats_of(render(scene, GetParam()));
  EXPECT_NEAR(s.mean, 1.0, 0.01);
}

TEST_P(PathIntegrator, ClosedSphereLitByFourPointLightsIsOneEverywhere) {
  const RenderScene scene = scene_from(kClosedSphere + R"(
lights:
  - {type: point, position: [0, 0, 0], intensity: 0.785398163}
  - {type: point, position: [0, 0, 0], intensity: 0.785398163}
  - {type: point, position: [0, 0, 0], intensity: 0.785398163}
  - {type: point, position: [0, 0, 0], intensity: 0.785398163}
world: [{type: sphere, center: [0, 0, 0], radius: 1, material: wall}]
)");
  const ImageStats s = stats_of(render(scene, GetParam()));
  EXPECT_NEAR(s.mean, 1.0, 0.01);
}

TEST_P(PathIntegrator, ClosedSphereThatEmitsIsOneEverywhere) {
  const RenderScene scene = scene_from(kClosedSphere + R"(
world: [{type: sphere, center: [0, 0, 0], radius: 1, material: glowing_wall}]
)");
  const ImageStats s = stats_of(render(scene, GetParam()));
  EXPECT_NEAR(s.mean, 1.0, 0.01);
}

// The white furnace: an object inside a sphere that emits radiance 1 inwards and reflects
// nothing. An object that loses no energy vanishes: every pixel is 1.
std::string furnace(const std::string& object_material) {
  return R"(
rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 40, resolution: [24, 24]}
render: {spp: 64, max_depth: 64, integrator: path}
materials:
  sky: {type: diffuse, color: [0, 0, 0], emission: [1, 1, 1], emission_sides: both}
  object: )" +
         object_material + R"(
world:
  - {type: sphere, center: [0, 0, 0], radius: 20, material: sky}
  - {type: sphere, center: [0, 0, 0], radius: 1, material: object}
)";
}

TEST_P(PathIntegrator, FurnaceHidesAWhiteLambertianSphere) {
  const ImageStats s = stats_of(render(scene_from(furnace("{type: diffuse, color: [1, 1, 1]}")), GetParam()));
  EXPECT_NEAR(s.mean, 1.0, 0.003);
  EXPECT_GT(s.min, 0.9);  // no pixel far off: the estimator is nearly noise-free here
}

TEST_P(PathIntegrator, FurnaceHidesTheSameSphereWithEachEstimatorAlone) {
  for (const char* sampling : {"light", "bsdf"}) {
    const RenderScene scene =
        scene_from(furnace("{type: diffuse, color: [1, 1, 1]}"), {std::string("render.sampling=") + sampling});
    EXPECT_NEAR(stats_of(render(scene, GetParam())).mean, 1.0, 0.006) << sampling;
  }
}

// The same furnace with its emitter an instance: an emissive sphere scaled up from radius 1 and
// moved, and a closed emissive box of triangles scaled and mirrored. Instanced emitters are
// light-sampled in world space (the MIS weights would not sum to 1 otherwise), so the white
// sphere still vanishes.
TEST_P(PathIntegrator, FurnaceHidesAWhiteSphereInsideInstancedEmitters) {
  const std::string common = R"(
rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 40, resolution: [24, 24]}
render: {spp: 64, max_depth: 64, integrator: path}
materials:
  sky: {type: diffuse, color: [0, 0, 0], emission: [1, 1, 1], emission_sides: both}
  white: {type: diffuse, color: [1, 1, 1]}
objects:
  sky_sphere: [{type: sphere, center: [0, 0, 0], radius: 1, material: sky}]
  sky_box: [{type: mesh, file: )" +
                             std::string(RTPRO_SOURCE_DIR) + R"(/scenes/meshes/box.obj, material: sky}]
world:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: white}
)";
  for (const std::string& enclosure :
       {std::string("  - {type: instance, object: sky_sphere, transform: [{scale: 20}, {translate: [1, 0, 0]}]}\n"),
        std::string("  - {type: instance, object: sky_box, transform: [{scale: [-30, 30, 30]}, {translate: [0, -15, "
                    "0]}]}\n")}) {
    const RenderScene scene = scene_from(common + enclosure);
    const LightSet lights(scene);
    EXPECT_FALSE(lights.empty()) << enclosure;
    EXPECT_NEAR(stats_of(render(scene, GetParam())).mean, 1.0, 0.003) << enclosure;
  }
}

TEST_P(PathIntegrator, FurnaceHidesASmoothGlassSphere) {
  const ImageStats s = stats_of(render(scene_from(furnace("{type: dielectric, ior: 1.5}")), GetParam()));
  EXPECT_NEAR(s.mean, 1.0, 0.01);
}

// Rough glass, energy-compensated, vanishes too: without compensation the light scattered between
// microfacets is lost at every interface a path crosses (0.62 at roughness 0.7).
TEST_P(PathIntegrator, FurnaceHidesRoughGlassAtEveryRoughness) {
  for (const char* roughness : {"0.1", "0.3", "0.7", "1"})
    for (const char* kind : {"dielectric", "principled"}) {
      const std::string material =
          std::string("{type: ") + kind + ", ior: 1.5, roughness: " + roughness +
          (std::string(kind) == "principled" ? ", color: [1, 1, 1], transmission_weight: 1}" : "}");
      const ImageStats s = stats_of(render(scene_from(furnace(material)), GetParam()));
      std::cout << "rough glass in the furnace, " << material << ": mean " << s.mean << ", max " << s.max << "\n";
      EXPECT_NEAR(s.mean, 1.0, 0.01) << material;
    }
}

// Under a uniform background (no light to sample) every path through the glass sphere brings
// back exactly 1, its refractions' 1/η² and η² cancelling, unless Russian roulette reweights it:
// roulette must read the throughput without refraction's radiance scale, and leave paths whose
// throughput is still 1 alone. On the radiance inside (1/2.25), with a 5% floor, pixels reached
// 1.32 here.
TEST_P(PathIntegrator, RussianRouletteLeavesFurnacePathsThroughGlassAtOne) {
  for (const char* material :
       {"{type: dielectric, ior: 1.5, roughness: 0.3}",
        "{type: principled, color: [1, 1, 1], transmission_weight: 1, ior: 1.5, roughness: 0.7}"}) {
    const RenderScene scene = scene_from(test::white_furnace_scene(material, 12, 32));
    const ImageStats s = stats_of(render(scene, GetParam()));
    EXPECT_NEAR(s.mean, 1.0, 0.005) << material;
    EXPECT_LT(s.max, 1.001) << material;
  }
}

TEST_P(PathIntegrator, FurnaceHidesAPerfectRoughConductorWithEnergyCompensation) {
  for (const char* roughness : {"0.2236", "0.5", "0.7071", "1"}) {  // alpha 0.05, 0.25, 0.5, 1
    const RenderScene scene =
        scene_from(furnace(std::string("{type: conductor, color: [1, 1, 1], roughness: ") + roughness + "}"));
    const ImageStats s = stats_of(render(scene, GetParam()));
    EXPECT_NEAR(s.mean, 1.0, 0.02) << "roughness " << roughness;
  }
}

// The glTF model keeps energy the way its layers are scaled (albedo scaling under the specular
// layer, the coat and the fuzz; Kulla–Conty in the metal): a white sphere of it vanishes in the
// furnace, whatever its roughness, metalness, coat or transmission.
TEST_P(PathIntegrator, FurnaceHidesWhitePrincipledSpheres) {
  for (const char* material :
       {"{type: principled, color: [1, 1, 1], roughness: 0.5}", "{type: principled, color: [1, 1, 1], roughness: 0}",
        "{type: principled, color: [1, 1, 1], metalness: 1, roughness: 0.6}",
        "{type: principled, color: [1, 1, 1], roughness: 0.4, coat_weight: 1, coat_roughness: 0.1}",
        "{type: principled, color: [1, 1, 1], transmission_weight: 1, roughness: 0}"}) {
    const ImageStats s = stats_of(render(scene_from(furnace(material)), GetParam()));
    EXPECT_NEAR(s.mean, 1.0, 0.02) << material;
  }
}

// Small and large lights of every kind over rough and smooth surfaces: light sampling alone,
// BSDF sampling alone and MIS estimate the same image. Each region's mean over independent seeds
// must agree within 3 standard errors.
TEST_P(PathIntegrator, LightSamplingBsdfSamplingAndMisAgree) {
  const std::string yaml = R"(
rtpro: 1
camera: {position: [0, 2.5, -6], look_at: [0, 0.6, 0], fov: 45, resolution: [24, 16]}
render: {spp: 16, max_depth: 3, integrator: path}
materials:
  floor: {type: diffuse, color: [0.7, 0.7, 0.7]}
  rough: {type: conductor, color: [0.9, 0.6, 0.3], roughness: 0.6}
  glossy: {type: conductor, color: [0.8, 0.8, 0.8], roughness: 0.25}
  lamp: {type: diffuse, color: [0, 0, 0], emission: [4, 4, 3]}
lights:
  - {type: quad, position: [0, 4, 0], edge1: [2, 0, 0], edge2: [0, 0, 2], intensity: 3}
  - {type: sphere, center: [-2, 1.5, -1], radius: 0.15, intensity: 40}
world:
  - {type: sphere, center: [0, -1000, 0], radius: 1000, material: floor}
  - {type: sphere, center: [-0.9, 0.7, 0], radius: 0.7, material: rough}
  - {type: sphere, center: [0.9, 0.7, 0], radius: 0.7, material: glossy}
  - {type: sphere, center: [1.8, 2.2, 1], radius: 0.3, material: lamp}
)";
  constexpr int kSeeds = 8;
  constexpr int kRegions = 4;                                       // quadrants
  std::map<std::string, std::vector<std::vector<double>>> regions;  // estimator → region → per seed
  for (const char* sampling : {"mis", "light", "bsdf"}) {
    auto& per_region = regions[sampling];
    per_region.assign(kRegions, {});
    for (int seed = 1; seed <= kSeeds; ++seed) {
      const RenderScene scene =
          scene_from(yaml, {std::string("render.sampling=") + sampling, "render.seed=" + std::to_string(seed)});
      const Image image = render(scene, GetParam());
      for (int r = 0; r < kRegions; ++r) {
        const int x0 = (r % 2) * image.width / 2, y0 = (r / 2) * image.height / 2;
        per_region[r].push_back(stats_of(image, x0, y0, x0 + image.width / 2, y0 + image.height / 2).mean);
      }
    }
  }
  const auto mean_and_error = [](const std::vector<double>& v) {
    double m = 0.0, s2 = 0.0;
    for (const double x : v) m += x;
    m /= static_cast<double>(v.size());
    for (const double x : v) s2 += (x - m) * (x - m);
    return std::pair{m, std::sqrt(s2 / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()))};
  };
  for (int r = 0; r < kRegions; ++r) {
    const auto [mis, mis_error] = mean_and_error(regions["mis"][r]);
    EXPECT_GT(mis, 0.01) << "region " << r << " should be lit";
    for (const char* other : {"light", "bsdf"}) {
      const auto [m, error] = mean_and_error(regions[other][r]);
      EXPECT_NEAR(m, mis, 3.0 * std::hypot(error, mis_error) + 1e-4) << other << " sampling, region " << r;
    }
  }
  // MIS is the least noisy of the three on this mix of lights and surfaces.
  double mis_noise = 0.0, bsdf_noise = 0.0;
  for (int r = 0; r < kRegions; ++r) {
    mis_noise += mean_and_error(regions["mis"][r]).second;
    bsdf_noise += mean_and_error(regions["bsdf"][r]).second;
  }
  EXPECT_LT(mis_noise, bsdf_noise);
}

TEST_P(PathIntegrator, ImageIsIndependentOfThreadsAndTiles) {
  const RenderScene scene = scene_from(furnace("{type: conductor, color: [0.9, 0.5, 0.2], roughness: 0.4}"),
                                       {"render.spp=4", "render.max_depth=5"});
  const auto backend = make_backend(GetParam(), scene, {});
  const auto render_with = [&](int threads, int tile_size) {
    tbb::global_control cap(tbb::global_control::max_allowed_parallelism, threads);
    RenderOptions options;
    options.tile_size = tile_size;
    return render_image(scene, *backend, options).image;
  };
  const Image a = render_with(1, 32), b = render_with(2, 5);
  ASSERT_EQ(a.data.size(), b.data.size());
  EXPECT_EQ(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)), 0);
}

// The albedo and normal AOVs come from the first surface that is not a mirror: through a smooth
// glass sphere, from what lies behind it; on a principled surface its base colour (not the
// Whitted view's diffuse colour, which a glossy highlight darkens).
TEST_P(PathIntegrator, AlbedoAovIsTheFirstNonSpecularSurfacesBaseColour) {
  const RenderScene scene = scene_from(R"(
rtpro: 1
camera: {position: [0, 0, -5], look_at: [0, 0, 0], fov: 10, resolution: [4, 4]}
render: {spp: 4, max_depth: 4, integrator: path, background: [1, 1, 1]}
materials:
  glass: {type: dielectric, ior: 1.0001}
  paint: {type: principled, color: [0.2, 0.4, 0.6], roughness: 0}
world:
  - {type: sphere, center: [0, 0, 0], radius: 3, material: glass}
  - {type: sphere, center: [0, 0, 50], radius: 30, material: paint}
)");
  const auto backend = make_backend(GetParam(), scene, {});
  RenderOptions options;
  options.aovs = {Aov::kAlbedo};
  const Image image = render_image(scene, *backend, options).image;
  ASSERT_EQ(image.channel_count(), 6);
  EXPECT_NEAR(image.at(2, 2, 3), 0.2f, 1e-6f);
  EXPECT_NEAR(image.at(2, 2, 4), 0.4f, 1e-6f);
  EXPECT_NEAR(image.at(2, 2, 5), 0.6f, 1e-6f);
}

INSTANTIATE_TEST_SUITE_P(Backends, PathIntegrator, ::testing::Values(BackendKind::kNative, BackendKind::kEmbree),
                         [](const auto& info) { return std::string(backend_name(info.param)); });

TEST(PathIntegratorBackends, SphereScenesAreBitIdenticalAcrossBackends) {
  const RenderScene scene =
      scene_from(furnace("{type: dielectric, ior: 1.5, roughness: 0.3}"), {"render.spp=4", "render.max_depth=8"});
  const Image native = render(scene, BackendKind::kNative), embree = render(scene, BackendKind::kEmbree);
  ASSERT_EQ(native.data.size(), embree.data.size());
  EXPECT_EQ(std::memcmp(native.data.data(), embree.data.data(), native.data.size() * sizeof(float)), 0);
}

}  // namespace path_integrator_test
}  // namespace rtpro
