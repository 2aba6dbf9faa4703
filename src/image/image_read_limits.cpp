#include "image_read_limits.h"

#include "rtpro/core/memory_budget.h"

#include <algorithm>

namespace rtpro {

namespace {

constexpr std::uint64_t kMaxReadValues = std::uint64_t{1} << 30;
constexpr std::uint64_t kLibraryRows = 256;

}  // namespace

std::uint64_t image_read_bytes(std::uint64_t width, std::uint64_t height, std::uint64_t channels,
                               std::uint64_t tile_pixels, std::uint64_t extra_bytes_per_pixel) {
  const std::uint64_t pixels = saturating_multiply(width, height);
  const std::uint64_t read_pixels =
      std::max({pixels, saturating_multiply(width, kLibraryRows), saturating_multiply(tile_pixels, 2)});
  return saturating_add(saturating_multiply(saturating_multiply(read_pixels, channels), sizeof(float)),
                        saturating_multiply(pixels, extra_bytes_per_pixel));
}

bool image_read_allowed(std::uint64_t width, std::uint64_t height, std::uint64_t channels, std::uint64_t tile_pixels,
                        std::uint64_t extra_bytes_per_pixel, std::uint64_t max_bytes) {
  const std::uint64_t pixels = saturating_multiply(width, height);
  return pixels <= kMaxReadValues && saturating_multiply(pixels, channels) <= kMaxReadValues &&
         image_read_bytes(width, height, channels, tile_pixels, extra_bytes_per_pixel) <= max_bytes;
}

std::size_t image_read_band_rows(std::size_t row_values) {
  constexpr std::size_t kBandValues = std::size_t{1} << 20;
  return std::max<std::size_t>(kBandValues / std::max<std::size_t>(row_values, 1), 64);
}

}  // namespace rtpro
