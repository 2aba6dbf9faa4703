#include "non_finite_pixels.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace rtpro::cli {

std::optional<std::string> non_finite_pixels_warning(const Image& image) {
  const auto channels = static_cast<std::size_t>(std::max(image.channel_count(), 1));
  const std::size_t colour = std::min<std::size_t>(channels, 3);
  std::size_t count = 0, first = 0;
  for (std::size_t pixel = 0; pixel * channels < image.data.size(); ++pixel) {
    const float* value = &image.data[pixel * channels];
    if (std::all_of(value, value + colour, [](float v) { return std::isfinite(v); })) continue;
    if (count++ == 0) first = pixel;
  }
  if (count == 0) return std::nullopt;
  const auto width = static_cast<std::size_t>(std::max(image.width, 1));
  return std::to_string(count) + (count == 1 ? " pixel is" : " pixels are") +
         " not finite (infinite or NaN; the first at x " + std::to_string(first % width) + ", y " +
         std::to_string(first / width) + ")";
}

}  // namespace rtpro::cli
