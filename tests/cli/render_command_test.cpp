// End-to-end tests of `rtpro render` and `rtpro info`, running the real binary.
#include "exr_attribute.h"
#include "rtpro/image/image_io.h"
#include "test_fixtures.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <fstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace rtpro {
namespace render_command_test {

using test::expect_rtpro_answer;
using test::render_args;
using test::rtpro_command;
using test::rtpro_executable;
using test::run_command;
using test::run_rtpro;

const char* kSmallScene = R"(rtpro: 1
camera: {position: [0, 1.5, 6], look_at: [0, 0.5, 0], fov: 40, resolution: [64, 48]}
render: {spp: 4, max_depth: 3, seed: 3}
materials:
  red: {color: [0.9, 0.2, 0.2], reflectivity: 0.3}
  mirror: {color: [0.2, 0.2, 0.2], reflectivity: 0.8}
lights:
  - {type: point, position: [4, 6, 5], color: [1, 1, 1], intensity: 1}
  - {type: directional, direction: [-1, -2, -1], intensity: 0.3}
objects:
  pair:
    - {type: sphere, center: [0, 0, 0], radius: 0.3, material: red}
    - {type: sphere, center: [0.7, 0, 0], radius: 0.2, material: mirror}
world:
  - {type: sphere, center: [0, -1000, 0], radius: 1000}
  - {type: sphere, center: [-1, 0.7, 0], radius: 0.7, material: red}
  - {type: sphere, center: [1, 0.6, 0], radius: 0.6, material: mirror}
  - {type: instance, object: pair, transform: {translate: [0, 0.3, 1.5]}}
  - {type: instance, object: pair, transform: {translate: [-1, 0.3, 2], rotate: {axis: [0, 1, 0], angle: 90}}}
)";

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

// Renders kSmallScene quietly with `options` and again with `other_options`, expects the same
// pixels, bit for bit, and returns the first image's file.
std::filesystem::path expect_same_image(const std::string& options, const std::string& other_options) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  const auto first = scene.parent_path() / "first.exr", second = scene.parent_path() / "second.exr";
  run_rtpro(render_args(scene, first, "-q " + options), 0);
  run_rtpro(render_args(scene, second, "-q " + other_options), 0);
  test::expect_same_pixels(first, second);
  return first;
}

TEST(RenderCommand, SameImageAtOneAndTwoThreads) {
  const auto image = expect_same_image("--threads 1", "--threads 2");
  EXPECT_GT(test::image_sum(read_image(image)), 10.0);
}

TEST(RenderCommand, SameImageWithATileLargerThanTheImage) { expect_same_image("", "--tile-size 2147483647"); }

TEST(RenderCommand, StatsJsonParsesAndCountsAddUp) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  const auto dir = scene.parent_path();
  const std::string out = run_rtpro(
      render_args(scene, dir / "s.exr", "--stats --stats-json " + (dir / "stats.json").string() + " --progress never"),
      0);
  EXPECT_NE(out.find("Mrays/s"), std::string::npos) << out;
  const nlohmann::json stats = read_json(dir / "stats.json");
  const auto& rays = stats["rays"];
  EXPECT_EQ(rays["camera"].get<std::uint64_t>(), 64u * 48u * 4u);
  EXPECT_EQ(rays["total"].get<std::uint64_t>(), rays["camera"].get<std::uint64_t>() +
                                                    rays["shadow"].get<std::uint64_t>() +
                                                    rays["reflection"].get<std::uint64_t>());
  EXPECT_GT(rays["shadow"].get<std::uint64_t>(), 0u);
  EXPECT_GT(rays["reflection"].get<std::uint64_t>(), 0u);
  EXPECT_EQ(stats["spp"].get<int>(), 4);
  EXPECT_TRUE(stats["complete"].get<bool>());
  EXPECT_GT(stats["memory_bytes"]["peak_rss"].get<std::uint64_t>(), 0u);
  EXPECT_GE(stats["seconds"]["total"].get<double>(), stats["seconds"]["render"].get<double>());
}

TEST(RenderCommand, RegionAndCropMatchTheFullRender) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  const auto dir = scene.parent_path();
  run_rtpro(render_args(scene, dir / "full.exr", "-q"), 0);
  run_rtpro(render_args(scene, dir / "region.exr", "-q --region 10,5,40,30"), 0);
  run_rtpro(render_args(scene, dir / "crop.exr", "-q --region 10,5,40,30 --crop"), 0);
  const Image full = read_image(dir / "full.exr"), region = read_image(dir / "region.exr"),
              crop = read_image(dir / "crop.exr");
  ASSERT_EQ(region.width, 64);
  ASSERT_EQ(crop.width, 30);
  ASSERT_EQ(crop.height, 25);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c) {
        const bool inside = x >= 10 && x < 40 && y >= 5 && y < 30;
        ASSERT_EQ(region.at(x, y, c), inside ? full.at(x, y, c) : 0.0f);
        if (inside) {
          ASSERT_EQ(crop.at(x - 10, y - 5, c), full.at(x, y, c));
        }
      }
  run_rtpro(render_args(scene, dir / "bad.exr", "-q --region 10,5,400,30"), 2);
  run_rtpro(render_args(scene, dir / "bad.exr", "-q --region 1,2,3"), 2);
}

// A cropped image is reported at its own size, with the window it shows and the image it is cut
// from: in the last line, the statistics and the metadata.
TEST(RenderCommand, ACropIsReportedAtItsOwnSizeWithItsWindow) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  const auto dir = scene.parent_path();
  const auto crop = dir / "crop.exr", stats_file = dir / "crop.json";
  expect_rtpro_answer(
      render_args(scene, crop, "--progress never --region 10,5,40,30 --crop --stats-json " + stats_file.string()), 0,
      "(30x25, the crop 10,5,40,30 of 64x48, 4 spp, ");
  std::ifstream in(stats_file);
  const nlohmann::json stats = nlohmann::json::parse(in);
  EXPECT_EQ(stats["resolution"], nlohmann::json::array({30, 25}));
  EXPECT_EQ(stats["full_resolution"], nlohmann::json::array({64, 48}));
  EXPECT_EQ(stats["region"], nlohmann::json::array({10, 5, 40, 30}));
  EXPECT_TRUE(stats["crop"].get<bool>());
  EXPECT_EQ(test::exr_string_attribute(crop, "rtpro:region"), "10,5,40,30");
  EXPECT_EQ(test::exr_string_attribute(crop, "rtpro:full_resolution"), "64x48");
  // Without --crop the image is the whole frame, the region named beside it.
  expect_rtpro_answer(render_args(scene, dir / "region.exr", "--progress never --region 10,5,40,30"), 0,
                      "(64x48, region 10,5,40,30, 4 spp, ");
}

TEST(RenderCommand, AovLayersAreWrittenWithCompositorNames) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  const auto file = scene.parent_path() / "aov.exr";
  run_rtpro(render_args(scene, file, "-q --aov albedo,normal,depth,object-id"), 0);
  const Image image = read_image(file);
  for (const char* name :
       {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "depth.Z", "object_id.id"})
    EXPECT_NE(std::find(image.channels.begin(), image.channels.end(), name), image.channels.end()) << name;
  run_rtpro(render_args(scene, file, "-q --aov bogus"), 2);
  // A layer asked for twice is refused before the render, not when the image is written.
  const auto twice = scene.parent_path() / "twice.exr";
  expect_rtpro_answer(render_args(scene, twice, "-q --aov depth,albedo,depth"), 2, "--aov depth");
  EXPECT_FALSE(std::filesystem::exists(twice));
}

TEST(RenderCommand, BadInputsFailCleanlyAndLeaveNoFile) {
  const auto dir = test::scratch_dir();
  const auto bad_scene = test::write_file("bad.yaml",
                                          "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0]}\n"
                                          "world:\n  - {type: sphere, center: [0, 0, 0], radius: -1}\n");
  const auto target = bad_scene.parent_path() / "never.png";
  expect_rtpro_answer(render_args(bad_scene, target), 2, "bad.yaml:4:");
  EXPECT_FALSE(std::filesystem::exists(target));
  expect_rtpro_answer(render_args(dir / "missing.yaml", target), 2, "missing.yaml");
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  run_rtpro(render_args(scene, dir / "x.unknownformat"), 2);
  run_rtpro(render_args(scene, "/nonexistent-folder/x.png"), 1);
  expect_rtpro_answer(render_args(scene, target, "--spp 0"), 2, "--spp 0: render.spp must be from 1 to 65536");
  run_rtpro(render_args(scene, target, "--no-such-flag"), 2);
  EXPECT_FALSE(std::filesystem::exists(target));
}

TEST(RenderCommand, InterruptWritesPartialImageAndKeepsExistingOutput) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  const auto dir = scene.parent_path();
  const auto output = dir / "out.exr";
  std::ofstream(output) << "a previous good image";
  int progress[2];
  ASSERT_EQ(pipe(progress), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    dup2(progress[1], STDERR_FILENO);
    close(progress[0]);
    const std::string exe = rtpro_executable().string();
    // Large enough to run for many seconds on two cores.
    execl(exe.c_str(), exe.c_str(), "render", scene.c_str(), "-o", output.c_str(), "--size", "1600x1200", "--spp",
          "256", "--threads", "2", "--tile-size", "16", "--progress", "always", "--set",
          "render.background=[0.2,0.3,0.5]", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(progress[1]);
  // Interrupt once the render runs (its first progress report), not after a guessed start-up time:
  // a sanitizer build takes longer than 1.5 s to start, and a SIGINT before rtpro installs its
  // handler ends the process the default way.
  std::string seen;
  char buffer[256];
  for (ssize_t got; seen.find('%') == std::string::npos && (got = read(progress[0], buffer, sizeof buffer)) > 0;)
    seen.append(buffer, static_cast<std::size_t>(got));
  ASSERT_NE(seen.find('%'), std::string::npos) << seen;
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const auto sent = std::chrono::steady_clock::now();
  kill(pid, SIGINT);
  int status = 0;
  std::thread drain([&] {  // keep the pipe from filling while rtpro finishes
    while (read(progress[0], buffer, sizeof buffer) > 0) {
    }
  });
  waitpid(pid, &status, 0);
  drain.join();
  close(progress[0]);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_LT(seconds, 5.0);  // generous for a loaded CI machine; the tiles in flight take well under a second
  EXPECT_EQ(test::read_file(output), "a previous good image");
  const Image partial = read_image(dir / "out.partial.exr");
  EXPECT_EQ(partial.width, 1600);
  // Finished tiles hold the picture (every pixel at least the sky colour); unfinished ones are 0.
  EXPECT_GT(test::image_sum(partial), 0.0);
  float last_row = 0;
  for (int x = 0; x < partial.width; ++x) last_row += partial.at(x, partial.height - 1, 0);
  EXPECT_EQ(last_row, 0.0f);
}

TEST(InfoCommand, CountsMatchTheScene) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  std::string out;
  ASSERT_EQ(run_command(rtpro_command("info " + scene.string() + " --json") + " 2>/dev/null", &out), 0) << out;
  const nlohmann::json info = nlohmann::json::parse(out);
  EXPECT_EQ(info["spheres"]["stored"].get<int>(), 3 + 2);
  EXPECT_EQ(info["spheres"]["rendered"].get<int>(), 3 + 2 * 2);
  EXPECT_EQ(info["instances"].get<int>(), 2);
  EXPECT_EQ(info["prototypes"].get<int>(), 1);
  EXPECT_EQ(info["lights"]["point"].get<int>(), 1);
  EXPECT_EQ(info["lights"]["directional"].get<int>(), 1);
  EXPECT_EQ(info["triangles"]["rendered"].get<int>(), 0);
  out = run_rtpro("info " + scene.string(), 0);
  EXPECT_NE(out.find("after instancing"), std::string::npos);
}

}  // namespace render_command_test
}  // namespace rtpro
