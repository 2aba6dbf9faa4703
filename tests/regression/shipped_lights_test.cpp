// Every light of every shipped scene lights something. A light that faces away from the scene
// (area_lights.yaml's rectangle once emitted upward, away from everything) leaves its scene's
// reference as wrong as the render, so the golden-image comparison cannot notice: each light is
// rendered here alone, with the ambient term, the background, the environment and emissive
// surfaces taken away, and its picture must not be black.
#include "fetched_meshes.h"
#include "regression_paths.h"
#include "scene_textures.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include "rtpro/backend/backend.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace rtpro {
namespace shipped_lights_test {

constexpr int kWidth = 64;  // the height keeps the scene's aspect
constexpr int kSpp = 4;

// The scene as the regression suite renders it, small, with nothing lit but by its lights.
RenderScene unlit_scene(const std::filesystem::path& file) {
  const SceneDescription full = parse_scene_file(file);
  const long height = std::max(1L, std::lround(double(kWidth) * full.camera.height / full.camera.width));
  RenderScene scene = build_render_scene(
      parse_scene_file(file, {"render.spp=" + std::to_string(kSpp),
                              "camera.resolution=[" + std::to_string(kWidth) + "," + std::to_string(height) + "]"}));
  scene.render.ambient = 0.0f;
  scene.render.background = Color(0.0f);
  scene.environment.reset();
  for (Material& material : scene.materials) material.emission = Emission{};
  return scene;
}

TEST(ShippedLights, EveryLightOfEveryShippedSceneReachesTheImage) {
  int lights_checked = 0;
  for (const std::filesystem::path& file : regression::scene_files()) {
    if (test::uses_fetched_assets(file) && !test::fetched_assets_present()) continue;
    const RenderScene unlit = unlit_scene(file);
    const std::unique_ptr<TextureLookup> textures = regression::open_scene_textures(unlit);
    for (std::size_t i = 0; i < unlit.lights.size(); ++i) {
      SCOPED_TRACE(regression::source_relative(file) + ", light " + std::to_string(i));
      RenderScene alone = unlit;
      alone.lights = {unlit.lights[i]};
      const auto backend = make_backend(BackendKind::kNative, alone, BackendOptions{});
      RenderOptions options;
      options.textures = textures.get();
      const Image image = render_image(alone, *backend, options).image;
      EXPECT_GT(test::image_sum(image), 0.0) << "this light reaches nothing the camera sees";
      ++lights_checked;
    }
  }
  EXPECT_GE(lights_checked, 10);
}

}  // namespace shipped_lights_test
}  // namespace rtpro
