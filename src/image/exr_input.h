#pragma once
// EXR read without OpenImageIO, through OpenEXR (which the EXR writer links already): an
// environment map or a compared render needs none of OpenImageIO's ~260 libraries, whose loading
// took half of a small HDRI-lit render (lookdev.yaml at 64x48: 0.35 of 0.7 s, and 135 of its
// 151 MB). Only the images OpenImageIO would return unchanged are read here: the first part's
// level 0, a data window of R, G, B and optionally A, each channel half or float at full
// resolution. The values are OpenImageIO's bit for bit (half to float is exact either way), the
// channels in its order. Anything else, and any file OpenEXR fails on, is left to OpenImageIO,
// whose reader then says what is wrong with it.
#include "rtpro/image/image.h"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace rtpro {

// Whether `file` starts with OpenEXR's magic number (its name is not looked at).
bool has_exr_signature(const std::filesystem::path& file);

// The image, or nothing when the file is not an EXR of that kind, would not fit in `max_bytes` of
// floats (0: default_memory_budget()), or OpenEXR fails on it. Throws InputError as read_image
// does when the file is missing or not a regular file, or its header is malformed
// (image_file_check.h, image_header_check.h): the same checks, before OpenEXR opens it.
std::optional<Image> read_exr_without_openimageio(const std::filesystem::path& file, std::uint64_t max_bytes);

}  // namespace rtpro
