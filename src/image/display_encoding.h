#pragma once
// Display-referred integer pixels for 8- and 16-bit formats: the image's first three channels
// (taken as R, G, B; a one- or two-channel image is shown as grey from its first channel) through
// an OpenColorIO display/view transform, clamped to [0, 1] and rounded to the nearest code value.
#include "rtpro/image/color_config.h"
#include "rtpro/image/image.h"
#include "rtpro/image/image_io.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtpro {

// The display/view transform a display-referred file is written through (options' config,
// display and view, each defaulted as ColorConfig does), and what the file says of it.
struct DisplayEncoding {
  DisplayTransform transform;
  std::string description;  // the file's ImageDescription: display, view and config
  // The display is an sRGB one, so the file may carry its format's sRGB tag; other displays'
  // encodings have no such tag, and untagged files are read as sRGB anyway.
  bool srgb = false;
};

// Throws InputError for an unreadable config or an unknown display or view.
DisplayEncoding display_encoding(const ImageWriteOptions& options);

std::vector<std::uint8_t> encode_for_display_8bit(const Image& image, const DisplayTransform& transform);
std::vector<std::uint16_t> encode_for_display_16bit(const Image& image, const DisplayTransform& transform);

}  // namespace rtpro
