#pragma once
// Display-referred integer pixels for 8- and 16-bit formats: the image's first three channels
// (taken as R, G, B; a one- or two-channel image is shown as grey from its first channel) through
// an OpenColorIO display/view transform, clamped to [0, 1] and rounded to the nearest code value.
#include "rtpro/image/color_config.h"
#include "rtpro/image/image.h"

#include <cstdint>
#include <vector>

namespace rtpro {

std::vector<std::uint8_t> encode_for_display_8bit(const Image& image, const DisplayTransform& transform);
std::vector<std::uint16_t> encode_for_display_16bit(const Image& image, const DisplayTransform& transform);

}  // namespace rtpro
