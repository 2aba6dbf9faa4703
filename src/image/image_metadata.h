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

// Throws RuntimeError naming `file` when the image is empty or its data does not match its size.
void require_writable_image(const std::filesystem::path& file, const Image& image);

}  // namespace rtpro
