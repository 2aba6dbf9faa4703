// End-to-end tests of `rtpro render` and `rtpro info`, running the real binary.
#include "rtpro/image/image_io.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace rtpro {
namespace render_command_test {

using test::rtpro_executable;
using test::run_command;

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

std::string rtpro_cmd(const std::string& args) { return rtpro_executable().string() + " " + args; }

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

TEST(RenderCommand, SameImageAtOneAndTwoThreads) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  const auto dir = scene.parent_path();
  std::string out;
  ASSERT_EQ(
      run_command(rtpro_cmd("render " + scene.string() + " -o " + (dir / "t1.exr").string() + " --threads 1 -q"), &out),
      0)
      << out;
  ASSERT_EQ(
      run_command(rtpro_cmd("render " + scene.string() + " -o " + (dir / "t2.exr").string() + " --threads 2 -q"), &out),
      0)
      << out;
  const Image one = read_image(dir / "t1.exr"), two = read_image(dir / "t2.exr");
  ASSERT_EQ(one.data.size(), two.data.size());
  EXPECT_EQ(std::memcmp(one.data.data(), two.data.data(), one.data.size() * sizeof(float)), 0);
  float sum = 0;
  for (float v : one.data) sum += v;
  EXPECT_GT(sum, 10.0f);
}

TEST(RenderCommand, SameImageWithATileLargerThanTheImage) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  const auto dir = scene.parent_path();
  const std::string base = rtpro_cmd("render " + scene.string() + " -q -o ");
  std::string out;
  ASSERT_EQ(run_command(base + (dir / "default.exr").string(), &out), 0) << out;
  ASSERT_EQ(run_command(base + (dir / "one_tile.exr").string() + " --tile-size 2147483647", &out), 0) << out;
  test::expect_same_pixels(dir / "default.exr", dir / "one_tile.exr");
}

TEST(RenderCommand, StatsJsonParsesAndCountsAddUp) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  const auto dir = scene.parent_path();
  std::string out;
  ASSERT_EQ(run_command(rtpro_cmd("render " + scene.string() + " -o " + (dir / "s.exr").string() +
                                  " --stats --stats-json " + (dir / "stats.json").string() + " --progress never"),
                        &out),
            0)
      << out;
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
  const std::string base = rtpro_cmd("render " + scene.string() + " -q -o ");
  ASSERT_EQ(run_command(base + (dir / "full.exr").string()), 0);
  ASSERT_EQ(run_command(base + (dir / "region.exr").string() + " --region 10,5,40,30"), 0);
  ASSERT_EQ(run_command(base + (dir / "crop.exr").string() + " --region 10,5,40,30 --crop"), 0);
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
  std::string out;
  EXPECT_EQ(run_command(base + (dir / "bad.exr").string() + " --region 10,5,400,30", &out), 2) << out;
  EXPECT_EQ(run_command(base + (dir / "bad.exr").string() + " --region 1,2,3", &out), 2) << out;
}

TEST(RenderCommand, AovLayersAreWrittenWithCompositorNames) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  const auto file = scene.parent_path() / "aov.exr";
  std::string out;
  ASSERT_EQ(run_command(rtpro_cmd("render " + scene.string() + " -q -o " + file.string() +
                                  " --aov albedo,normal,depth,object-id"),
                        &out),
            0)
      << out;
  const Image image = read_image(file);
  for (const char* name :
       {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "depth.Z", "object_id.id"})
    EXPECT_NE(std::find(image.channels.begin(), image.channels.end(), name), image.channels.end()) << name;
  EXPECT_EQ(run_command(rtpro_cmd("render " + scene.string() + " -q -o " + file.string() + " --aov bogus"), &out), 2);
  // A layer asked for twice is refused before the render, not when the image is written.
  const auto twice = scene.parent_path() / "twice.exr";
  EXPECT_EQ(run_command(
                rtpro_cmd("render " + scene.string() + " -q -o " + twice.string() + " --aov depth,albedo,depth"), &out),
            2)
      << out;
  EXPECT_NE(out.find("--aov depth"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(twice));
}

TEST(RenderCommand, BadInputsFailCleanlyAndLeaveNoFile) {
  const auto dir = test::scratch_dir();
  const auto bad_scene = test::write_file("bad.yaml",
                                          "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0]}\n"
                                          "world:\n  - {type: sphere, center: [0, 0, 0], radius: -1}\n");
  std::string out;
  const auto target = bad_scene.parent_path() / "never.png";
  EXPECT_EQ(run_command(rtpro_cmd("render " + bad_scene.string() + " -o " + target.string()), &out), 2);
  EXPECT_NE(out.find("bad.yaml:4:"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(target));
  EXPECT_EQ(run_command(rtpro_cmd("render " + (dir / "missing.yaml").string() + " -o " + target.string()), &out), 2);
  EXPECT_NE(out.find("missing.yaml"), std::string::npos) << out;
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  EXPECT_EQ(run_command(rtpro_cmd("render " + scene.string() + " -o " + (dir / "x.unknownformat").string()), &out), 2);
  EXPECT_EQ(run_command(rtpro_cmd("render " + scene.string() + " -o /nonexistent-folder/x.png"), &out), 1) << out;
  EXPECT_EQ(run_command(rtpro_cmd("render " + scene.string() + " -o " + target.string() + " --spp 0"), &out), 2);
  EXPECT_NE(out.find("--spp 0: render.spp must be from 1 to 65536"), std::string::npos) << out;
  EXPECT_EQ(run_command(rtpro_cmd("render " + scene.string() + " -o " + target.string() + " --no-such-flag"), &out), 2);
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
  std::ifstream previous(output);
  std::string text((std::istreambuf_iterator<char>(previous)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "a previous good image");
  const Image partial = read_image(dir / "out.partial.exr");
  EXPECT_EQ(partial.width, 1600);
  // Finished tiles hold the picture (every pixel at least the sky colour); unfinished ones are 0.
  float sum = 0;
  for (float v : partial.data) sum += v;
  EXPECT_GT(sum, 0.0f);
  float last_row = 0;
  for (int x = 0; x < partial.width; ++x) last_row += partial.at(x, partial.height - 1, 0);
  EXPECT_EQ(last_row, 0.0f);
}

TEST(InfoCommand, CountsMatchTheScene) {
  const auto scene = test::write_file("scene.yaml", kSmallScene);
  std::string out;
  ASSERT_EQ(run_command(rtpro_cmd("info " + scene.string() + " --json") + " 2>/dev/null", &out), 0) << out;
  const nlohmann::json info = nlohmann::json::parse(out);
  EXPECT_EQ(info["spheres"]["stored"].get<int>(), 3 + 2);
  EXPECT_EQ(info["spheres"]["rendered"].get<int>(), 3 + 2 * 2);
  EXPECT_EQ(info["instances"].get<int>(), 2);
  EXPECT_EQ(info["prototypes"].get<int>(), 1);
  EXPECT_EQ(info["lights"]["point"].get<int>(), 1);
  EXPECT_EQ(info["lights"]["directional"].get<int>(), 1);
  EXPECT_EQ(info["triangles"]["rendered"].get<int>(), 0);
  ASSERT_EQ(run_command(rtpro_cmd("info " + scene.string()), &out), 0);
  EXPECT_NE(out.find("after instancing"), std::string::npos);
}

}  // namespace render_command_test
}  // namespace rtpro
