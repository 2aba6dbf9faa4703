// A scene written for the whitted integrator, path traced (`rtpro render scene.yaml --integrator
// path`), and the reverse: a phong mirror shows what it reflects, lights mean the same under both
// integrators (scenes/FORMAT.md, "Light units"), and a phong highlight narrows and brightens as its
// shininess grows. Both backends where an image is rendered.
#include "rtpro/backend/backend.h"
#include "rtpro/core/error.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "bsdf.h"
#include "material_bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace rtpro {
namespace whitted_scene_path_traced_test {

// The scene `text` rendered as `rtpro render` with `--integrator integrator` renders it.
Image render(const std::string& text, const std::string& integrator, BackendKind backend_kind) {
  const RenderScene scene =
      build_render_scene(parse_scene_text(text, "scene.yaml", {"render.integrator=" + integrator}));
  const auto backend = make_backend(backend_kind, scene, {});
  return render_image(scene, *backend, {}).image;
}

// The mean of the centre 2×2 pixels of an image of even size, channel c.
double centre(const Image& image, int c) {
  const int x = image.width / 2 - 1, y = image.height / 2 - 1;
  return (image.at(x, y, c) + image.at(x + 1, y, c) + image.at(x, y + 1, c) + image.at(x + 1, y + 1, c)) / 4.0;
}

class WhittedScenePathTraced : public ::testing::TestWithParam<BackendKind> {};

// A phong sphere of reflectivity 1 filling the view reflects the uniform background: its pixels
// are the background's colour, where a Lambert reading of its colour made it black.
TEST_P(WhittedScenePathTraced, APhongMirrorShowsTheBackground) {
  const std::string scene = R"(
rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 8, resolution: [8, 8]}
render: {spp: 4, max_depth: 3, ambient: 0, background: [0.2, 0.5, 0.8]}
materials:
  mirror: {color: [0.5, 0.5, 0.5], reflectivity: 1}
world:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: mirror}
)";
  for (const char* integrator : {"whitted", "path"}) {
    const Image image = render(scene, integrator, GetParam());
    const double expected[3] = {0.2, 0.5, 0.8};
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre(image, c), expected[c], 1e-4) << integrator << " channel " << c;
  }
}

// A diffuse plane seen from above, lit by one light of `light` (a YAML mapping) and nothing
// else, under `render_extra`'s light units: the centre pixel's value, whitted and path.
struct CentreValues {
  double whitted, path;
};
CentreValues lit_plane_centre(const std::string& light, const std::string& render_extra, BackendKind backend) {
  const std::string scene = R"(
rtpro: 1
camera: {position: [0, 6, 0], look_at: [0, 0, 0], up: [0, 0, 1], fov: 4, resolution: [4, 4]}
render: {spp: 1, max_depth: 1, ambient: 0, background: [0, 0, 0])" +
                            render_extra + R"(}
materials:
  matte: {color: [0.5, 0.5, 0.5], specular: 0}
lights:
  - )" + light + R"(
world:
  - {type: sphere, center: [0, -1000, 0], radius: 1000, material: matte}
)";
  return {centre(render(scene, "whitted", backend), 1), centre(render(scene, "path", backend), 1)};
}

// What a light means does not depend on the integrator that renders it: in a scene written for
// whitted (POV-Ray's units: colour × intensity is what a white surface facing the light shows, at
// any distance) and in a radiometric one (pbrt's: W/sr over d², irradiance), the two agree on the
// irradiance-derived value of a diffuse plane under it, for point, spot and directional lights.
TEST_P(WhittedScenePathTraced, LightsMeanTheSameUnderBothIntegrators) {
  const std::vector<std::string> lights{
      "{type: point, position: [0, 2, 0], intensity: 0.8}",
      "{type: spot, position: [0, 2, 0], direction: [0, -1, 0], intensity: 0.8, outer_angle: 30}",
      "{type: directional, direction: [0, -1, 0], intensity: 0.8}"};
  for (const std::string& light : lights) {
    const CentreValues whitted_units = lit_plane_centre(light, "", GetParam());
    // kd × colour × intensity × cos θ.
    EXPECT_NEAR(whitted_units.whitted, 0.4, 1e-3) << light;
    EXPECT_NEAR(whitted_units.path, whitted_units.whitted, 0.02 * whitted_units.whitted) << light;
    const CentreValues radiometric = lit_plane_centre(light, ", light_units: radiometric", GetParam());
    // kd / π × irradiance: 0.8 / 2² for the point and spot lights, 0.8 for the directional one.
    const double irradiance = light.find("directional") != std::string::npos ? 0.8 : 0.2;
    EXPECT_NEAR(radiometric.path, 0.5 / std::numbers::pi * irradiance, 2e-3 * irradiance) << light;
    EXPECT_NEAR(radiometric.whitted, radiometric.path, 0.02 * radiometric.path) << light;
  }
}

// The units are those of the integrator the file itself names, whatever --integrator (an override
// of render.integrator) renders it with, unless render.light_units says.
TEST(WhittedScenePathTraced, LightUnitsFollowTheIntegratorTheFileNames) {
  const auto units = [](const std::string& extra, const std::vector<std::string>& overrides) {
    const std::string text = "rtpro: 1\ncamera: {position: [0, 0, -4], look_at: [0, 0, 0]}\n" + extra;
    return parse_scene_text(text, "scene.yaml", overrides).render.light_units;
  };
  EXPECT_EQ(units("", {}), LightUnits::kWhitted);
  EXPECT_EQ(units("", {"render.integrator=path"}), LightUnits::kWhitted);
  EXPECT_EQ(units("render: {integrator: path}", {"render.integrator=whitted"}), LightUnits::kRadiometric);
  EXPECT_EQ(units("variables: {i: path}\nrender: {integrator: $i}", {}), LightUnits::kRadiometric);
  EXPECT_EQ(units("render: {light_units: radiometric}", {}), LightUnits::kRadiometric);
  EXPECT_EQ(units("render: {integrator: path, light_units: whitted}", {}), LightUnits::kWhitted);
  EXPECT_THROW(units("render: {light_units: lumens}", {}), InputError);
}

INSTANTIATE_TEST_SUITE_P(Backends, WhittedScenePathTraced,
                         ::testing::Values(BackendKind::kEmbree, BackendKind::kNative),
                         [](const auto& info) { return info.param == BackendKind::kEmbree ? "embree" : "native"; });

// A phong material's BSDF under the path integrator, by shininess, with its highlight alone.
Bsdf highlight_of_shininess(float shininess) {
  const RenderScene scene = build_render_scene(parse_scene_text(R"(
rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0]}
materials:
  shiny: {color: [0, 0, 0], specular: 1, shininess: )" + std::to_string(shininess) +
                                                                    R"(}
)",
                                                                "scene.yaml"));
  SurfacePoint point{};
  point.geometric_normal = point.shading_normal = {0.0f, 0.0f, 1.0f};
  point.front_face = true;
  return material_bsdf(scene.materials[1], point, nullptr).bsdf;
}

// Shininess becomes a roughness: the higher it is, the narrower the angle off the mirror direction
// where the highlight halves, and (a little) the brighter its peak, which the whitted integrator
// keeps at `specular` whatever the shininess.
TEST(WhittedScenePathTraced, AHighlightNarrowsAndBrightensWithShininess) {
  const Vec3 wo = normalize(Vec3(0.5f, 0.0f, 0.866f));
  const float theta_r = std::acos(wo.z);
  const auto toward = [](float theta) { return Vec3(-std::sin(theta), 0.0f, std::cos(theta)); };
  float last_peak = 0.0f, last_width = 10.0f;
  for (float shininess : {2.0f, 10.0f, 50.0f, 250.0f}) {
    const Bsdf bsdf = highlight_of_shininess(shininess);
    const float peak = bsdf_eval(bsdf, wo, toward(theta_r)).x;
    float width = 0.0f;
    while (width < 1.5f && bsdf_eval(bsdf, wo, toward(theta_r + width)).x > 0.5f * peak) width += 1e-4f;
    EXPECT_GT(peak, last_peak) << "shininess " << shininess;
    EXPECT_LT(width, 0.75f * last_width) << "shininess " << shininess;
    last_peak = peak;
    last_width = width;
  }
}

}  // namespace whitted_scene_path_traced_test
}  // namespace rtpro
