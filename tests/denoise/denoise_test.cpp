// The denoiser on synthetic renders with known answers: flat regions stay flat and keep their
// level, albedo and normal edges stay sharp, fireflies go and details stay, and the result does
// not depend on the thread count.
#include "rtpro/denoise/denoise.h"
#include "rtpro/core/error.h"
#include "noisy_fixture.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <string>

namespace rtpro {
namespace denoise_test {

using noisy_fixture::without_channel;

using noisy_fixture::NoisyOptions;
using noisy_fixture::PixelTruth;
using noisy_fixture::region_mean;
using noisy_fixture::region_mse;
using noisy_fixture::Rgb;

constexpr int kWidth = 72, kHeight = 56;  // not multiples of the 32-pixel tiles

PixelTruth flat(const Rgb& colour) {
  PixelTruth t;
  t.colour = colour;
  return t;
}

TEST(Denoise, FlatEmitterStaysFlat) {
  const Rgb emitted{17.0f, 12.0f, 4.0f};
  const Image noisy = noisy_fixture::noisy_render(kWidth, kHeight, [&](int, int) {
    PixelTruth t = flat(emitted);
    t.albedo = {0.78f, 0.78f, 0.78f};
    return t;
  });
  DenoiseReport report;
  const Image denoised = denoise(noisy, {}, &report);
  EXPECT_EQ(report.features, (std::vector<std::string>{"albedo", "normal", "depth"}));
  EXPECT_EQ(report.firefly_pixels, 0u);
  ASSERT_EQ(denoised.width, kWidth);
  ASSERT_EQ(denoised.height, kHeight);
  ASSERT_EQ(denoised.channels, (std::vector<std::string>{"R", "G", "B"}));
  for (int c = 0; c < 3; ++c) {
    // The noisy mean over all pixels is within about 0.2·emitted/sqrt(4032), 0.3%, of the truth.
    EXPECT_NEAR(region_mean(denoised, c, 0, 0, kWidth, kHeight), emitted[c], 0.01 * emitted[c]) << c;
    const double noisy_mse = region_mse(noisy, c, emitted[c], 0, 0, kWidth, kHeight);
    const double denoised_mse = region_mse(denoised, c, emitted[c], 0, 0, kWidth, kHeight);
    EXPECT_LT(denoised_mse, noisy_mse / 20.0) << c;
  }
}

// Edges: two regions side by side, x < kEdge and the rest, over kEdgeHeight rows. A pixel next to
// the edge has neighbours on its own side only along its column and away from the edge, so its
// column's mean keeps most of its noise: the check allows three standard deviations of that mean,
// plus 5% of the step for bleeding (a filter that ignored the edge would move it by about half the
// step).
constexpr int kEdge = 36, kEdgeHeight = 200;
constexpr float kEdgeNoise = 0.1f;  // relative

void expect_side_kept(const Image& denoised, int x, float truth, float step, int c) {
  const float tolerance = 0.05f * step + 3.0f * kEdgeNoise * truth / std::sqrt(static_cast<float>(kEdgeHeight));
  EXPECT_NEAR(region_mean(denoised, c, x, 0, x + 1, kEdgeHeight), truth, tolerance)
      << "column " << x << " channel " << c;
}

// Renders the edge whose every column's truth `column(x)` gives, and expects the denoised image to
// keep the level of each side at the edge and to cut every column's squared error by `error_cut`:
// both sides are smoothed, the columns at the edge too.
void expect_edge_kept_sharp(const std::function<PixelTruth(int x)>& column, double error_cut) {
  NoisyOptions options;
  options.relative_sigma = kEdgeNoise;
  const Image noisy = noisy_fixture::noisy_render(
      kWidth, kEdgeHeight, [&](int x, int) { return column(x); }, options);
  const Image denoised = denoise(noisy);
  for (int c = 0; c < 3; ++c) {
    const float left = column(kEdge - 1).colour[c], right = column(kEdge).colour[c];
    expect_side_kept(denoised, kEdge - 1, left, left - right, c);
    expect_side_kept(denoised, kEdge, right, left - right, c);
    for (const int x : {0, kEdge - 1, kEdge, kWidth - 1}) {
      const float truth = column(x).colour[c];
      EXPECT_LT(region_mse(denoised, c, truth, x, 0, x + 1, kEdgeHeight),
                region_mse(noisy, c, truth, x, 0, x + 1, kEdgeHeight) / error_cut)
          << "column " << x << " channel " << c;
    }
  }
}

TEST(Denoise, AlbedoEdgeStaysSharp) {
  const Rgb bright{0.8f, 0.6f, 0.5f}, dark{0.2f, 0.25f, 0.3f};
  constexpr float kLight = 1.5f;
  expect_edge_kept_sharp(
      [&](int x) {
        PixelTruth t;
        t.albedo = x < kEdge ? bright : dark;
        for (int c = 0; c < 3; ++c) t.colour[c] = kLight * t.albedo[c];
        return t;
      },
      5.0);
}

TEST(Denoise, NormalEdgeStaysSharp) {
  // One albedo; the left faces the light, the right is turned 60° away from it (half the light).
  const Rgb albedo{0.7f, 0.7f, 0.7f};
  const Rgb facing{0.0f, 0.0f, -1.0f}, turned{0.8660254f, 0.0f, -0.5f};
  constexpr float kLight = 2.0f;
  expect_edge_kept_sharp(
      [&](int x) {
        PixelTruth t;
        t.albedo = albedo;
        t.normal = x < kEdge ? facing : turned;
        const float shade = x < kEdge ? 1.0f : 0.5f;
        for (int c = 0; c < 3; ++c) t.colour[c] = kLight * shade * albedo[c];
        return t;
      },
      3.0);
}

// Neither darker nor brighter than the truth beyond what the noise allows, from very dark to
// bright, with noise that grows with the level (as Monte Carlo noise does) and with noise that
// does not.
TEST(Denoise, FlatRegionsKeepTheirLevel) {
  for (const float level : {0.002f, 0.05f, 1.0f, 40.0f}) {
    for (const bool relative : {true, false}) {
      NoisyOptions options;
      options.relative_sigma = relative ? 0.5f : 0.0f;
      options.absolute_sigma = relative ? 0.0f : 0.3f * level;
      options.seed = 7;
      const Image noisy = noisy_fixture::noisy_render(
          kWidth, kHeight,
          [&](int, int) {
            return flat({level, 0.5f * level, 0.25f * level});
          },
          options);
      DenoiseReport report;
      const Image denoised = denoise(noisy, {}, &report);
      EXPECT_EQ(report.firefly_pixels, 0u) << "level " << level;
      for (int c = 0; c < 3; ++c) {
        const double truth = level * (c == 0 ? 1.0 : c == 1 ? 0.5 : 0.25);
        // The noisy image's own mean is off by about sigma/sqrt(pixels): 0.8% of the level here.
        const double noisy_error = std::abs(region_mean(noisy, c, 0, 0, kWidth, kHeight) - truth);
        const double denoised_error = std::abs(region_mean(denoised, c, 0, 0, kWidth, kHeight) - truth);
        EXPECT_LT(denoised_error, noisy_error + 0.01 * truth) << "level " << level << " channel " << c;
      }
    }
  }
}

TEST(Denoise, WithoutFeaturesTheColourAloneGuides) {
  NoisyOptions options;
  options.features = false;
  const Image noisy = noisy_fixture::noisy_render(
      kWidth, kHeight,
      [](int, int) {
        return flat({1.0f, 0.5f, 0.2f});
      },
      options);
  DenoiseReport report;
  const Image denoised = denoise(noisy, {}, &report);
  EXPECT_TRUE(report.features.empty());
  for (int c = 0; c < 3; ++c) {
    const float truth = c == 0 ? 1.0f : c == 1 ? 0.5f : 0.2f;
    EXPECT_NEAR(region_mean(denoised, c, 0, 0, kWidth, kHeight), truth, 0.01 * truth);
    EXPECT_LT(region_mse(denoised, c, truth, 0, 0, kWidth, kHeight),
              region_mse(noisy, c, truth, 0, 0, kWidth, kHeight) / 10.0);
  }
}

// A few pixels a hundred times too bright in a noisy flat region: left out, not spread into
// blotches. With the threshold at 0 they are kept.
TEST(Denoise, FirefliesAreLeftOutUnlessKept) {
  constexpr float kLevel = 0.5f;
  Image noisy = noisy_fixture::noisy_render(kWidth, kHeight, [](int, int) { return flat({kLevel, kLevel, kLevel}); });
  const int fireflies[][2] = {{10, 10}, {40, 20}, {60, 45}, {25, 40}};
  for (const auto& f : fireflies)
    for (int c = 0; c < 3; ++c) noisy.at(f[0], f[1], c) = 100.0f * kLevel;
  DenoiseReport report;
  const Image denoised = denoise(noisy, {}, &report);
  EXPECT_EQ(report.firefly_pixels, 4u);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) ASSERT_LT(denoised.at(x, y, 0), 1.2f * kLevel) << x << "," << y;
  EXPECT_NEAR(region_mean(denoised, 0, 0, 0, kWidth, kHeight), kLevel, 0.01 * kLevel);

  DenoiseSettings keep;
  keep.firefly_threshold = 0.0f;
  const Image kept = denoise(noisy, keep, &report);
  EXPECT_EQ(report.firefly_pixels, 0u);
  EXPECT_GT(kept.at(40, 20, 0), 1.5f * kLevel);
}

// `image` with the layers of the renderer's own noise measure: half-buffers or a variance layer,
// for a render whose colour in columns x < noisy_columns had `sigma` of noise (relative, from the
// fixture's hash) and was exact elsewhere.
Image with_noise_measure(const Image& image, bool halves, int noisy_columns = 0, float sigma = 0.0f) {
  std::vector<std::string> channels = image.channels;
  for (const ChannelNames3* layer : halves ? std::vector<const ChannelNames3*>{&kHalfAChannels, &kHalfBChannels}
                                           : std::vector<const ChannelNames3*>{&kVarianceChannels})
    for (std::string_view name : *layer) channels.emplace_back(name);
  Image result(image.width, image.height, channels);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      int k = 0;
      for (; k < image.channel_count(); ++k) result.at(x, y, k) = image.at(x, y, k);
      for (int c = 0; c < 3; ++c) {
        const float colour = image.at(x, y, c);
        // Halves that average to the colour and differ by its noise.
        const float spread = x < noisy_columns ? sigma * colour * noisy_fixture::gaussian(x, y, c, 99) : 0.0f;
        if (halves) {
          result.at(x, y, k + c) = colour + spread;
          result.at(x, y, k + 3 + c) = colour - spread;
        } else {
          result.at(x, y, k + c) = x < noisy_columns ? sigma * sigma * colour * colour : 0.0f;
        }
      }
    }
  return result;
}

// A noise-free picture with a one-pixel highlight three times as bright as its surroundings and a
// thin darker line, beside a noisy band. From the colour alone the details look like noise (and
// the highlight like a firefly); with the renderer's measure of noise (half-buffers that agree
// there, or a variance of zero) they are details and stay exactly as they are.
TEST(Denoise, CleanDetailsStayWithTheRenderersNoiseMeasure) {
  constexpr int kNoisyColumns = 12;
  const Image picture = noisy_fixture::noisy_render(
      kWidth, kHeight,
      [](int x, int y) {
        const float level = (x == 40 && y == 20) ? 3.0f : (y == 40 ? 0.6f : 1.0f);
        PixelTruth t = flat({0.3f * level, 0.3f * level, 0.3f * level});
        return t;
      },
      NoisyOptions{0.0f});
  Image noisy_band = picture;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kNoisyColumns; ++x)
      for (int c = 0; c < 3; ++c) noisy_band.at(x, y, c) *= 1.0f + 0.2f * noisy_fixture::gaussian(x, y, c, 5);

  DenoiseReport report;
  const Image guessed = denoise(noisy_band, {}, &report);
  EXPECT_FALSE(report.used_measured_noise);
  EXPECT_EQ(report.firefly_pixels, 1u);
  EXPECT_LT(guessed.at(40, 20, 0), 0.5f);

  for (const bool halves : {true, false}) {
    const Image denoised = denoise(with_noise_measure(noisy_band, halves, kNoisyColumns, 0.2f), {}, &report);
    EXPECT_TRUE(report.used_measured_noise);
    // Half-buffers cannot tell a highlight from a firefly: two bright samples, one in each half,
    // look the same. The sample variance can.
    EXPECT_EQ(report.firefly_pixels, halves ? 1u : 0u);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 2 * kNoisyColumns; x < kWidth; ++x) {
        if (halves && x == 40 && y == 20) continue;
        EXPECT_NEAR(denoised.at(x, y, 0), picture.at(x, y, 0), 1e-4f * picture.at(x, y, 0)) << x << "," << y;
      }
  }
}

// A film of one sample per pixel writes that sample as both halves and a variance of zero: no
// measure of noise, and the result is the same as without them.
TEST(Denoise, HalvesOfOneSampleAreNoMeasure) {
  const Image noisy = noisy_fixture::noisy_render(kWidth, kHeight, [](int, int) { return flat({1.0f, 0.5f, 0.2f}); });
  const Image plain = denoise(noisy);
  for (const bool halves : {true, false}) {
    DenoiseReport report;
    const Image with_layers = denoise(with_noise_measure(noisy, halves), {}, &report);
    EXPECT_FALSE(report.used_measured_noise);
    EXPECT_EQ(std::memcmp(with_layers.data.data(), plain.data.data(), plain.data.size() * sizeof(float)), 0);
  }
}

Image denoised_with_threads(const Image& noisy, int threads) {
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  return denoise(noisy);
}

TEST(Denoise, SameBitsForAnyThreadCount) {
  // Something with detail: a gradient, a disc of another albedo and a slanted depth.
  const Image noisy = noisy_fixture::noisy_render(97, 70, [](int x, int y) {
    PixelTruth t;
    const bool disc = (x - 40) * (x - 40) + (y - 30) * (y - 30) < 400;
    t.albedo = disc ? Rgb{0.9f, 0.2f, 0.1f} : Rgb{0.5f, 0.5f, 0.5f};
    t.depth = 3.0f + 0.02f * x;
    for (int c = 0; c < 3; ++c) t.colour[c] = t.albedo[c] * (0.5f + 0.01f * y);
    return t;
  });
  const Image one = denoised_with_threads(noisy, 1);
  const Image two = denoised_with_threads(noisy, 2);
  ASSERT_EQ(one.data.size(), two.data.size());
  EXPECT_EQ(std::memcmp(one.data.data(), two.data.data(), one.data.size() * sizeof(float)), 0);
}

// The InputError denoise throws for `image`; records a failure if none is thrown.
std::string denoise_error(const Image& image, const DenoiseSettings& settings = {}) {
  try {
    denoise(image, settings);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

TEST(Denoise, RefusesIncompleteInputs) {
  const Image noisy = noisy_fixture::noisy_render(8, 8, [](int, int) { return flat({1.0f, 1.0f, 1.0f}); });
  EXPECT_NE(denoise_error(without_channel(noisy, "G")).find("R and B but not G"), std::string::npos);
  Image no_colour = noisy;
  for (std::string_view name : kColourChannels) no_colour = without_channel(no_colour, name);
  EXPECT_NE(denoise_error(no_colour).find("no R, G, B colour channels"), std::string::npos);
  EXPECT_NE(denoise_error(without_channel(noisy, "albedo.B")).find("albedo.R and albedo.G but not albedo.B"),
            std::string::npos);
  Image half_a_only = with_noise_measure(noisy, true);
  for (std::string_view name : kHalfBChannels) half_a_only = without_channel(half_a_only, name);
  EXPECT_NE(denoise_error(half_a_only).find("half_a but not half_b"), std::string::npos);
  Image short_data = noisy;
  short_data.data.pop_back();
  EXPECT_NE(denoise_error(short_data).find("pixel data"), std::string::npos);
  DenoiseSettings wide;
  wide.window_radius = 33;
  EXPECT_NE(denoise_error(noisy, wide).find("window radius"), std::string::npos);
}

TEST(Denoise, DenoisedImageKeepsTheNoisyColourAsALayer) {
  const Image noisy = noisy_fixture::noisy_render(20, 12, [](int, int) { return flat({1.0f, 2.0f, 3.0f}); });
  const Image denoised = denoise(noisy);
  const Image layered = with_denoised_colour(noisy, denoised);
  ASSERT_EQ(layered.channel_count(), noisy.channel_count() + 3);
  for (int c = 0; c < noisy.channel_count(); ++c) EXPECT_EQ(layered.channels[c], noisy.channels[c]);
  const int first_noisy = noisy.channel_count();
  for (int c = 0; c < 3; ++c) EXPECT_EQ(layered.channels[first_noisy + c], kNoisyChannels[c]);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 20; ++x)
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(layered.at(x, y, c), denoised.at(x, y, c));
        EXPECT_EQ(layered.at(x, y, first_noisy + c), noisy.at(x, y, c));
        EXPECT_EQ(layered.at(x, y, 3 + c), noisy.at(x, y, 3 + c));  // albedo kept
      }
  // Denoising the layered image again starts from the same noisy colour: the same result.
  const Image again = denoise(layered);
  EXPECT_EQ(std::memcmp(again.data.data(), denoised.data.data(), denoised.data.size() * sizeof(float)), 0);
  EXPECT_EQ(with_denoised_colour(layered, again).channel_count(), layered.channel_count());
}

}  // namespace denoise_test
}  // namespace rtpro
