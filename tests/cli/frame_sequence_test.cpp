// Keyframed scene values and --frames / --skip-existing, through the real binary (issue 14).
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <sstream>

namespace rtpro {
namespace frame_sequence_test {

using test::expect_rtpro_answer;
using test::render_args;
using test::rtpro_command;
using test::run_command;
using test::run_rtpro;

const char* kAnimated = R"(rtpro: 1
camera:
  position: {keyframes: {1: [0, 1, 6], 5: [2, 1, 5]}}
  look_at: [0, 0.5, 0]
  fov: {keyframes: {1: 40, 3: 30}, interpolation: smooth}
  resolution: [20, 14]
render: {spp: 4, seed: 2}
lights:
  - {type: point, position: [4, 6, 5], intensity: {keyframes: {1: 1, 5: 0.5}, interpolation: step}}
world:
  - {type: sphere, center: [0, -1000, 0], radius: 1000}
  - {type: sphere, center: [0, 0.7, 0], radius: 0.7}
)";

nlohmann::json camera_at(const std::filesystem::path& scene, int frame) {
  const std::string info = run_rtpro("info --json " + scene.string() + " -D frame=" + std::to_string(frame), 0);
  return nlohmann::json::parse(info)["camera"];
}

TEST(Keyframes, InterpolateBetweenKeysAndHoldOutside) {
  const auto scene = test::write_file("anim.yaml", kAnimated);
  EXPECT_EQ(camera_at(scene, 1)["position"], nlohmann::json::array({0.0, 1.0, 6.0}));
  EXPECT_EQ(camera_at(scene, 3)["position"], nlohmann::json::array({1.0, 1.0, 5.5}));
  EXPECT_EQ(camera_at(scene, 0)["position"], nlohmann::json::array({0.0, 1.0, 6.0}));
  EXPECT_EQ(camera_at(scene, 9)["position"], nlohmann::json::array({2.0, 1.0, 5.0}));
  EXPECT_EQ(camera_at(scene, 2)["fov"], 35.0);  // smoothstep(0.5) = 0.5
  // Without a frame, a scene is at frame 1.
  EXPECT_EQ(nlohmann::json::parse(run_rtpro("info --json " + scene.string(), 0))["camera"]["fov"], 40.0);
}

TEST(Keyframes, MistakesAreErrorsAtTheirPlace) {
  const auto bad_shape = test::write_file(
      "a.yaml", std::string(kAnimated).replace(std::string(kAnimated).find("5: [2, 1, 5]"), 12, "5: [2, 1]"));
  std::string out = expect_rtpro_answer("info " + bad_shape.string(), 2, "a.yaml:3:");
  EXPECT_NE(out.find("the same shape as the first"), std::string::npos) << out;
  const auto bad_mode =
      test::write_file("b.yaml", std::string(kAnimated).replace(std::string(kAnimated).find("smooth"), 6, "smoth"));
  out = expect_rtpro_answer("info " + bad_mode.string(), 2, "b.yaml:5:");
  EXPECT_NE(out.find("did you mean 'smooth'?"), std::string::npos) << out;
}

TEST(FrameSequence, EachFrameIsTheImageItRendersAlone) {
  const auto scene = test::write_file("anim.yaml", kAnimated);
  const auto dir = scene.parent_path();
  run_rtpro(render_args(scene, dir / "seq_##.exr", "--frames 1-5:2 -q"), 0);
  EXPECT_FALSE(std::filesystem::exists(dir / "seq_02.exr"));
  std::vector<float> previous;
  for (int frame : {1, 3, 5}) {
    const auto alone = dir / ("alone_" + std::to_string(frame) + ".exr");
    run_rtpro(render_args(scene, alone) + " -D frame=" + std::to_string(frame) + " -q", 0);
    const Image in_sequence = read_image(dir / ("seq_0" + std::to_string(frame) + ".exr"));
    const Image single = read_image(alone);
    EXPECT_EQ(in_sequence.data, single.data) << "frame " << frame;
    EXPECT_NE(in_sequence.data, previous) << "frame " << frame << " did not move";
    previous = in_sequence.data;
  }
}

TEST(FrameSequence, SkipExistingLeavesWrittenFramesAlone) {
  const auto scene = test::write_file("anim.yaml", kAnimated);
  const auto dir = scene.parent_path();
  std::ofstream(dir / "f_0002.exr") << "rendered by another machine";
  run_rtpro(render_args(scene, dir / "f_####.exr", "--frames 1-3 --skip-existing -q"), 0);
  std::ifstream kept(dir / "f_0002.exr");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "rendered by another machine");
  EXPECT_TRUE(std::filesystem::exists(dir / "f_0001.exr"));
  EXPECT_TRUE(std::filesystem::exists(dir / "f_0003.exr"));
}

TEST(FrameSequence, ProgressAndStatsNameTheFrame) {
  const auto scene = test::write_file("anim.yaml", kAnimated);
  const auto dir = scene.parent_path();
  std::string out;
  ASSERT_EQ(run_command(
                "{ " +
                    rtpro_command(render_args(scene, dir / "p_#.exr") +
                                  " --frames 2-3 -q --progress json --stats-json " + (dir / "stats_#.json").string()) +
                    " > /dev/null; }",
                &out),
            0)
      << out;
  std::istringstream lines(out);
  std::vector<int> finals;
  for (std::string line; std::getline(lines, line);) {
    const nlohmann::json progress = nlohmann::json::parse(line);
    if (progress["final"].get<bool>()) finals.push_back(progress["frame"].get<int>());
  }
  EXPECT_EQ(finals, (std::vector<int>{2, 3})) << out;
  EXPECT_TRUE(std::filesystem::exists(dir / "stats_2.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "stats_3.json"));
  out =
      run_rtpro(render_args(scene, dir / "q_#.exr") + " --frames 2-3 --stats-json " + (dir / "stats.json").string(), 2);
  EXPECT_NE(out.find("--stats-json with --frames needs a frame number pattern"), std::string::npos) << out;
}

TEST(FrameSequence, PatternAndRangeMistakesAreRefused) {
  const auto scene = test::write_file("anim.yaml", kAnimated);
  const auto dir = scene.parent_path();
  expect_rtpro_answer(render_args(scene, dir / "x.exr", "--frames 1-3"), 2, "--frames needs a frame number pattern");
  expect_rtpro_answer(render_args(scene, dir / "x_##.exr"), 2, "give --frames");
  expect_rtpro_answer(render_args(scene, dir / "x_##.exr", "--frames 5-1"), 2, "the first frame is after the last");
  expect_rtpro_answer(render_args(scene, dir / "x_##.exr", "--frames 1-3:0"), 2, "the step must be at least 1");
  expect_rtpro_answer(render_args(scene, dir / "x_##.exr", "--frames 5-5:9223372036854775807"), 2,
                      "--frames '5-5:9223372036854775807': the step must be at most 99999999");
  expect_rtpro_answer(render_args(scene, dir / "x_##.exr", "--frames 1-3 -D frame=2"), 2, "--frames sets the frame");
  EXPECT_FALSE(std::filesystem::exists(dir / "x_01.exr"));
}

// A run of more than 31 '#' once went through a 32-byte buffer: every frame wrote one file.
TEST(FrameSequence, ALongPatternGivesEachFrameItsOwnFile) {
  const auto scene = test::write_file("anim.yaml", kAnimated);
  const auto dir = scene.parent_path();
  const std::string hashes(40, '#');
  run_rtpro(render_args(scene, dir / ("long_" + hashes + ".exr"), "--frames 1-2 -q"), 0);
  for (const char* frame : {"1", "2"})
    EXPECT_TRUE(std::filesystem::exists(dir / ("long_" + std::string(39, '0') + frame + ".exr"))) << "frame " << frame;
}

}  // namespace frame_sequence_test
}  // namespace rtpro
