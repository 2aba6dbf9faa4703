// `--environment FILE|R,G,B`: one flag that lights a scene from every direction, replacing the
// scene's own environment. A white-furnace-like check makes the expected pixels exact: a diffuse
// sphere of albedo 0.5 in a constant environment of radiance c, sampled by its BSDF alone, reflects
// exactly 0.5·c (a convex sphere sees only the environment), and misses see c.
#include "rtpro/image/image_io.h"
#include "scene/gltf_test_files.h"
#include "test_commands.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace rtpro {
namespace environment_option_test {

using test::render_args;
using test::run_rtpro;

// The sphere fills the centre of a 9×9 image; the scene's own environment (radiance 5) is what
// --environment must replace.
std::filesystem::path sphere_scene() {
  return test::write_file("sphere.yaml",
                          "rtpro: 1\n"
                          "camera: {position: [0, 0, 6], look_at: [0, 0, 0], fov: 30, resolution: [9, 9]}\n"
                          "render: {integrator: path, spp: 4, max_depth: 2, sampling: bsdf}\n"
                          "environment: {color: [5, 5, 5]}\n"
                          "materials: {grey: {type: diffuse, color: [0.5, 0.5, 0.5]}}\n"
                          "world:\n  - {type: sphere, center: [0, 0, 0], radius: 1, material: grey}\n");
}

void expect_pixel(const Image& image, int x, int y, const Color& expected) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(x, y, c), expected[c], 1e-4f * expected[c]) << x << "," << y;
}

TEST(EnvironmentOption, AConstantColourReplacesTheScenesEnvironment) {
  const auto dir = test::scratch_dir();
  const auto scene = sphere_scene();
  for (const char* backend : {"embree", "native"}) {
    run_rtpro(render_args(scene, dir / "c.exr", std::string("-q --backend ") + backend + " --environment 0.2,0.4,0.8"),
              0);
    const Image image = read_image(dir / "c.exr");
    expect_pixel(image, 4, 4, Color(0.1f, 0.2f, 0.4f));
    expect_pixel(image, 0, 0, Color(0.2f, 0.4f, 0.8f));
  }
  // One value is a grey; an override after it changes it as any other.
  run_rtpro(render_args(scene, dir / "g.exr", "-q --environment 0.5 --set environment.intensity=2"), 0);
  expect_pixel(read_image(dir / "g.exr"), 4, 4, Color(0.5f));
}

TEST(EnvironmentOption, AnImageFileLightsTheScene) {
  const auto dir = test::scratch_dir();
  const auto scene = sphere_scene();
  Image sky(8, 4);
  for (int y = 0; y < sky.height; ++y)
    for (int x = 0; x < sky.width; ++x)
      for (int c = 0; c < 3; ++c) sky.at(x, y, c) = 0.5f / float(1 << c);  // exact in RGBE
  write_image(dir / "sky.hdr", sky, {});
  // Relative to where rtpro runs, not to the scene file.
  std::string said;
  ASSERT_EQ(test::run_command("cd " + dir.string() + " && " +
                                  test::rtpro_command(render_args(scene, "f.exr", "-q --environment sky.hdr")),
                              &said),
            0)
      << said;
  expect_pixel(read_image(dir / "f.exr"), 4, 4, Color(0.25f, 0.125f, 0.0625f));
  test::expect_rtpro_answer(render_args(scene, dir / "x.exr", "--environment missing.exr"), 2,
                            "--environment missing.exr: environment.file: image file");
}

TEST(EnvironmentOption, AModelUnderAnEnvironmentGetsNoDefaultLight) {
  test::scratch_dir();
  test::GltfFile gltf;
  gltf.mesh(gltf.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3"));
  gltf.node({{"mesh", 0}});
  gltf.scene({0});
  const auto model = gltf.write("bare");
  const auto bare = nlohmann::json::parse(run_rtpro("info --json " + model.string() + " 2>/dev/null", 0));
  ASSERT_EQ(bare["light_list"].size(), 1u);
  EXPECT_EQ(bare["light_list"][0]["name"], "rtpro default light");
  const auto lit =
      nlohmann::json::parse(run_rtpro("info --json " + model.string() + " --environment 1,1,1 2>/dev/null", 0));
  EXPECT_TRUE(lit["light_list"].empty());
  EXPECT_EQ(lit["notes"].dump().find("adds a directional light"), std::string::npos) << lit["notes"];
}

}  // namespace environment_option_test
}  // namespace rtpro
