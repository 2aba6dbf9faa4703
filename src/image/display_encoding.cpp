#include "display_encoding.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace rtpro {

namespace {

std::vector<float> display_rgb(const Image& image, const DisplayTransform& transform) {
  const std::size_t pixel_count = static_cast<std::size_t>(image.width) * image.height;
  const std::size_t stride = image.channels.size();
  const bool grey = stride < 3;
  std::vector<float> rgb(pixel_count * 3);
  for (std::size_t pixel = 0; pixel < pixel_count; ++pixel)
    for (std::size_t c = 0; c < 3; ++c) rgb[pixel * 3 + c] = image.data[pixel * stride + (grey ? 0 : c)];
  // Applied to a copy: the caller's scene-linear image stays as it is.
  transform.apply(rgb.data(), pixel_count);
  return rgb;
}

template <typename Code>
std::vector<Code> quantise(const std::vector<float>& rgb) {
  constexpr float top = std::numeric_limits<Code>::max();
  std::vector<Code> codes(rgb.size());
  std::transform(rgb.begin(), rgb.end(), codes.begin(), [](float value) {
    // Written so that NaN fails the first test and becomes 0 (black) rather than undefined
    // behaviour in the float-to-integer conversion; +inf becomes the top code.
    const float clamped = value > 0.0f ? std::min(value, 1.0f) : 0.0f;
    return static_cast<Code>(std::lround(clamped * top));
  });
  return codes;
}

}  // namespace

DisplayEncoding display_encoding(const ImageWriteOptions& options) {
  const ColorConfig config = ColorConfig::load(options.ocio_config);
  DisplayTransform transform = config.display_transform(options.display, options.view);
  std::string display_lowercase = transform.display();
  std::transform(display_lowercase.begin(), display_lowercase.end(), display_lowercase.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  std::string description = "rtpro image, display-referred: OpenColorIO display \"" + transform.display() +
                            "\", view \"" + transform.view() + "\" (config: " + config.source() + ")";
  return {std::move(transform), std::move(description), display_lowercase.find("srgb") != std::string::npos};
}

std::vector<std::uint8_t> encode_for_display_8bit(const Image& image, const DisplayTransform& transform) {
  return quantise<std::uint8_t>(display_rgb(image, transform));
}

std::vector<std::uint16_t> encode_for_display_16bit(const Image& image, const DisplayTransform& transform) {
  return quantise<std::uint16_t>(display_rgb(image, transform));
}

}  // namespace rtpro
