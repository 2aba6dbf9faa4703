// `--shutter OPEN,CLOSE`: the camera's shutter from the command line. A keyframed emissive sphere
// sweeping across the frame blurs with it open, and a closed one renders the frame's instant.
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

namespace rtpro {
namespace shutter_option_test {

using test::render_args;
using test::run_rtpro;

float brightest(const Image& image) { return *std::max_element(image.data.begin(), image.data.end()); }

TEST(ShutterOption, OpenShutterBlursAKeyframedSphereAndKeepsItsEnergy) {
  const auto dir = test::scratch_dir();
  const auto scene =
      test::write_file("sweep.yaml",
                       "rtpro: 1\n"
                       "camera: {position: [0, 0, -8], look_at: [0, 0, 0], fov: 40, resolution: [32, 16]}\n"
                       "render: {integrator: path, spp: 16, max_depth: 1}\n"
                       "materials: {glow: {type: diffuse, color: [0, 0, 0], emission: [1, 1, 1]}}\n"
                       "world:\n  - {type: sphere, radius: 0.5, material: glow,\n"
                       "     center: {keyframes: {0: [-2, 0, 0], 2: [2, 0, 0]}}}\n");
  run_rtpro(render_args(scene, dir / "still.exr", "-q"), 0);
  const Image still = read_image(dir / "still.exr");
  EXPECT_EQ(brightest(still), 1.0f);
  for (const char* backend : {"embree", "native"}) {
    run_rtpro(render_args(scene, dir / "blur.exr", std::string("-q --backend ") + backend + " --shutter -0.5,0.5"), 0);
    const Image blur = read_image(dir / "blur.exr");
    EXPECT_LT(brightest(blur), 0.7f) << backend;  // the sphere sweeps 2 units, 2 diameters
    EXPECT_NEAR(test::image_sum(blur), test::image_sum(still), 0.03 * test::image_sum(still)) << backend;
  }
}

TEST(ShutterOption, InfoSaysWhatMovesAndHowManyTimeStepsItTakes) {
  // A sphere sliding (2 steps hold a straight line) and an instance turning 90° in the shutter (its
  // steps doubled until each chord keeps within 1/1000 of the arc).
  const auto scene =
      test::write_file("moving.yaml",
                       "rtpro: 1\n"
                       "camera: {position: [0, 0, -8], look_at: [0, 0, 0], resolution: [4, 4]}\n"
                       "objects: {ball: [{type: sphere, radius: 0.5}]}\n"
                       "world:\n  - {type: sphere, radius: 0.5, center: {keyframes: {0: [-2, 0, 0], 2: [2, 0, 0]}}}\n"
                       "  - {type: instance, object: ball,\n"
                       "     transform: {rotate: {axis: [0, 1, 0], angle: {keyframes: {0: 0, 2: 180}}}}}\n");
  const auto json = nlohmann::json::parse(run_rtpro("info --json " + scene.string() + " --shutter -0.5,0.5", 0));
  const auto& motion = json.at("motion");
  EXPECT_EQ(motion.at("shutter"), nlohmann::json::array({-0.5, 0.5}));
  EXPECT_EQ(motion.at("moving_spheres"), 1);
  EXPECT_EQ(motion.at("center_steps"), 2);
  EXPECT_EQ(motion.at("moving_instances"), 1);
  EXPECT_GE(motion.at("transform_steps").get<int>(), 17);
  EXPECT_EQ(motion.at("deforming_meshes"), 0);
  EXPECT_FALSE(motion.at("camera_moves").get<bool>());
  const std::string text = run_rtpro("info " + scene.string() + " --shutter -0.5,0.5", 0);
  EXPECT_NE(text.find("motion       shutter [-0.5, 0.5] frames: 1 moving instance ("), std::string::npos) << text;
  EXPECT_NE(text.find("1 moving sphere (2 time steps)"), std::string::npos) << text;
  // Closed, nothing is said of motion: nothing blurs.
  EXPECT_EQ(run_rtpro("info " + scene.string(), 0).find("motion "), std::string::npos);
}

TEST(ShutterOption, MalformedValuesAreRefusedNamingTheFlag) {
  const auto out = test::scratch_dir() / "x.exr";
  const auto scene = test::write_file("plain.yaml",
                                      "rtpro: 1\ncamera: {position: [0, 0, -8], look_at: [0, 0, 0], resolution: [4, "
                                      "4]}\nworld: []\n");
  test::expect_rtpro_answer(render_args(scene, out, "--shutter 0.5"), 2, "--shutter '0.5': expected OPEN,CLOSE");
  test::expect_rtpro_answer(render_args(scene, out, "--shutter 1,0"), 2, "--shutter 1,0");
}

}  // namespace shutter_option_test
}  // namespace rtpro
