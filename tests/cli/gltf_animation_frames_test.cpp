// glTF animations rendered as shots through the real binary, on both backends: frame f is the
// file posed at f / render.fps seconds, for an animated object and for a camera under an animated
// parent. Each check is where a small emissive quad lands in the image, against the pinhole
// projection of the position the keys give (computed here, not by rtpro).
#include "rtpro/image/image_io.h"
#include "scene/gltf_test_files.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace rtpro {
namespace gltf_animation_frames_test {

constexpr int kWidth = 64, kHeight = 32;
constexpr double kYfov = 0.5, kDistance = 5.0;

// The image column (pixels from the left edge) where a point at height 0, `x` across and
// kDistance in front of the camera appears.
double column_of(double x) {
  const double half_width = std::tan(kYfov / 2) * kWidth / kHeight;  // at unit distance
  return kWidth / 2.0 * (1.0 + x / kDistance / half_width);
}

// The brightness-weighted mean column of the image's red channel.
double centroid_column(const Image& image) {
  double sum = 0.0, weighted = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      sum += image.at(x, y, 0);
      weighted += (x + 0.5) * image.at(x, y, 0);
    }
  return weighted / sum;
}

// A 0.5-wide emissive quad at node 0 and a camera (kYfov, aspect 2) kDistance in front of the
// origin at node 2, a child of node 1. `quad_x` and `rig_x`: x keyed at 0 and 2/24 s (frames 0
// and 2 at 24 fps) for the quad and the camera's parent.
std::filesystem::path animated_file(const std::string& name, std::vector<float> quad_x, std::vector<float> rig_x) {
  test::GltfFile gltf;
  const int positions = gltf.floats({-0.25f, 0.25f, 0, -0.25f, -0.25f, 0, 0.25f, -0.25f, 0, 0.25f, 0.25f, 0}, "VEC3");
  const int quad = gltf.mesh(positions, gltf.indices({1, 2, 3, 1, 3, 0}));
  gltf.json["meshes"][quad]["primitives"][0]["material"] = 0;
  gltf.json["materials"] = {
      {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}}, {"emissiveFactor", {1, 1, 1}}}};
  gltf.json["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", kYfov}, {"aspectRatio", 2.0}, {"znear", 0.1}}}}};
  gltf.node({{"mesh", quad}});
  gltf.node({{"children", {2}}});
  gltf.node({{"camera", 0}, {"translation", {0, 0, kDistance}}});
  gltf.scene({0, 1});
  const int times = gltf.floats({0.0f, 2.0f / 24.0f}, "SCALAR");
  nlohmann::json samplers = nlohmann::json::array(), channels = nlohmann::json::array();
  for (const auto& [node, x] : {std::pair{0, quad_x}, std::pair{1, rig_x}}) {
    samplers.push_back({{"input", times}, {"output", gltf.floats({x[0], 0, 0, x[1], 0, 0}, "VEC3")}});
    channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", node}, {"path", "translation"}}}});
  }
  gltf.json["animations"] = {{{"samplers", samplers}, {"channels", channels}}};
  return gltf.write(name);
}

std::string frame_options(const std::string& backend) {
  return "--size " + std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --spp 4 -q --backend " + backend;
}

TEST(GltfAnimationFrames, AnAnimatedObjectMovesAsItsKeysSayOnBothBackends) {
  const auto file = animated_file("moving_quad", {-1, 1}, {0, 0});
  const auto dir = file.parent_path();
  for (const std::string backend : {"embree", "native"}) {
    const auto pattern = dir / ("quad_" + backend + "_#.exr");
    test::run_rtpro(test::render_args(file, pattern, frame_options(backend) + " --frames 0-2"), 0);
    for (int frame = 0; frame <= 2; ++frame) {
      const Image image = read_image(dir / ("quad_" + backend + "_" + std::to_string(frame) + ".exr"));
      EXPECT_NEAR(centroid_column(image), column_of(-1.0 + frame), 0.05) << backend << " frame " << frame;
    }
  }
}

TEST(GltfAnimationFrames, ACameraUnderAnAnimatedParentFollowsItAndFpsSetsTheTime) {
  const auto file = animated_file("moving_camera", {0, 0}, {0, 1});
  const auto out = file.parent_path() / "camera.exr";
  // Frame 1 at 24 fps is 1/24 s, halfway: the camera is at x = 0.5, the quad 0.5 to its left.
  test::run_rtpro(test::render_args(file, out, frame_options("native") + " -D frame=1"), 0);
  EXPECT_NEAR(centroid_column(read_image(out)), column_of(-0.5), 0.05);
  // At 12 fps frame 1 is 2/24 s: the last key.
  test::run_rtpro(test::render_args(file, out, frame_options("embree") + " -D frame=1 --set render.fps=12"), 0);
  EXPECT_NEAR(centroid_column(read_image(out)), column_of(-1.0), 0.05);
}

// The mean column of the orange pixels (red well above blue): where the box of
// scenes/animated_shot.gltf is.
double orange_column(const Image& image) {
  double count = 0.0, sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y, 0) > 0.05f && image.at(x, y, 0) > 2.0f * image.at(x, y, 2)) {
        count += 1.0;
        sum += x + 0.5;
      }
  return count > 0.0 ? sum / count : -1.0;
}

// The shipped shot (scripts/make_animated_gltf.py) as a short sequence: the box slides from
// x = -1 to 1 under a camera centred on x = 0, both backends agreeing on every frame.
TEST(GltfAnimationFrames, TheShippedShotRendersAsASequenceOnBothBackends) {
  const auto scene = test::scenes_dir() / "animated_shot.gltf";
  const auto dir = test::scratch_dir();
  std::vector<Image> native;
  for (const std::string backend : {"native", "embree"}) {
    const auto pattern = dir / ("shot_" + backend + "_##.exr");
    test::run_rtpro(test::render_args(scene, pattern, "--size 48x32 --spp 2 -q --frames 0-24:12 --backend " + backend),
                    0);
    for (int frame = 0; frame <= 24; frame += 12) {
      const std::string number = frame < 10 ? "0" + std::to_string(frame) : std::to_string(frame);
      const Image image = read_image(dir / ("shot_" + backend + "_" + number + ".exr"));
      const double column = orange_column(image);
      if (frame == 0) {
        EXPECT_LT(column, 20.0) << backend;
      }
      if (frame == 12) {
        EXPECT_NEAR(column, 24.0, 1.5) << backend;
      }
      if (frame == 24) {
        EXPECT_GT(column, 28.0) << backend;
      }
      if (backend == "native") {
        native.push_back(image);
        continue;
      }
      const Image& other = native[std::size_t(frame / 12)];
      double difference = 0.0;
      for (std::size_t i = 0; i < image.data.size(); ++i) difference += std::fabs(image.data[i] - other.data[i]);
      EXPECT_LT(difference / double(image.data.size()), 1e-3) << "frame " << frame;
    }
  }
}

TEST(GltfAnimationFrames, InfoSaysHowManyFramesTheAnimationRunsAndBadFpsIsAnError) {
  const auto file = animated_file("bad_fps", {0, 0}, {0, 0});
  // Keys up to 2/24 s: frames 0 to 2 at 24 fps, 0 to 3 at 30 (2.5 rounded up).
  test::expect_rtpro_answer("info " + file.string(), 0, "is animated: 0.0833333 s, frames 0 to 2 at 24 fps");
  test::expect_rtpro_answer("info " + file.string() + " --set render.fps=30", 0, "frames 0 to 3 at 30 fps");
  test::expect_rtpro_answer("info " + file.string() + " --set render.fps=0", 2, "render.fps");
}

}  // namespace gltf_animation_frames_test
}  // namespace rtpro
