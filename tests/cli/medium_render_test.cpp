// Participating media through the rtpro binary, on both backends: the volumetric white furnace
// (an albedo-1 medium behind an index-matched boundary in a uniform sky of radiance 1 vanishes at
// every anisotropy), Beer–Lambert through an absorbing interior, light-only, phase-only and MIS
// estimators of a lit fog agreeing, and bad media refused at their file:line:column.
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
  for (const std::string backend : {"native", "embree"})
    for (const std::string g : {"-0.7", "0", "0.7"}) {
      const Image image = render("medium_furnace_" + backend,
                                 R"(rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 20, resolution: [16, 16]}
render: {integrator: path, spp: 64, max_depth: 256, background: [1, 1, 1]}
materials:
  fog: {type: interface, interior: {sigma_s: [2, 2, 2], anisotropy: )" +
                                     g + R"(}}
world:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: fog}
)",
                                 "--backend " + backend);
      const Stats s = stats(image);
      SCOPED_TRACE(backend + ", g = " + g);
      EXPECT_NEAR(s.mean, 1.0, 0.01);
      // Only Russian roulette's weights spread a pixel (every path that escapes carries 1): at
      // 64 spp its pixels stay within ±0.12 (measured ±0.11).
      EXPECT_GT(s.min, 0.85);
      EXPECT_LT(s.max, 1.15);
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

// Mean of the image and the standard error of that mean, from two renders of other seeds: the
// pixels' noise variance is half their differences' variance.
struct Estimate {
  double mean = 0.0, error = 0.0;
};

Estimate estimate(const std::string& sampling) {
  const std::string scene = R"(rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 35, resolution: [16, 16]}
render: {integrator: path, spp: 16, max_depth: 6}
lights:
  - {type: sphere, center: [0.2, 2.6, 0.3], radius: 0.9, color: [1, 1, 1], intensity: 4}
materials:
  fog: {type: interface, interior: {sigma_s: [0.9, 0.7, 0.5], sigma_a: [0.1, 0.1, 0.2], anisotropy: 0.4}}
  floor: {type: diffuse, color: [0.5, 0.5, 0.5]}
world:
  - {type: sphere, center: [0, 0, 0], radius: 1.2, material: fog}
  - {type: sphere, center: [0, -101.2, 0], radius: 100, material: floor}
)";
  const Image a = render("lit_fog_" + sampling + "_a", scene, "--set render.sampling=" + sampling + " --seed 1");
  const Image b = render("lit_fog_" + sampling + "_b", scene, "--set render.sampling=" + sampling + " --seed 2");
  double sum = 0.0, differences = 0.0, squares = 0.0;
  for (std::size_t i = 0; i < a.data.size(); ++i) {
    sum += a.data[i] + b.data[i];
    const double d = double(a.data[i]) - double(b.data[i]);
    differences += d;
    squares += d * d;
  }
  const double n = double(a.data.size());
  const double variance = (squares / n - (differences / n) * (differences / n)) / 2.0;
  return {sum / (2.0 * n), std::sqrt(variance / (2.0 * n))};
}

TEST(MediumRender, LitFogEstimatorsAgree) {
  const Estimate mis = estimate("mis"), light = estimate("light"), phase = estimate("bsdf");
  std::cout << "[fog] mis " << mis.mean << " ± " << mis.error << ", light " << light.mean << " ± " << light.error
            << ", phase " << phase.mean << " ± " << phase.error << "\n";
  EXPECT_GT(mis.mean, 0.01);  // the fog is lit
  EXPECT_NEAR(light.mean, mis.mean, 3.0 * std::hypot(light.error, mis.error));
  EXPECT_NEAR(phase.mean, mis.mean, 3.0 * std::hypot(phase.error, mis.error));
  EXPECT_NEAR(phase.mean, light.mean, 3.0 * std::hypot(phase.error, light.error));
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
