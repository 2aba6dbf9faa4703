// Passes through the real binary: adaptive sampling (--noise-threshold) stops converged pixels,
// keeps the mean of what it renders, and says in the spp layer what each pixel took; a time limit
// ends the render with whole passes.
#include "exr_attribute.h"
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

namespace rtpro {
namespace adaptive_render_test {

using test::expect_rtpro_answer;
using test::render_args;
using test::rtpro_command;
using test::run_command;

// The upper half is black sky (zero error: converged at the first check), the lower half a floor
// lit by a small spherical lamp, with a ball's soft shadow and its lit side (noisy).
const char* kScene = R"(rtpro: 1
camera: {position: [0, 1, 4], look_at: [0, 1, 0], fov: 50, resolution: [48, 32]}
render: {integrator: path, spp: 256, max_depth: 3, seed: 7}
materials:
  floor: {type: diffuse, color: [0.6, 0.6, 0.6]}
  ball: {type: diffuse, color: [0.8, 0.3, 0.2]}
  lamp: {type: diffuse, color: [0, 0, 0], emission: [30, 30, 30]}
world:
  - {type: sphere, center: [0, -1000, 0], radius: 1000, material: floor}
  - {type: sphere, center: [0.3, 0.4, 0], radius: 0.4, material: ball}
  - {type: sphere, center: [-0.6, 1.6, 0.4], radius: 0.15, material: lamp}
)";

struct Rendered {
  Image image;
  nlohmann::json stats;
  std::string said;  // stderr and stdout
  std::filesystem::path file;
};

Rendered render(const std::string& name, const std::string& options) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto out = scene.parent_path() / (name + ".exr");
  const auto stats = scene.parent_path() / (name + ".json");
  std::string output;
  const int code = run_command(rtpro_command(render_args(scene, out) + " --stats-json " + stats.string() +
                                             " --aov spp,variance --progress never " + options),
                               &output);
  EXPECT_EQ(code, 0) << output;
  Rendered r;
  r.said = output;
  r.file = out;
  if (code != 0) return r;
  r.image = read_image(out);
  std::ifstream in(stats);
  r.stats = nlohmann::json::parse(in);
  return r;
}

int channel(const Image& image, const std::string& name) {
  const auto it = std::find(image.channels.begin(), image.channels.end(), name);
  return it == image.channels.end() ? -1 : static_cast<int>(it - image.channels.begin());
}

TEST(AdaptiveRender, ConvergedPixelsTakeNoMoreSamplesAndTheSppLayerCountsTheCameraRays) {
  const Rendered adaptive = render("adaptive", "--noise-threshold 0.02");
  ASSERT_FALSE(adaptive.image.data.empty());
  const int spp = channel(adaptive.image, "spp.count");
  ASSERT_GE(spp, 0);
  double total = 0.0, most = 0.0;
  for (int y = 0; y < adaptive.image.height; ++y)
    for (int x = 0; x < adaptive.image.width; ++x) {
      const double samples = adaptive.image.at(x, y, spp);
      total += samples;
      most = std::max(most, samples);
    }
  // Every sample is one camera ray.
  EXPECT_EQ(total, adaptive.stats["rays"]["camera"].get<double>());
  // The sky converged at the first check, after the 16 samples every pixel takes first (passes of
  // 1, 1, 2, 4 and 8), and took no more; the noisy floor went on.
  for (int x = 0; x < adaptive.image.width; ++x) EXPECT_EQ(adaptive.image.at(x, 0, spp), 16.0f) << "x " << x;
  EXPECT_GT(most, 64.0);
  EXPECT_LT(total, 256.0 * adaptive.image.width * adaptive.image.height / 2);
  EXPECT_EQ(adaptive.stats["passes"]["total"], 20);
}

// The floor's rows at equal weight: adaptive sampling takes fewer samples where the error is low,
// never a biased subset of them (each pixel's samples are a prefix of its sample sequence).
TEST(AdaptiveRender, KeepsTheMeanOfAFlatRegionWithinNoise) {
  const Rendered adaptive = render("adaptive_mean", "--noise-threshold 0.05");
  const Rendered uniform = render("uniform", "");
  ASSERT_FALSE(adaptive.image.data.empty());
  ASSERT_FALSE(uniform.image.data.empty());
  const int variance = channel(uniform.image, "variance.R");
  ASSERT_GE(variance, 0);
  for (int c = 0; c < 3; ++c) {
    double sum_a = 0, sum_u = 0, var_a = 0, var_u = 0;
    int n = 0;
    for (int y = 24; y < 32; ++y)
      for (int x = 0; x < 48; ++x, ++n) {
        sum_a += adaptive.image.at(x, y, c);
        sum_u += uniform.image.at(x, y, c);
        var_a += adaptive.image.at(x, y, variance + c);
        var_u += uniform.image.at(x, y, variance + c);
      }
    const double sigma = std::sqrt(var_a + var_u) / n;
    SCOPED_TRACE("channel " + std::to_string(c));
    EXPECT_GT(sum_u / n, 0.01);  // lit
    EXPECT_NEAR(sum_a / n, sum_u / n, 4.0 * sigma + 1e-6);
  }
}

// The relMSE metric: the sky stops at the first check, the floor goes on, every sample is counted,
// and the floor's mean stays the uniform render's within noise.
TEST(AdaptiveRender, RelMseMetricStopsConvergedPixelsAndKeepsTheMean) {
  const Rendered adaptive = render("relmse", "--noise-threshold 0.002 --noise-metric relmse --min-samples 16");
  const Rendered uniform = render("relmse_uniform", "");
  ASSERT_FALSE(adaptive.image.data.empty());
  ASSERT_FALSE(uniform.image.data.empty());
  const int spp = channel(adaptive.image, "spp.count"), variance = channel(uniform.image, "variance.R");
  double total = 0.0, most = 0.0;
  for (int y = 0; y < adaptive.image.height; ++y)
    for (int x = 0; x < adaptive.image.width; ++x) {
      total += adaptive.image.at(x, y, spp);
      most = std::max(most, static_cast<double>(adaptive.image.at(x, y, spp)));
    }
  EXPECT_EQ(total, adaptive.stats["rays"]["camera"].get<double>());
  for (int x = 0; x < adaptive.image.width; ++x) EXPECT_EQ(adaptive.image.at(x, 0, spp), 16.0f) << "x " << x;
  // The statistics say what the pixels took, not the 256 asked for.
  const nlohmann::json& taken = adaptive.stats["spp_taken"];
  EXPECT_EQ(taken["min"].get<int>(), 16);
  EXPECT_EQ(taken["max"].get<double>(), most);
  EXPECT_NEAR(taken["mean"].get<double>(), total / (adaptive.image.width * adaptive.image.height), 1e-9);
  EXPECT_EQ(adaptive.stats["spp"].get<double>(), most);
  EXPECT_EQ(adaptive.stats["spp_requested"].get<int>(), 256);
  EXPECT_GT(most, 64.0);
  EXPECT_LT(total, 256.0 * adaptive.image.width * adaptive.image.height / 2);
  for (int c = 0; c < 3; ++c) {
    double sum_a = 0, sum_u = 0, var = 0;
    int n = 0;
    for (int y = 24; y < 32; ++y)
      for (int x = 0; x < 48; ++x, ++n) {
        sum_a += adaptive.image.at(x, y, c);
        sum_u += uniform.image.at(x, y, c);
        var += adaptive.image.at(x, y, variance + c) + uniform.image.at(x, y, variance + c);
      }
    SCOPED_TRACE("channel " + std::to_string(c));
    EXPECT_NEAR(sum_a / n, sum_u / n, 4.0 * std::sqrt(var) / n + 1e-6);
  }
}

// Stopped by the time limit, the image holds whole passes (the first always finishes) and is the
// output, not a partial one.
TEST(AdaptiveRender, TimeLimitEndsWithTheFinishedPasses) {
  const Rendered limited = render("limited", "--spp 65536 --time-limit 0.5");
  ASSERT_FALSE(limited.image.data.empty());
  EXPECT_EQ(limited.stats["passes"]["stop"], "time limit");
  const int done = limited.stats["passes"]["done"].get<int>();
  EXPECT_GE(done, 1);
  EXPECT_LT(done, limited.stats["passes"]["total"].get<int>());
  EXPECT_TRUE(limited.stats["complete"].get<bool>());
  // Every pixel took the same samples: whole passes, no tile ahead of another.
  const int spp = channel(limited.image, "spp.count");
  const float first = limited.image.at(0, 0, spp);
  for (int y = 0; y < limited.image.height; ++y)
    for (int x = 0; x < limited.image.width; ++x) ASSERT_EQ(limited.image.at(x, y, spp), first);
  // What they took is what the statistics and the metadata say, beside what was asked.
  const int taken = static_cast<int>(first);
  EXPECT_LT(taken, 65536);
  EXPECT_EQ(limited.stats["spp"].get<int>(), taken);
  EXPECT_EQ(limited.stats["spp_taken"]["min"].get<int>(), taken);
  EXPECT_EQ(limited.stats["spp_taken"]["max"].get<int>(), taken);
  EXPECT_EQ(limited.stats["spp_requested"].get<int>(), 65536);
  EXPECT_EQ(test::exr_string_attribute(limited.file, "rtpro:spp"), std::to_string(taken));
  EXPECT_EQ(test::exr_string_attribute(limited.file, "rtpro:spp_min"), std::to_string(taken));
  EXPECT_EQ(test::exr_string_attribute(limited.file, "rtpro:spp_max"), std::to_string(taken));
  EXPECT_EQ(test::exr_string_attribute(limited.file, "rtpro:spp_requested"), "65536");
  EXPECT_NE(limited.said.find(std::to_string(taken) + " of 65536 spp: time limit, "), std::string::npos)
      << limited.said;
}

TEST(AdaptiveRender, RefusesAThresholdForAOnePassRender) {
  const auto scene = test::write_file("scene.yaml", kScene);
  expect_rtpro_answer(render_args(scene, scene.parent_path() / "x.exr", "--integrator whitted --noise-threshold 0.01"),
                      2, "one pass");
}

// A least number of samples above the most a pixel takes is said, not silently cut to it.
TEST(AdaptiveRender, WarnsOfMinSamplesAboveTheSpp) {
  const auto scene = test::write_file("scene.yaml", kScene);
  expect_rtpro_answer(
      render_args(scene, scene.parent_path() / "x.exr", "--size 8x8 --spp 4 --noise-threshold 0.01 --min-samples 64"),
      0, "warning: --min-samples 64 is more than the 4 samples a pixel takes at most");
}

}  // namespace adaptive_render_test
}  // namespace rtpro
