#pragma once
// The denoiser's kernel: per pixel, a weighted least-squares fit of the colour over a window of
// neighbours, linear in the regressed features and the screen position; the fit's value at the
// pixel, multiplied by the albedo again, is the output. A neighbour's weight is e^-(its
// non-local-means colour distance + its feature distances + its firefly distance).
#include "denoise_buffers.h"
#include "rtpro/denoise/denoise.h"
#include "rtpro/image/image.h"

namespace rtpro {

// The border every plane of the buffers needs for these settings.
int regression_filter_pad(const DenoiseSettings& settings);

// The filtered colour, an RGB image of the buffers' size.
Image regression_filter(const DenoiseBuffers& buffers, const DenoiseSettings& settings);

}  // namespace rtpro
