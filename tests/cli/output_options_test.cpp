// -o - with --format, --exposure, --progress json and the --ocio-display rename, through the
// real binary (issue 14).
#include "rtpro/image/image_io.h"
#include "sphere_on_floor.h"
#include "test_commands.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <sstream>

namespace rtpro {
namespace output_options_test {

using test::expect_rtpro_answer;
using test::render_args;
using test::rtpro_command;
using test::run_command;
using test::run_rtpro;

const std::string kScene = test::sphere_on_floor_scene();

// Standard output to `file`, standard error to the output run_rtpro() returns.
std::string run_to(const std::string& args, const std::filesystem::path& file, int code) {
  std::string out;
  EXPECT_EQ(run_command("{ " + rtpro_command(args) + " > " + file.string() + "; }", &out), code) << args << "\n" << out;
  return out;
}

TEST(OutputOptions, StandardOutputHoldsTheSameImageAsAFile) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto dir = scene.parent_path();
  run_rtpro(render_args(scene, dir / "file.exr", "-q"), 0);
  run_to("render " + scene.string() + " -o - --format exr -q", dir / "piped.exr", 0);
  test::expect_same_pixels(dir / "file.exr", dir / "piped.exr");
  run_to("render " + scene.string() + " -o - --format png -q", dir / "piped.png", 0);
  EXPECT_EQ(test::read_file(dir / "piped.png").substr(1, 3), "PNG");
}

TEST(OutputOptions, FormatMistakesAreRefused) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto dir = scene.parent_path();
  std::string out = run_to("render " + scene.string() + " -o -", dir / "x", 2);
  EXPECT_NE(out.find("needs --format"), std::string::npos) << out;
  expect_rtpro_answer(render_args(scene, dir / "x.exr", "--format png"), 2, "--format png contradicts");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.exr"));
}

TEST(OutputOptions, ExposureScalesTheColourByPowersOfTwo) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto dir = scene.parent_path();
  run_rtpro(render_args(scene, dir / "e0.exr", "-q --aov depth"), 0);
  run_rtpro(render_args(scene, dir / "e2.exr", "-q --aov depth --exposure 2"), 0);
  const Image base = read_image(dir / "e0.exr"), bright = read_image(dir / "e2.exr");
  ASSERT_EQ(base.channels, bright.channels);
  double sum = 0;
  for (std::size_t i = 0; i < base.data.size(); ++i) {
    const std::string& channel = base.channels[i % base.channels.size()];
    const float expected = channel == "R" || channel == "G" || channel == "B" ? base.data[i] * 4.0f : base.data[i];
    ASSERT_EQ(bright.data[i], expected) << channel;
    sum += base.data[i];
  }
  EXPECT_GT(sum, 1.0);
  expect_rtpro_answer(render_args(scene, dir / "x.exr", "--exposure 100"), 2, "--exposure must be");
}

TEST(OutputOptions, JsonProgressIsOneObjectPerLine) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto dir = scene.parent_path();
  const std::string out = run_to(render_args(scene, dir / "p.exr", "--tile-size 8 -q --progress json"), "/dev/null", 0);
  std::istringstream lines(out);
  std::string line;
  int objects = 0;
  nlohmann::json last;
  while (std::getline(lines, line)) {
    last = nlohmann::json::parse(line);  // throws on anything but one object per line
    ++objects;
    EXPECT_LE(last["tiles_done"].get<int>(), last["tiles_total"].get<int>());
    EXPECT_GE(last["elapsed_seconds"].get<double>(), 0.0);
  }
  ASSERT_GE(objects, 1) << out;
  EXPECT_TRUE(last["final"].get<bool>());
  EXPECT_EQ(last["tiles_done"], 6);  // 24x16 in 8x8 tiles
  EXPECT_EQ(last["tiles_total"], 6);
}

TEST(OutputOptions, OldDisplaySpellingWarns) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto dir = scene.parent_path();
  const std::string render = render_args(scene, dir / "d.png");
  std::string out = expect_rtpro_answer(render + " --display sRGB --progress never", 0, "--display is deprecated");
  out = run_rtpro(render + " --ocio-display sRGB --progress never", 0);
  EXPECT_EQ(out.find("deprecated"), std::string::npos) << out;
  expect_rtpro_answer(render + " --ocio-display sRGB --display sRGB", 2, "give only --ocio-display");
}

TEST(OutputOptions, HelpListsFormatsAndTheirEncodings) {
  const std::string out = run_rtpro("render --help", 0);
  for (const char* fragment :
       {".exr", "scene-linear", ".tif", "16-bit", ".png", "8-bit", "--ocio-display", "-D,--define"})
    EXPECT_NE(out.find(fragment), std::string::npos) << fragment << "\n" << out;
}

// The help listed .pfm, which rtpro then refused ("unknown image format"): every extension the
// -o help names is written.
TEST(OutputOptions, EveryFormatTheHelpNamesIsWritten) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const std::string help = run_rtpro("render --help", 0);
  const std::size_t begin = help.find("Output image"), end = help.find("-D,--define");
  ASSERT_NE(begin, std::string::npos) << help;
  const std::string formats = help.substr(begin, end - begin);
  int written = 0;
  for (std::size_t dot = formats.find(" ."); dot != std::string::npos; dot = formats.find(" .", dot + 1)) {
    std::size_t stop = dot + 2;
    while (stop < formats.size() && std::isalnum(static_cast<unsigned char>(formats[stop]))) ++stop;
    const std::string extension = formats.substr(dot + 1, stop - dot - 1);
    if (extension.size() < 2) continue;
    const auto out = scene.parent_path() / ("out" + extension);
    run_rtpro("render " + scene.string() + " -q -o " + out.string(), 0);
    EXPECT_TRUE(std::filesystem::is_regular_file(out)) << extension;
    ++written;
  }
  EXPECT_GE(written, 8);
}

// A killed `-o -` render left its image in $TMPDIR, and a killed textured render its decoded .tx
// copies (1.1 GB for an 8k texture): the next render removes what dead processes left there, and
// keeps what a live one is still using.
TEST(OutputOptions, WhatKilledRendersLeftInTmpdirIsRemovedByTheNextOne) {
  const auto dir = test::scratch_dir();
  const auto tmp = dir / "tmp";
  std::filesystem::create_directories(tmp);
  write_image(dir / "tex.png", test::uniform_image(2, 2, 0.5f), {});
  const auto scene =
      test::write_file("textured.yaml",
                       "rtpro: 1\ncamera: {position: [0, 1, 6], look_at: [0, 0.5, 0], resolution: [24, 16]}\n"
                       "render: {spp: 2}\nlights: [{type: point, position: [4, 6, 5]}]\n"
                       "materials: {t: {color: {texture: tex.png}}}\n"
                       "world: [{type: sphere, center: [0, 0.7, 0], radius: 0.7, material: t}]\n");
  const std::string dead = std::to_string(test::dead_pid()), alive = std::to_string(::getpid());
  std::ofstream(tmp / ("rtpro-stdout-" + dead + "-0.png")) << "a killed render's image";
  std::ofstream(tmp / ("rtpro-stdout-" + alive + "-0.png")) << "a live render's image";
  std::filesystem::create_directories(tmp / ("rtpro-textures-" + dead + "-0"));
  std::ofstream(tmp / ("rtpro-textures-" + dead + "-0") / "0.tx") << "a killed render's texture";
  std::string out;
  ASSERT_EQ(run_command("{ TMPDIR=" + tmp.string() + " " +
                            rtpro_command("render " + scene.string() + " -q -o - --format png") + " > " +
                            (dir / "out.png").string() + "; }",
                        &out),
            0)
      << out;
  EXPECT_GT(read_image(dir / "out.png").width, 0);
  EXPECT_FALSE(std::filesystem::exists(tmp / ("rtpro-stdout-" + dead + "-0.png")));
  EXPECT_FALSE(std::filesystem::exists(tmp / ("rtpro-textures-" + dead + "-0")));
  EXPECT_TRUE(std::filesystem::exists(tmp / ("rtpro-stdout-" + alive + "-0.png")));
  std::vector<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(tmp)) left.push_back(entry.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"rtpro-stdout-" + alive + "-0.png"})
      << "the render left its own files behind";
}

}  // namespace output_options_test
}  // namespace rtpro
