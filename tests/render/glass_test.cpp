// Glass through the whole render path: energy kept by a clear sphere under a uniform sky,
// absorption over the path inside, refraction rays counted.
#include "rtpro/backend/backend.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace rtpro {
namespace glass_test {

// One sphere of `material` filling the middle of a 32x32 image under a uniform sky, no lights:
// every path ends in the sky, so what a pixel shows is the sky times what the glass let through.
RenderScene sphere_under_sky(const std::string& material) {
  return build_render_scene(
      parse_scene_text("rtpro: 1\ncamera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 30, resolution: [32, 32]}\n"
                       "render: {spp: 4, max_depth: 24, ambient: 0, background: [0.5, 0.5, 0.5]}\n"
                       "materials:\n  glass: " +
                           material +
                           "\n"
                           "world:\n  - {type: sphere, center: [0, 0, 0], radius: 1, material: glass}\n",
                       "glass.yaml"));
}

Color pixel(const RenderResult& result, int x, int y) {
  const std::size_t i = (std::size_t(y) * std::size_t(result.image.width) + std::size_t(x)) * 3;
  return {result.image.data[i], result.image.data[i + 1], result.image.data[i + 2]};
}

RenderResult render_with(BackendKind kind, const RenderScene& scene) {
  const auto backend = make_backend(kind, scene, BackendOptions{});
  return render_image(scene, *backend, RenderOptions{});
}

// Fresnel splits each path's weight into reflected and refracted parts that sum to it, and a
// clear dielectric absorbs nothing: every pixel is the sky, up to the throughput cut-off and the
// depth limit (both tiny here).
TEST(Glass, AClearSphereUnderAUniformSkyNeitherGainsNorLosesEnergy) {
  const RenderScene scene = sphere_under_sky("{ior: 1.5, specular: 0}");
  for (const BackendKind kind : {BackendKind::kNative, BackendKind::kEmbree}) {
    const RenderResult result = render_with(kind, scene);
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        const Color c = pixel(result, x, y);
        ASSERT_NEAR(c.x, 0.5f, 0.5f * 0.01f) << x << "," << y;
      }
    EXPECT_GT(result.rays[RayKind::kRefraction], 0u);
  }
}

// An index-matched medium (ior 1: no bending, no reflection) isolates absorption: through the
// centre the light crosses the sphere along its diameter (2 units, a little less off-centre), so the
// centre pixel is the sky times transmittance^(2 / distance) per channel.
TEST(Glass, AbsorptionFollowsBeerLambertAlongThePathInside) {
  const RenderResult tinted =
      render_with(BackendKind::kNative,
                  sphere_under_sky("{ior: 1, specular: 0, transmittance: [0.5, 0.8, 1.0], transmittance_distance: 1}"));
  const Color c = pixel(tinted, 16, 16);
  EXPECT_NEAR(c.x, 0.5f * 0.25f, 0.5f * 0.25f * 0.01f);  // 0.5^2
  EXPECT_NEAR(c.y, 0.5f * 0.64f, 0.5f * 0.64f * 0.01f);  // 0.8^2
  EXPECT_NEAR(c.z, 0.5f, 1e-6f);
  const RenderResult half =
      render_with(BackendKind::kNative,
                  sphere_under_sky("{ior: 1, specular: 0, transmittance: [0.5, 0.8, 1.0], transmittance_distance: 2}"));
  EXPECT_NEAR(pixel(half, 16, 16).x, 0.5f * 0.5f, 0.5f * 0.5f * 0.01f);  // 0.5^(2/2)
}

TEST(Glass, OpaqueScenesTraceNoRefractionRays) {
  const RenderResult result = render_with(BackendKind::kNative, sphere_under_sky("{color: [0.5, 0.5, 0.5]}"));
  EXPECT_EQ(result.rays[RayKind::kRefraction], 0u);
}

TEST(Glass, BadIndicesAndAbsorptionWithoutGlassAreInputErrors) {
  for (const std::string material :
       {"{ior: 0}", "{ior: -1.5}", "{ior: .NaN}", "{ior: .inf}", "{transmittance: [0.5, 0.5, 0.5]}",
        "{ior: 1.5, transmittance: [2, 1, 1]}", "{ior: 1.5, transmittance_distance: 0}"}) {
    try {
      sphere_under_sky(material);
      ADD_FAILURE() << material << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("glass.yaml:5:"), std::string::npos) << e.what();
    }
  }
}

}  // namespace glass_test
}  // namespace rtpro
