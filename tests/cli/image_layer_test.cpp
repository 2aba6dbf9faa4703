// The rtpro executable loads OpenImageIO (through librtpro_image_oiio.so) only to read or write an
// image: see rtpro/image/image_layer.h.
#include "test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace rtpro {
namespace {

using test::rtpro_executable;
using test::run_command;

const char* kTinyScene = R"(rtpro: 1
camera: {position: [0, 1, 5], look_at: [0, 0, 0], fov: 40, resolution: [16, 12]}
render: {spp: 1, max_depth: 2, seed: 1}
lights:
  - {type: point, position: [4, 6, 5], color: [1, 1, 1], intensity: 1}
world:
  - {type: sphere, center: [0, 0, 0], radius: 1}
)";

// The dynamic loader's own report of what it loads: proof, not a timing.
bool loads_openimageio(const std::string& arguments, int expected_exit_code) {
  std::string out;
  const int code = run_command("LD_DEBUG=libs " + rtpro_executable().string() + " " + arguments, &out);
  EXPECT_EQ(code, expected_exit_code) << arguments << "\n" << out.substr(0, 2000);
  return out.find("libOpenImageIO.so") != std::string::npos;
}

TEST(ImageLayer, OnlyReadingOrWritingAnImageLoadsOpenImageIo) {
  const auto scene = test::write_file("scene.yaml", kTinyScene);
  const auto folder = scene.parent_path();
  EXPECT_FALSE(loads_openimageio("--version", 0));
  EXPECT_FALSE(loads_openimageio("--help", 0));
  EXPECT_FALSE(loads_openimageio("info " + scene.string(), 0));
  EXPECT_FALSE(loads_openimageio("render " + scene.string() + " -o " + (folder / "x.unknownformat").string(), 2));
  EXPECT_FALSE(loads_openimageio("render " + scene.string() + " -o " + (folder / "x.png").string() + " --view nope", 2));
  EXPECT_FALSE(loads_openimageio("render " + scene.string() + " --no-such-flag", 2));
  // The control: the same check sees the load when an image is written.
  EXPECT_TRUE(loads_openimageio("render -q " + scene.string() + " -o " + (folder / "x.png").string(), 0));
}

// The render starts loading the image layer in the background before it reads the scene; an error
// in the scene must still be reported in full, and not wait for that load.
TEST(ImageLayer, SceneErrorsDuringABackgroundLoadAreReportedInFull) {
  const auto scene = test::write_file(
      "scene.yaml", std::string(kTinyScene) + "  - {type: mesh, file: missing_mesh.obj}\n");
  std::string out;
  EXPECT_EQ(run_command(rtpro_executable().string() + " render " + scene.string() + " -o " +
                            (scene.parent_path() / "x.png").string(),
                        &out),
            2);
  EXPECT_NE(out.find("missing_mesh.obj"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(scene.parent_path() / "x.png"));
}

TEST(ImageLayer, WithoutThePluginImagesFailWithAClearErrorAndEverythingElseWorks) {
  const auto folder = test::scratch_dir();
  const auto lonely = folder / "rtpro";
  std::filesystem::copy_file(rtpro_executable(), lonely);
  const auto scene = test::write_file("scene.yaml", kTinyScene);
  std::string out;
  EXPECT_EQ(run_command(lonely.string() + " info " + scene.string(), &out), 0) << out;
  EXPECT_EQ(run_command(lonely.string() + " render -q " + scene.string() + " -o " + (folder / "x.png").string(), &out),
            1);
  EXPECT_NE(out.find("librtpro_image_oiio.so"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(folder / "x.png"));
  EXPECT_EQ(run_command(lonely.string() + " compare " + (folder / "a.exr").string() + " " +
                            (folder / "b.exr").string(),
                        &out),
            1);
  EXPECT_NE(out.find("librtpro_image_oiio.so"), std::string::npos) << out;
}

}  // namespace
}  // namespace rtpro
