#pragma once
// The outputs rtpro writes without OpenImageIO: EXR through OpenEXR (exr_output.h) and PNG through
// libpng (png_output.h). The executable's image layer and the OpenImageIO-linked module both send
// these files here first, so the list lives in one place.
#include "rtpro/image/image.h"
#include "rtpro/image/image_io.h"

#include <filesystem>

namespace rtpro {

bool written_without_openimageio(const std::filesystem::path& file);

// Writes `file` and returns true when its format is one of those; otherwise writes nothing and
// returns false. Throws as write_image does.
bool write_without_openimageio(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options);

}  // namespace rtpro
