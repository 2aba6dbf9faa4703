// `rtpro render --denoise` through the real binary: the denoised colour, the noisy one kept as a
// layer and equal to the render without --denoise, the layers the denoiser read, and PNG output.
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace rtpro {
namespace render_denoise_test {

using test::render_args;

const char* kScene = R"(rtpro: 1
camera: {position: [0, 1, 4], look_at: [0, 0.4, 0], fov: 40, resolution: [48, 32]}
render: {integrator: path, spp: 8, max_depth: 4}
materials:
  white: {type: diffuse, color: [0.8, 0.8, 0.8]}
  red: {type: diffuse, color: [0.8, 0.1, 0.1]}
lights:
  - {type: sphere, center: [1, 3, 2], radius: 0.5, intensity: 20}
world:
  - {type: sphere, center: [0, -1000, 0], radius: 1000, material: white}
  - {type: sphere, center: [0, 0.5, 0], radius: 0.5, material: red}
)";

int channel(const Image& image, const std::string& name) {
  const auto found = std::find(image.channels.begin(), image.channels.end(), name);
  return found == image.channels.end() ? -1 : static_cast<int>(found - image.channels.begin());
}

TEST(RenderDenoise, KeepsTheNoisyColourAndTheLayersAndSmoothsTheColour) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto dir = scene.parent_path();
  test::run_rtpro(render_args(scene, dir / "noisy.exr", "-q --no-journal"), 0);
  test::run_rtpro(render_args(scene, dir / "denoised.exr", "-q --no-journal --denoise"), 0);
  const Image noisy = read_image(dir / "noisy.exr"), denoised = read_image(dir / "denoised.exr");
  for (const char* name :
       {"R", "G", "B", "noisy.R", "noisy.G", "noisy.B", "albedo.R", "N.X", "depth.Z", "half_a.R", "half_b.B"})
    EXPECT_GE(channel(denoised, name), 0) << name;
  // The noisy layer is the render without --denoise, bit for bit; the colour differs from it but
  // keeps its mean.
  double noisy_sum = 0.0, denoised_sum = 0.0;
  int differing = 0;
  for (int y = 0; y < noisy.height; ++y)
    for (int x = 0; x < noisy.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float a = noisy.at(x, y, channel(noisy, std::string("RGB").substr(c, 1)));
        EXPECT_EQ(a, denoised.at(x, y, channel(denoised, std::string("noisy.") + "RGB"[c]))) << x << "," << y;
        const float d = denoised.at(x, y, channel(denoised, std::string("RGB").substr(c, 1)));
        differing += d != a;
        noisy_sum += a;
        denoised_sum += d;
      }
  EXPECT_GT(differing, noisy.width * noisy.height);
  EXPECT_NEAR(denoised_sum / noisy_sum, 1.0, 0.05);
}

TEST(RenderDenoise, WritesADisplayImageToo) {
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto png = scene.parent_path() / "denoised.png";
  test::run_rtpro(render_args(scene, png, "-q --no-journal --denoise"), 0);
  const Image image = read_image(png);
  EXPECT_EQ(image.width, 48);
  EXPECT_EQ(image.channel_count(), 3);
}

}  // namespace render_denoise_test
}  // namespace rtpro
