#include "pixel_region_option.h"

#include "rtpro/core/error.h"

#include <cstdio>

namespace rtpro::cli {

std::optional<PixelRegion> parse_region(const std::string& text) {
  if (text.empty()) return std::nullopt;
  PixelRegion r;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &r.x0, &r.y0, &r.x1, &r.y1, &extra) != 4)
    throw InputError("--region '" + text + "': expected x0,y0,x1,y1 in pixels (x1 and y1 exclusive)");
  return r;
}

void check_region_fits(const std::optional<PixelRegion>& region, const std::string& text, int width, int height) {
  if (!region) return;
  if (region->x0 < 0 || region->y0 < 0 || region->x1 > width || region->y1 > height || region->width() <= 0 ||
      region->height() <= 0)
    throw InputError("--region " + text + ": not a non-empty window inside the " + std::to_string(width) + "x" +
                     std::to_string(height) + " image (x0,y0,x1,y1 with x1, y1 exclusive)");
}

}  // namespace rtpro::cli
