#pragma once
// Where and in what shape `rtpro render` writes its image: which outputs hold the AOV layers, the
// file an interrupted render writes instead, and the window --crop keeps.
#include "rtpro/image/image.h"
#include "rtpro/render/tiles.h"

#include <filesystem>

namespace rtpro::cli {

bool holds_layers(const std::filesystem::path& output);
std::filesystem::path partial_path(const std::filesystem::path& output);
Image crop_image(const Image& full, const PixelRegion& r);

}  // namespace rtpro::cli
