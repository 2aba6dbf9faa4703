// The command line's usage errors and precedence, through the real binary (issue 14): every
// mistake is one line naming the flag, with the nearest valid spelling, and exit code 2.
#include "rtpro/image/image_io.h"
#include "sphere_on_floor.h"
#include "test_commands.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace rtpro {
namespace usage_test {

using test::expect_rtpro_answer;
using test::render_args;
using test::run_rtpro;

const std::string kScene = test::sphere_on_floor_scene();

std::size_t line_count(const std::string& text) {
  std::size_t lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

void expect_one_line_error(const std::string& args, const std::string& fragment) {
  const std::string out = run_rtpro(args, 2);
  EXPECT_NE(out.find(fragment), std::string::npos) << args << "\n" << out;
  EXPECT_EQ(line_count(out), 1u) << args << "\n" << out;
  EXPECT_EQ(out.rfind("rtpro: error: ", 0), 0u) << out;
}

TEST(Usage, UnknownCommandSuggestsTheNearest) {
  expect_one_line_error("rendr scene.yaml", "unknown command 'rendr'; did you mean 'render'?");
  expect_one_line_error("", "a command is required: render, compare, crosscheck, info");
  expect_one_line_error("--hlep", "unknown option '--hlep'; did you mean '--help'?");
}

TEST(Usage, UnknownOptionSuggestsTheNearest) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto out = scene.parent_path() / "out.exr";
  expect_one_line_error(render_args(scene, out, "--sp 4"),
                        "unknown option '--sp' for 'rtpro render'; did you mean '--spp'?");
  expect_one_line_error(render_args(scene, out, "--max-dept=3"), "did you mean '--max-depth'?");
  expect_one_line_error("info " + scene.string() + " --jsn", "did you mean '--json'?");
  expect_one_line_error("render " + scene.string() + " --outfile " + out.string(),
                        "rtpro's is -o/--output (pbrt's --outfile)");
  expect_one_line_error(render_args(scene, out, "--render-anim"), "rtpro's is --frames FIRST-LAST");
  expect_one_line_error(render_args(scene, out, "-qx"), "unknown option '-x'");
  // Mitsuba's -x once suggested -h; docs/usage.md names rtpro's spelling.
  expect_one_line_error(render_args(scene, out, "-x"),
                        "unknown option '-x' for 'rtpro render'; rtpro's is --skip-existing (Mitsuba's -x)");
  expect_one_line_error("info " + scene.string() + " second.yaml third.yaml",
                        "unexpected arguments: 'second.yaml' 'third.yaml'");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(Usage, SingleValueOptionsGivenTwiceAreRefused) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto dir = scene.parent_path();
  expect_one_line_error(render_args(scene, dir / "a.exr") + " -o " + (dir / "b.exr").string(), "-o given twice");
  expect_one_line_error("render " + scene.string() + " -o a.exr --spp=4 --spp 16", "--spp given twice ('4' and '16')");
  EXPECT_FALSE(std::filesystem::exists(dir / "a.exr"));
  EXPECT_FALSE(std::filesystem::exists(dir / "b.exr"));
}

TEST(Usage, ValuesAreCheckedByTheSceneFilesRules) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto out = scene.parent_path() / "out.exr";
  expect_one_line_error(render_args(scene, out, "--seed -1"),
                        "--seed -1: render.seed: expected a non-negative integer");
  expect_one_line_error(render_args(scene, out, "--size 64"), "--size '64': expected WIDTHxHEIGHT");
  expect_one_line_error(render_args(scene, out, "--set render.background=[255,0,0]"), "looks like 8-bit sRGB values");
  expect_one_line_error(render_args(scene, out, "--region 0,0,30,10"),
                        "--region 0,0,30,10: not a non-empty window inside the 24x16 image");
  expect_one_line_error(render_args(scene, out, "--tile-size 0"), "--tile-size must be at least 1");
  expect_one_line_error(render_args(scene, out, "-q --progress sometimes"),
                        "--progress: sometimes not in {never,auto,always,json}");
}

// Keyword values are read in any case, as pbrt and Cycles users type them (`--backend Embree`), and
// reach the render as the keyword itself; misspelt ones are still refused with the list.
TEST(Usage, KeywordValuesAreReadInAnyCase) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto lower = scene.parent_path() / "lower.exr", mixed = scene.parent_path() / "mixed.exr";
  run_rtpro(render_args(scene, lower,
                        "--backend embree --integrator path --aov albedo,depth --progress never --noise-metric relmse "
                        "--embree-quality high"),
            0);
  expect_rtpro_answer(render_args(scene, mixed,
                                  "--backend Embree --integrator PATH --aov Albedo,DEPTH --progress NEVER "
                                  "--noise-metric RelMSE --embree-quality High"),
                      0, "embree)");
  test::expect_same_pixels(lower, mixed);
  const Image image = read_image(mixed);
  EXPECT_NE(std::find(image.channels.begin(), image.channels.end(), "albedo.R"), image.channels.end());
  expect_one_line_error(render_args(scene, mixed, "--backend Embre"), "--backend: Embre not in {native,embree}");
}

TEST(Usage, AovsNeedAnExrOutput) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto png = scene.parent_path() / "out.png";
  expect_one_line_error(render_args(scene, png, "--aov albedo"), "--aov needs an EXR output");
  EXPECT_FALSE(std::filesystem::exists(png));
  // A list option takes one value per occurrence: the scene after it stays the scene.
  const auto exr = scene.parent_path() / "out.exr";
  run_rtpro("render -o " + exr.string() + " --aov albedo --aov depth " + scene.string() + " -q", 0);
  EXPECT_TRUE(std::filesystem::exists(exr));
}

// --set and its shorthands apply in the order typed: the last one to set a key wins.
TEST(Usage, OverridesApplyInCommandLineOrder) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const std::string base = render_args(scene, scene.parent_path() / "o.exr") + " --stats --progress never";
  EXPECT_NE(run_rtpro(base + " --set render.spp=9 --spp 16", 0).find(", 16 spp"), std::string::npos);
  EXPECT_NE(run_rtpro(base + " --spp 16 --set render.spp=9", 0).find(", 9 spp"), std::string::npos);
  EXPECT_NE(run_rtpro(base + " --size 8x8 --set camera.resolution=[10,6]", 0).find("10x6"), std::string::npos);
  EXPECT_NE(run_rtpro(base + " --set camera.resolution=[10,6] --size 8x8", 0).find("8x8"), std::string::npos);
}

TEST(Usage, AnySampleCountRenders) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto out = scene.parent_path() / "six.exr";
  expect_rtpro_answer(render_args(scene, out, "--spp 6"), 0, "6 spp");
  EXPECT_GT(test::image_sum(read_image(out)), 1.0);
}

TEST(Usage, SceneFromStandardInput) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto dir = scene.parent_path();
  run_rtpro(render_args(scene, dir / "file.exr", "-q"), 0);
  run_rtpro("render - -o " + (dir / "stdin.exr").string() + " -q < " + scene.string(), 0);
  test::expect_same_pixels(dir / "file.exr", dir / "stdin.exr");
  expect_rtpro_answer("info - < /dev/null", 2, "<stdin>");
}

}  // namespace usage_test
}  // namespace rtpro
