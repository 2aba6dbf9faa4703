#include "rtpro/denoise/denoise.h"

#include "denoise_buffers.h"
#include "regression_filter.h"
#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>

namespace rtpro {

namespace {

void check_settings(const DenoiseSettings& s) {
  if (s.window_radius < 1 || s.window_radius > 32)
    throw InputError("the denoiser's window radius must be 1 to 32, got " + std::to_string(s.window_radius));
  if (s.patch_radius < 0 || s.patch_radius > 8)
    throw InputError("the denoiser's patch radius must be 0 to 8, got " + std::to_string(s.patch_radius));
  for (const float tolerance : {s.colour_tolerance, s.albedo_tolerance, s.normal_tolerance, s.depth_tolerance})
    if (!(tolerance >= 1e-3f && tolerance <= 1e3f))
      throw InputError("the denoiser's tolerances must be 0.001 to 1000, got " + std::to_string(tolerance));
  if (!(s.firefly_threshold >= 0.0f) || !std::isfinite(s.firefly_threshold))
    throw InputError("the denoiser's firefly threshold must be a number >= 0");
}

int channel_of(const Image& image, std::string_view name) {
  const auto found = std::find(image.channels.begin(), image.channels.end(), name);
  return found == image.channels.end() ? -1 : static_cast<int>(found - image.channels.begin());
}

}  // namespace

Image denoise(const Image& image, const DenoiseSettings& settings, DenoiseReport* report) {
  check_settings(settings);
  const DenoiseBuffers buffers = gather_denoise_buffers(image, settings, regression_filter_pad(settings));
  if (report) *report = buffers.report;
  return regression_filter(buffers, settings);
}

std::uint64_t denoise_peak_bytes(std::uint64_t width, std::uint64_t height, std::uint64_t channels,
                                 const DenoiseSettings& settings) {
  constexpr std::uint64_t kPlanes = 3 + 3 + 7 + 2 + 1;  // DenoiseBuffers
  const auto pad = static_cast<std::uint64_t>(std::max(regression_filter_pad(settings), 0));
  const std::uint64_t padded_pixels =
      saturating_multiply(saturating_add(width, 2 * pad), saturating_add(height, 2 * pad));
  const std::uint64_t pixels = saturating_multiply(width, height);
  // The noisy image and the denoised RGB, with either the planes or the merged layers (the noisy
  // channels and three more) beside them, whichever is larger.
  const std::uint64_t images = saturating_multiply(pixels, saturating_add(channels, 3));
  const std::uint64_t planes = saturating_multiply(padded_pixels, kPlanes);
  const std::uint64_t merged = saturating_multiply(pixels, saturating_add(channels, 3));
  return saturating_multiply(saturating_add(images, std::max(planes, merged)), sizeof(float));
}

Image with_denoised_colour(const Image& noisy, const Image& denoised) {
  if (denoised.width != noisy.width || denoised.height != noisy.height || denoised.channel_count() != 3)
    throw InputError("the denoised image does not match the noisy one");
  if (noisy.data.size() !=
      static_cast<std::size_t>(noisy.width) * static_cast<std::size_t>(noisy.height) * noisy.channels.size())
    throw InputError("the image's pixel data does not match its size");
  int colour[3], kept[3];
  for (int c = 0; c < 3; ++c) {
    colour[c] = channel_of(noisy, kColourChannels[c]);
    kept[c] = channel_of(noisy, kNoisyChannels[c]);
    if (colour[c] < 0) throw InputError("the image has no " + std::string(kColourChannels[c]) + " channel");
  }
  const bool has_noisy = kept[0] >= 0 && kept[1] >= 0 && kept[2] >= 0;
  std::vector<std::string> channels = noisy.channels;
  if (!has_noisy)
    for (int c = 0; c < 3; ++c) {
      kept[c] = static_cast<int>(channels.size());
      channels.emplace_back(kNoisyChannels[c]);
    }
  Image result(noisy.width, noisy.height, std::move(channels));
  const std::size_t in_stride = noisy.channels.size(), out_stride = result.channels.size();
  const std::size_t pixels = static_cast<std::size_t>(noisy.width) * static_cast<std::size_t>(noisy.height);
  for (std::size_t p = 0; p < pixels; ++p) {
    const float* in = noisy.data.data() + p * in_stride;
    float* out = result.data.data() + p * out_stride;
    std::copy(in, in + in_stride, out);
    for (int c = 0; c < 3; ++c) {
      if (!has_noisy) out[kept[c]] = in[colour[c]];
      out[colour[c]] = denoised.data[p * 3 + c];
    }
  }
  return result;
}

}  // namespace rtpro
