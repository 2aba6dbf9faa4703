#pragma once
// rtpro's own denoiser (Open Image Denoise is not packaged in Debian 12): feature-guided
// first-order regression in the manner of NFOR (Bitterli et al. 2016). Each pixel's colour, over
// a window of neighbours, is fitted as a linear function of the features (normal, inverse depth,
// screen position) and the fit's value at the pixel is the output. Neighbours are weighted by
// non-local-means patch distances (Rousselle et al. 2012) in the colour and by their albedo,
// normal and depth distances; the colour is divided by the albedo first (and multiplied back
// after), so textures are not smoothed away; fireflies (a pixel far brighter than its
// neighbourhood's noise allows) are left out. docs/usage.md, "Denoising", has the measurements
// behind each choice.
//
// The denoiser works on an Image's named channels, so the renderer calls it on its film in memory
// and `rtpro denoise` on an EXR file read back: the same pixels give the same bits. Every output
// pixel is computed from its own neighbourhood only, so the result is the same, bit for bit, for
// any number of threads.
#include "rtpro/image/image.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro {

using ChannelNames3 = std::array<std::string_view, 3>;

// What the denoiser reads: the pixel's colour (the mean of its samples) and, optionally, the
// features of render --aov albedo,normal,depth. Without features the colour alone guides it,
// which blurs more detail.
inline constexpr ChannelNames3 kColourChannels{"R", "G", "B"};
inline constexpr ChannelNames3 kAlbedoChannels{"albedo.R", "albedo.G", "albedo.B"};
inline constexpr ChannelNames3 kNormalChannels{"N.X", "N.Y", "N.Z"};
inline constexpr std::string_view kDepthChannel = "depth.Z";

// Where a denoised image keeps the noisy colour it came from. An image that holds these (the
// output of an earlier denoise) is denoised again from them, not from its denoised R,G,B.
inline constexpr ChannelNames3 kNoisyChannels{"noisy.R", "noisy.G", "noisy.B"};

// Optional: the renderer's own measure of each pixel's noise, from the film's half-buffers (the
// mean of the pixel's even-indexed samples, 0, 2, 4, ..., and of its odd-indexed ones) or the
// sample variance of the pixel's mean (the variance layer, used when both are present). The
// denoiser estimates the noise from each pixel's neighbourhood, which takes fine detail for noise;
// with these it knows a detail that every sample sees (a highlight, a thin line in a clean area)
// from noise and from a firefly. Filtering the halves against each other (NFOR's cross filtering)
// measured a higher error than this (docs/usage.md, "Denoising").
inline constexpr ChannelNames3 kHalfAChannels{"half_a.R", "half_a.G", "half_a.B"};
inline constexpr ChannelNames3 kHalfBChannels{"half_b.R", "half_b.G", "half_b.B"};
inline constexpr ChannelNames3 kVarianceChannels{"variance.R", "variance.G", "variance.B"};

struct DenoiseSettings {
  // The regression window is (2·radius+1)² pixels: 15×15 by default.
  int window_radius = 7;
  // Colour distances compare (2·patch_radius+1)² patches: 5×5 by default.
  int patch_radius = 2;
  // How different two patches may be, in standard deviations of their noise, before a neighbour
  // loses its weight: larger smooths more (Rousselle et al. 2012 call it k).
  float colour_tolerance = 0.5f;
  // How much a feature may differ before a neighbour loses its weight: albedo and normal in their
  // own units (per component), inverse depth relative to what a plane could change.
  float albedo_tolerance = 0.1f;
  float normal_tolerance = 0.4f;
  float depth_tolerance = 1.0f;
  // A pixel counts as a firefly, and is left out, when its squared difference from the median of
  // its eight neighbours exceeds this many times what the neighbourhood's noise explains (in
  // noise-free surroundings: when it is 2.4 times as bright as that median); 0 keeps every pixel. Gaussian noise goes past
  // it far less than once in a billion pixels; a firefly, by hundreds.
  float firefly_threshold = 32.0f;
};

// What the denoiser found in the image and did.
struct DenoiseReport {
  // Which of albedo, normal and depth the image held (each is used when present).
  std::vector<std::string> features;
  // Whether the image held half-buffers or a variance layer (the renderer's measure of noise).
  bool used_measured_noise = false;
  // Pixels left out as fireflies (their energy is lost: a bias the error measure favours).
  std::size_t firefly_pixels = 0;
};

// The denoised colour of `image` (an Image with R, G, B): an RGB image of the same size. Throws
// InputError when R, G or B is missing, when a layer is present only in part (albedo.R without
// albedo.B, half_a without half_b), when the pixel data does not match the image's size, or for
// settings out of
// range (window_radius 1 to 32, patch_radius 0 to 8, tolerances 0.001 to 1000, threshold >= 0).
Image denoise(const Image& image, const DenoiseSettings& settings = {}, DenoiseReport* report = nullptr);

// What `rtpro denoise` holds at its peak for a width × height image of `channels` channels,
// estimated from the file's header before anything is read: the image's floats, the denoiser's
// padded planes (colour, variance, seven features, two depth slopes, fireflies), its RGB output
// and the output file's layers beside the noisy image (a 1.6 MB EXR of 16384x16384 pixels holds
// 30 GiB of them). Deliberately on the high side.
std::uint64_t denoise_peak_bytes(std::uint64_t width, std::uint64_t height, std::uint64_t channels,
                                 const DenoiseSettings& settings = {});

// `noisy` with its R,G,B replaced by `denoised` (an RGB image of the same size) and the noisy
// colour kept as noisy.R/G/B (or kept as it was, when `noisy` already holds those); every other
// channel stays.
Image with_denoised_colour(const Image& noisy, const Image& denoised);

}  // namespace rtpro
