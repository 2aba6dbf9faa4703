#pragma once
// A false-colour picture of where two images differ. Per pixel, the largest absolute channel
// difference divided by `full_scale` goes through a black -> blue -> red -> yellow -> white ramp
// (brightness rises with the error; white means full_scale or more). A full_scale of 0 means the
// largest finite difference in the image. Pixels where one image holds NaN or infinity and the
// other does not are magenta. `rtpro compare` passes its fail threshold as full_scale.
//
// The heat map's colours are display-referred by nature, so they are written to be seen exactly:
// PNG, JPEG and TIFF get them unchanged through the config's "Raw" view (the display's default
// view, e.g. an ACES tone curve, would shift them); EXR and other float formats get them decoded
// through the inverse sRGB curve, so that any viewer's usual scene-linear-to-sRGB display shows
// the same ramp. EXR files also keep an "error" channel with the raw per-pixel difference.
#include "rtpro/image/image.h"

#include <filesystem>

namespace rtpro {

// Channels R, G, B (the display-referred ramp colour) and "error". The images must have the same
// size and channel count.
Image diff_heat_map(const Image& reference, const Image& test, float full_scale);

// Throws like write_image; InputError when the chosen OpenColorIO config has no "Raw" view on its
// default display and the format needs one.
void write_diff_image(const std::filesystem::path& file, const Image& reference, const Image& test, float full_scale);

}  // namespace rtpro
