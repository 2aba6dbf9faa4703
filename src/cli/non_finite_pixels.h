#pragma once
// The last look at an image before it is written: pixels that are infinite or NaN (a radiance
// beyond 32-bit floats, summed) are never written without a word.
#include "rtpro/image/image.h"

#include <optional>
#include <string>

namespace rtpro::cli {

// "3 pixels are not finite (infinite or NaN; the first at x 4, y 0)", or nothing when every value of the colour channels is finite.
std::optional<std::string> non_finite_pixels_warning(const Image& image);

}  // namespace rtpro::cli
