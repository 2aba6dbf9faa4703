// Participating media through the rtpro binary, on both backends: the volumetric white furnace
// (an albedo-1 medium behind an index-matched boundary in a uniform sky of radiance 1 vanishes at
// every anisotropy, and on average when its scattering is coloured), Beer–Lambert through an
// absorbing interior, light-only, phase-only and MIS estimators of a lit fog agreeing, and bad
// media refused at their file:line:column.
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <regex>
#include <string>

namespace rtpro {
namespace medium_render_test {

Image render(const std::string& name, const std::string& text, const std::string& options) {
  const auto scene = test::write_file(name + ".yaml", text);
  const auto output = scene.parent_path() / (name + ".exr");
  test::run_rtpro(test::render_args(scene, output, "-q --no-journal " + options), 0);
  return read_image(output);
}

struct Stats {
  double mean = 0.0, min = 1e30, max = -1e30;
};

Stats stats(const Image& image) {
  Stats s;
  for (const float v : image.data) {
    s.mean += v;
    s.min = std::min(s.min, double(v));
    s.max = std::max(s.max, double(v));
  }
  s.mean /= double(image.data.size());
  return s;
}

TEST(MediumRender, VolumetricWhiteFurnaceOnBothBackends) {
  // Three albedo-1 spheres side by side, g = -0.7, 0 and 0.7, in a sky of radiance 1: a grey
  // medium is tracked analogously (every collision's weight 1), the phase function's sample
  // weighs p/pdf = 1 and Russian roulette leaves paths of throughput 1 alone, so every path brings
  // back exactly 1 and so does every pixel, not only their mean.
  for (const std::string backend : {"native", "embree"}) {
    const Image image = render("medium_furnace_" + backend, R"(rtpro: 1
camera: {position: [0, 0, -12], look_at: [0, 0, 0], fov: 30, resolution: [24, 8]}
render: {integrator: path, spp: 16, max_depth: 256, background: [1, 1, 1]}
materials:
  back: {type: interface, interior: {sigma_s: [2, 2, 2], anisotropy: -0.7}}
  even: {type: interface, interior: {sigma_s: [3, 3, 3]}}
  forward: {type: interface, interior: {sigma_s: [2, 2, 2], anisotropy: 0.7}}
world:
  - {type: sphere, center: [-2.2, 0, 0], radius: 1, material: back}
  - {type: sphere, center: [0, 0, 0], radius: 1, material: even}
  - {type: sphere, center: [2.2, 0, 0], radius: 1, material: forward}
)",
                               "--backend " + backend);
    const Stats s = stats(image);
    SCOPED_TRACE(backend);
    EXPECT_GT(s.min, 0.99);
    EXPECT_LT(s.max, 1.01);
  }
}

TEST(MediumRender, ColouredWhiteFurnaceAveragesToOne) {
  // Scattering of another colour in each channel: collisions are taken at the majorant of the
  // three and weighted per channel (medium_tracking.h), so pixels spread (±0.3 at 256 spp), but
  // their mean is 1. The image mean's standard error is 0.0045 per channel (measured: pixels'
  // standard deviation 0.072 over 256 pixels): 0.025 is more than 5 of them.
  for (const std::string backend : {"native", "embree"}) {
    const Image image = render("medium_coloured_furnace_" + backend, R"(rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 20, resolution: [16, 16]}
render: {integrator: path, spp: 256, max_depth: 256, background: [1, 1, 1]}
materials:
  fog: {type: interface, interior: {sigma_s: [0.5, 2, 4], anisotropy: 0.3}}
world:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: fog}
)",
                               "--backend " + backend);
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0;
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) sum += image.at(x, y, c);
      EXPECT_NEAR(sum / (image.width * image.height), 1.0, 0.025) << backend << ", channel " << c;
    }
  }
}

TEST(MediumRender, AbsorbingInteriorIsBeerLambert) {
  // The camera ray through the sphere's centre crosses 2 units of σa: the pixel is exp(−2σa)
  // exactly (closed form, no noise), on both backends.
  for (const std::string backend : {"native", "embree"}) {
    const Image image = render("medium_absorbing_" + backend, R"(rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 0.01, resolution: [1, 1]}
render: {integrator: path, spp: 4, max_depth: 4, background: [1, 1, 1]}
world:
  - {type: sphere, radius: 1, material: default, interior: {sigma_a: [0.1, 0.5, 2]}}
materials:
  default: {type: interface}
)",
                               "--backend " + backend);
    const float sigma[3] = {0.1f, 0.5f, 2.0f};
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.data[c], std::exp(-2.0f * sigma[c]), 2e-4f) << backend;
  }
}

// The image's mean over pixels and channels and that mean's standard error, from the render's
// own variance layer (each pixel's mean's variance per channel). A pixel's channels share their
// paths: its channel mean's standard deviation is taken as the mean of theirs, the most it can be.
struct Estimate {
  double mean = 0.0, error = 0.0;
};

Estimate estimate(const std::string& sampling, const std::string& backend) {
  const std::string scene = R"(rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 35, resolution: [16, 16]}
render: {integrator: path, spp: 32, max_depth: 6}
lights:
  - {type: sphere, center: [0.2, 2.6, 0.3], radius: 0.9, color: [1, 1, 1], intensity: 4}
materials:
  fog: {type: interface, interior: {sigma_s: [0.9, 0.7, 0.5], sigma_a: [0.1, 0.1, 0.2], anisotropy: 0.4}}
  floor: {type: diffuse, color: [0.5, 0.5, 0.5]}
world:
  - {type: sphere, center: [0, 0, 0], radius: 1.2, material: fog}
  - {type: sphere, center: [0, -101.2, 0], radius: 100, material: floor}
)";
  const Image image = render("lit_fog_" + sampling + "_" + backend, scene,
                             "--aov variance --set render.sampling=" + sampling + " --backend " + backend);
  const auto found = std::find(image.channels.begin(), image.channels.end(), "variance.R");
  if (found == image.channels.end()) {
    ADD_FAILURE() << "no variance layer";
    return {};
  }
  const int variance = static_cast<int>(found - image.channels.begin());
  double sum = 0.0, variances = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      double deviation = 0.0;
      for (int c = 0; c < 3; ++c) {
        sum += image.at(x, y, c);
        deviation += std::sqrt(image.at(x, y, variance + c)) / 3.0;
      }
      variances += deviation * deviation;
    }
  const double n = double(image.width) * image.height;
  return {sum / (3.0 * n), std::sqrt(variances) / n};
}

TEST(MediumRender, LitFogEstimatorsAgreeOnBothBackends) {
  for (const std::string backend : {"native", "embree"}) {
    const Estimate mis = estimate("mis", backend), light = estimate("light", backend),
                   phase = estimate("bsdf", backend);
    std::cout << "[fog] " << backend << ": mis " << mis.mean << " ± " << mis.error << ", light " << light.mean << " ± "
              << light.error << ", phase " << phase.mean << " ± " << phase.error << "\n";
    SCOPED_TRACE(backend);
    EXPECT_GT(mis.mean, 0.01);  // the fog is lit
    EXPECT_GT(mis.error, 0.0);
    EXPECT_NEAR(light.mean, mis.mean, 3.0 * std::hypot(light.error, mis.error));
    EXPECT_NEAR(phase.mean, mis.mean, 3.0 * std::hypot(phase.error, mis.error));
    EXPECT_NEAR(phase.mean, light.mean, 3.0 * std::hypot(phase.error, light.error));
  }
}

TEST(MediumRender, BadMediaAreRefusedWhereWritten) {
  const auto refuse = [](const std::string& interior, const std::string& text) {
    const auto scene = test::write_file("bad_medium.yaml", R"(rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0]}
materials:
  fog: {type: interface, interior: )" + interior + R"(}
)");
    const std::string answer = test::expect_rtpro_answer("info " + scene.string(), 2, text);
    EXPECT_TRUE(std::regex_search(answer, std::regex(scene.filename().string() + ":4:[0-9]+: "))) << answer;
  };
  refuse("{sigma_s: [1, -1, 1]}", "coefficient per scene unit");
  refuse("{sigma_a: [.nan, 1, 1]}", "sigma_a");
  refuse("{sigma_s: [1, 1, 1], anisotropy: 1}", "strictly between -1 (back) and 1");
  refuse("{sigma_s: [1, 1, 1], anisotropy: -1.5}", "strictly between -1 (back) and 1");
  refuse("{color: [0.5, 0.5, 0.5], density: -2}", "density");
  refuse("{color: [1.5, 0.5, 0.5]}", "albedo");
  refuse("{sigma_s: [1, 1, 1], density: 2}", "either sigma_a and sigma_s");
}

}  // namespace medium_render_test
}  // namespace rtpro
