#pragma once
// What every image rtpro writes says about itself, and the checks before any image is written:
// shared by the OpenEXR writer and the OpenImageIO writers.
#include "rtpro/image/image.h"
#include "rtpro/image/image_io.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace rtpro {

// Software, ImageDescription (`description`) and DateTime in OpenImageIO's standard names, then
// the caller's entries (options.metadata), each replacing an entry of the same name.
std::vector<std::pair<std::string, std::string>> image_metadata(std::string description,
                                                                const ImageWriteOptions& options);

// What a scene-linear file (EXR and the other float formats) says of its colour: Rec.709 primaries
// and the D65 white point as x, y pairs (red, green, blue, white) for the chromaticities attribute,
// and image_metadata's entries with rtpro:colorspace among the defaults.
inline constexpr float kRec709Chromaticities[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
std::vector<std::pair<std::string, std::string>> scene_linear_metadata(const ImageWriteOptions& options);

// Throws RuntimeError naming `file` when the image is empty or its data does not match its size.
void require_writable_image(const std::filesystem::path& file, const Image& image);

}  // namespace rtpro
