#pragma once
// Synthetic renders with known answers for the denoiser's tests: a noiseless picture with its
// features, and noise from a deterministic hash.
#include "rtpro/denoise/denoise.h"
#include "rtpro/image/image.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro::noisy_fixture {

using Rgb = std::array<float, 3>;

// What one pixel truly is.
struct PixelTruth {
  Rgb colour{0.0f, 0.0f, 0.0f};
  Rgb albedo{0.5f, 0.5f, 0.5f};
  Rgb normal{0.0f, 0.0f, -1.0f};
  float depth = 4.0f;
};

inline std::uint32_t mix(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// A standard normal variate (approximately: the sum of four uniforms, scaled to unit variance),
// a pure function of its arguments.
inline float gaussian(int x, int y, int channel, std::uint32_t stream) {
  std::uint32_t h = mix(stream * 0x9e3779b9u ^
                        mix(static_cast<std::uint32_t>(x) * 73856093u ^ static_cast<std::uint32_t>(y) * 19349663u ^
                            static_cast<std::uint32_t>(channel) * 83492791u));
  float sum = 0.0f;
  for (int i = 0; i < 4; ++i) {
    h = mix(h + 0x632be5abu);
    sum += static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
  }
  return (sum - 2.0f) * std::sqrt(3.0f);
}

struct NoisyOptions {
  float relative_sigma = 0.2f;  // the full mean's noise, per channel, relative to its value
  float absolute_sigma = 0.0f;  // plus this
  bool features = true;         // write albedo, N and depth
  std::uint32_t seed = 1;
};

// The channels render (and the film's half-buffers) would write for `truth`, with noise.
template <typename Truth>
Image noisy_render(int width, int height, Truth&& truth, const NoisyOptions& o = {}) {
  std::vector<std::string> channels{"R", "G", "B"};
  if (o.features) {
    for (const auto* layer : {&kAlbedoChannels, &kNormalChannels})
      for (std::string_view name : *layer) channels.emplace_back(name);
    channels.emplace_back(kDepthChannel);
  }
  Image image(width, height, channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const PixelTruth t = truth(x, y);
      for (int k = 0; k < 3; ++k) {
        const float sigma = o.relative_sigma * t.colour[k] + o.absolute_sigma;
        image.at(x, y, k) = t.colour[k] + sigma * gaussian(x, y, k, o.seed);
      }
      int c = 3;
      if (o.features) {
        for (int k = 0; k < 3; ++k) image.at(x, y, c++) = t.albedo[k];
        for (int k = 0; k < 3; ++k) image.at(x, y, c++) = t.normal[k];
        image.at(x, y, c++) = t.depth;
      }
    }
  return image;
}

// The mean of channel `c` over the pixels x0 <= x < x1, y0 <= y < y1.
inline double region_mean(const Image& image, int c, int x0, int y0, int x1, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) sum += image.at(x, y, c);
  return sum / (static_cast<double>(x1 - x0) * (y1 - y0));
}

// The mean squared difference of channel `c` from `value` over a region.
inline double region_mse(const Image& image, int c, float value, int x0, int y0, int x1, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) sum += (image.at(x, y, c) - value) * (image.at(x, y, c) - value);
  return sum / (static_cast<double>(x1 - x0) * (y1 - y0));
}

// `image` without its channel `name` (every other channel as it was), for inputs with a layer torn.
inline Image without_channel(const Image& image, std::string_view name) {
  Image result(image.width, image.height, {});
  std::vector<int> kept;
  for (int c = 0; c < image.channel_count(); ++c)
    if (image.channels[c] != name) {
      kept.push_back(c);
      result.channels.push_back(image.channels[c]);
    }
  result.data.clear();
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c : kept) result.data.push_back(image.at(x, y, c));
  return result;
}

}  // namespace rtpro::noisy_fixture
