// The rtpro executable loads OpenImageIO (through librtpro_image_oiio.so) only to read or write an
// image: see rtpro/image/image_layer.h.
#include "sphere_on_floor.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace rtpro {
namespace image_layer_test {

using test::render_args;
using test::rtpro_executable;
using test::run_command;

const std::string kTinyScene = test::sphere_on_floor_scene();

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
  EXPECT_FALSE(loads_openimageio(render_args(scene, folder / "x.unknownformat"), 2));
  EXPECT_FALSE(loads_openimageio(render_args(scene, folder / "x.tif", "--view nope"), 2));
  EXPECT_FALSE(loads_openimageio("render " + scene.string() + " --no-such-flag", 2));
  // An EXR is written through OpenEXR alone, a PNG through libpng alone.
  EXPECT_FALSE(loads_openimageio("render -q " + scene.string() + " -o " + (folder / "x.exr").string(), 0));
  EXPECT_FALSE(loads_openimageio("render -q " + scene.string() + " -o " + (folder / "x.png").string(), 0));
  // The control: the same check sees the load when an image is written through OpenImageIO.
  EXPECT_TRUE(loads_openimageio("render -q " + scene.string() + " -o " + (folder / "x.tif").string(), 0));
  // An EXR environment is read through OpenEXR alone.
  const auto lit =
      test::write_file("lit.yaml", kTinyScene + "environment: {file: " + (folder / "x.exr").string() + "}\n");
  EXPECT_FALSE(loads_openimageio("render -q " + lit.string() + " -o " + (folder / "lit.exr").string(), 0));
}

// The render starts loading the image layer in the background before it reads the scene; an error
// in the scene must still be reported in full, and not wait for that load.
TEST(ImageLayer, SceneErrorsDuringABackgroundLoadAreReportedInFull) {
  const auto scene = test::write_file("scene.yaml", kTinyScene + "  - {type: mesh, file: missing_mesh.obj}\n");
  test::expect_rtpro_answer(render_args(scene, scene.parent_path() / "x.tif"), 2, "missing_mesh.obj");
  EXPECT_FALSE(std::filesystem::exists(scene.parent_path() / "x.tif"));
}

TEST(ImageLayer, WithoutThePluginImagesFailWithAClearErrorAndEverythingElseWorks) {
  const auto folder = test::scratch_dir();
  const auto lonely = folder / "rtpro";
  std::filesystem::copy_file(rtpro_executable(), lonely);
  const auto scene = test::write_file("scene.yaml", kTinyScene);
  std::string out;
  EXPECT_EQ(run_command(lonely.string() + " info " + scene.string(), &out), 0) << out;
  EXPECT_EQ(run_command(lonely.string() + " render -q " + scene.string() + " -o " + (folder / "x.tif").string(), &out),
            1);
  EXPECT_NE(out.find("librtpro_image_oiio.so"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(folder / "x.tif"));
  for (const char* written_without_it : {"x.exr", "x.png"}) {
    const auto image = folder / written_without_it;
    EXPECT_EQ(run_command(lonely.string() + " render -q " + scene.string() + " -o " + image.string(), &out), 0) << out;
    EXPECT_TRUE(std::filesystem::exists(image));
  }
  // An EXR of R, G, B is read through OpenEXR too: an HDRI environment needs no plugin, and a
  // comparison fails only where it compares.
  const auto lit =
      test::write_file("lit.yaml", kTinyScene + "environment: {file: " + (folder / "x.exr").string() + "}\n");
  EXPECT_EQ(run_command(lonely.string() + " render -q " + lit.string() + " -o " + (folder / "lit.exr").string(), &out),
            0)
      << out;
  EXPECT_TRUE(std::filesystem::exists(folder / "lit.exr"));
  EXPECT_EQ(
      run_command(lonely.string() + " compare " + (folder / "x.exr").string() + " " + (folder / "lit.exr").string(),
                  &out),
      1);
  EXPECT_NE(out.find("librtpro_image_oiio.so"), std::string::npos) << out;
}

// The build lists the plugin's libraries beside it; the loader opens them one by one first (a
// matter of speed only). With the list, without it, or with a list of names that do not load, the
// render writes the same image; the dynamic loader's report shows who opened OpenImageIO.
TEST(ImageLayer, ThePluginsLibraryListChangesOnlyWhoOpensThem) {
  const auto folder = test::scratch_dir();
  const auto plugin = rtpro_executable().parent_path() / "librtpro_image_oiio.so";
  const auto list = plugin.string() + ".libraries";
  ASSERT_TRUE(std::filesystem::exists(list)) << "the build writes " << list;
  std::filesystem::copy_file(rtpro_executable(), folder / "rtpro");
  std::filesystem::copy_file(plugin, folder / "librtpro_image_oiio.so");
  const auto scene = test::write_file("scene.yaml", kTinyScene);
  const auto render = [&](const std::string& image) {
    std::string out;
    const int code = run_command("LD_DEBUG=files " + (folder / "rtpro").string() + " render -q " + scene.string() +
                                     " -o " + (folder / image).string() + " 2>&1",
                                 &out);
    EXPECT_EQ(code, 0) << out.substr(0, 2000);
    const std::size_t line = out.find("file=libOpenImageIO.so");
    EXPECT_NE(line, std::string::npos);
    return out.substr(line, out.find('\n', line) - line);
  };
  // The same pixels (the files differ in their time stamps).
  const auto same_pixels = [&](const std::string& a, const std::string& b) {
    std::string out;
    EXPECT_EQ(
        run_command(rtpro_executable().string() + " compare " + (folder / a).string() + " " + (folder / b).string(),
                    &out),
        0)
        << out;
    return out.find("max error   0 ") != std::string::npos;
  };

  std::filesystem::copy_file(list, folder / "librtpro_image_oiio.so.libraries");
  EXPECT_NE(render("listed.tif").find("dynamically loaded by"), std::string::npos);
  std::filesystem::remove(folder / "librtpro_image_oiio.so.libraries");
  EXPECT_NE(render("unlisted.tif").find("needed by"), std::string::npos);
  std::ofstream(folder / "librtpro_image_oiio.so.libraries") << "libnot-a-library.so.7\n\n/nonexistent/libx.so\n";
  EXPECT_NE(render("bogus.tif").find("needed by"), std::string::npos);

  EXPECT_TRUE(same_pixels("listed.tif", "unlisted.tif"));
  EXPECT_TRUE(same_pixels("listed.tif", "bogus.tif"));
}

}  // namespace image_layer_test
}  // namespace rtpro
