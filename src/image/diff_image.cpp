#include "rtpro/image/diff_image.h"

#include "rtpro/core/error.h"
#include "rtpro/image/image_compare.h"
#include "rtpro/image/image_io.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace rtpro {

namespace {

using Rgb = std::array<float, 3>;

constexpr std::array<Rgb, 5> kRamp = {{{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}}};
constexpr Rgb kNonFiniteMismatch = {1, 0, 1};

Rgb ramp_colour(float error, float full_scale) {
  const float scaled = full_scale > 0.0f ? error / full_scale : 0.0f;  // all black when nothing differs
  const float position = std::clamp(scaled, 0.0f, 1.0f) * float(kRamp.size() - 1);
  const std::size_t lower = std::min(static_cast<std::size_t>(position), kRamp.size() - 2);
  const float blend = position - float(lower);
  Rgb colour;
  for (std::size_t c = 0; c < 3; ++c) colour[c] = kRamp[lower][c] + blend * (kRamp[lower + 1][c] - kRamp[lower][c]);
  return colour;
}

// Infinite where one image is NaN or infinite and the other is not the same value.
float pixel_error(const Image& reference, const Image& test, int x, int y) {
  float error = 0.0f;
  for (int c = 0; c < reference.channel_count(); ++c) {
    const float a = reference.at(x, y, c);
    const float b = test.at(x, y, c);
    if (std::isfinite(a) && std::isfinite(b)) error = std::max(error, std::abs(a - b));
    else if (!same_non_finite(a, b)) return INFINITY;
  }
  return error;
}

float srgb_to_linear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

Image diff_heat_map(const Image& reference, const Image& test, float full_scale) {
  if (reference.width != test.width || reference.height != test.height ||
      reference.channel_count() != test.channel_count())
    throw InputError("a diff image needs two images of the same size and channel count");
  Image heat_map(reference.width, reference.height, {"R", "G", "B", "error"});
  float largest_finite_error = 0.0f;
  for (int y = 0; y < heat_map.height; ++y)
    for (int x = 0; x < heat_map.width; ++x) {
      const float error = pixel_error(reference, test, x, y);
      heat_map.at(x, y, 3) = error;
      if (std::isfinite(error)) largest_finite_error = std::max(largest_finite_error, error);
    }
  const float scale = full_scale > 0.0f ? full_scale : largest_finite_error;
  for (int y = 0; y < heat_map.height; ++y)
    for (int x = 0; x < heat_map.width; ++x) {
      const float error = heat_map.at(x, y, 3);
      const Rgb colour = std::isinf(error) ? kNonFiniteMismatch : ramp_colour(error, scale);
      for (int c = 0; c < 3; ++c) heat_map.at(x, y, c) = colour[c];
    }
  return heat_map;
}

void write_diff_image(const std::filesystem::path& file, const Image& reference, const Image& test, float full_scale) {
  Image heat_map = diff_heat_map(reference, test, full_scale);
  ImageWriteOptions options;
  std::ostringstream description;
  description << "rtpro compare heat map: largest channel difference per pixel, black 0 to white >= ";
  if (full_scale > 0.0f) description << full_scale;
  else description << "the largest difference";
  description << "; magenta: NaN or infinity in one image only";
  options.metadata = {{"ImageDescription", description.str()}};
  if (writes_scene_linear(file)) {
    for (int y = 0; y < heat_map.height; ++y)
      for (int x = 0; x < heat_map.width; ++x)
        for (int c = 0; c < 3; ++c) heat_map.at(x, y, c) = srgb_to_linear(heat_map.at(x, y, c));
  } else {
    options.view = "Raw";
  }
  write_image(file, heat_map, options);
}

}  // namespace rtpro
