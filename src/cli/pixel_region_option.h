#pragma once
// `--region x0,y0,x1,y1`: the window of the image to render, in pixels (x1 and y1 exclusive).
#include "rtpro/render/tiles.h"

#include <optional>
#include <string>

namespace rtpro::cli {

// None for an empty text; an InputError unless it is four integers.
std::optional<PixelRegion> parse_region(const std::string& text);

// Before the scene is built: a region outside the image would only be refused after the BVH.
void check_region_fits(const std::optional<PixelRegion>& region, const std::string& text, int width, int height);

}  // namespace rtpro::cli
