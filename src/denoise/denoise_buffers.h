#pragma once
// The denoiser's inputs, gathered from an Image's named channels into padded planes: the colour
// (divided by the albedo when there is one), its noise variance (from each pixel's neighbourhood,
// capped by the renderer's own measure when the image has half-buffers or a variance layer), the
// features, and which pixels are fireflies.
#include "padded_plane.h"
#include "rtpro/denoise/denoise.h"
#include "rtpro/image/image.h"

#include <array>
#include <vector>

namespace rtpro {

using PaddedRgb = std::array<PaddedPlane, 3>;

// The colour is divided by (albedo + this) before filtering and multiplied by it after: small
// enough that dark textures still come out flat, large enough that a black albedo (the
// background) does not divide by zero.
inline constexpr float kDemodulationFloor = 0.02f;

struct DenoiseBuffers {
  int width = 0;
  int height = 0;
  PaddedRgb colour;    // divided by (albedo + kDemodulationFloor) when there is an albedo
  PaddedRgb variance;  // of `colour`, per pixel
  // Feature planes: albedo R,G,B, normal X,Y,Z and inverse depth, those present.
  std::vector<PaddedPlane> features;
  int albedo_first = -1;  // index in `features` of albedo.R, or -1 when absent
  int normal_first = -1;
  int depth = -1;
  // |d(inverse depth)/dx| and /dy (the smaller one-sided difference, so a silhouette does not
  // count): how much the depth of a plane may change over an offset.
  PaddedPlane depth_slope_x, depth_slope_y;
  // Added to every distance to the pixel: 0, or large for a firefly (so it is left out of its
  // neighbours' sums and of its own).
  PaddedPlane firefly_distance;
  DenoiseReport report;
};

// Throws InputError for missing R,G,B, a layer present only in part (or half_a without half_b),
// or data that does not match the image's size. `pad` is the border every plane gets.
DenoiseBuffers gather_denoise_buffers(const Image& image, const DenoiseSettings& settings, int pad);

// The colour's albedo factor at a pixel: what the filtered colour is multiplied by again.
float demodulation_factor(const DenoiseBuffers& buffers, int x, int y, int channel);

}  // namespace rtpro
