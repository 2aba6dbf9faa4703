#include "display_encoding.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace rtpro {

namespace {

// The image's display codes, worked in chunks side by side: each chunk's pixels copied out as RGB
// (the caller's scene-linear image stays as it is), through the transform, and quantised, while
// they are in the cache.
template <typename Code>
std::vector<Code> display_codes(const Image& image, const DisplayTransform& transform) {
  constexpr std::size_t kChunkPixels = 4096;
  constexpr float top = std::numeric_limits<Code>::max();
  const std::size_t pixel_count = static_cast<std::size_t>(image.width) * image.height;
  const std::size_t stride = image.channels.size();
  const bool grey = stride < 3;
  std::vector<Code> codes(pixel_count * 3);
  const std::size_t chunks = (pixel_count + kChunkPixels - 1) / kChunkPixels;
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t chunk) {
    const std::size_t first = chunk * kChunkPixels;
    const std::size_t count = std::min(kChunkPixels, pixel_count - first);
    float rgb[3 * kChunkPixels];
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t c = 0; c < 3; ++c) rgb[3 * i + c] = image.data[(first + i) * stride + (grey ? 0 : c)];
    transform.apply(rgb, count);
    Code* out = codes.data() + 3 * first;
    for (std::size_t i = 0; i < 3 * count; ++i) {
      // Written so that NaN fails the first test and becomes 0 (black) rather than undefined
      // behaviour in the float-to-integer conversion; +inf becomes the top code.
      const float clamped = rgb[i] > 0.0f ? std::min(rgb[i], 1.0f) : 0.0f;
      // lround's half away from zero, for a value in [0, top]: in double, x + 0.5 is exact and
      // its truncation is the rounding (a call into libm per channel was 3% of a 1024² PNG's
      // process).
      out[i] = static_cast<Code>(static_cast<double>(clamped * top) + 0.5);
    }
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
  return display_codes<std::uint8_t>(image, transform);
}

std::vector<std::uint16_t> encode_for_display_16bit(const Image& image, const DisplayTransform& transform) {
  return display_codes<std::uint16_t>(image, transform);
}

}  // namespace rtpro
