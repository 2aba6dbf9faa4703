#pragma once
// EXR files written without OpenImageIO. Writing an EXR is how nearly every render ends, and
// OpenImageIO brings some 260 shared libraries with it (0.13 s of CPU to load, taken from the
// render's own threads while it runs; third_party_notes/openexr.md). The file is what OpenImageIO
// wrote for the same image: scanlines of 32-bit floats, ZIP compression, Rec.709 chromaticities,
// and the metadata under the names OpenImageIO's EXR reader maps back to its own (comments for
// ImageDescription, capDate for DateTime). OpenEXR writes the header; the chunks are compressed by
// libdeflate (exr_zip_block.h) on the threads the render may use, 2.7-3.1x faster than OpenEXR's zlib.
#include "rtpro/image/image.h"
#include "rtpro/image/image_io.h"

#include <filesystem>
#include <string>

namespace rtpro {

// .exr, and OpenImageIO's other names for the same format (.sxr, .mxr), in any case.
bool is_exr_file(const std::filesystem::path& file);

// The whole file in memory: every channel of `image` as 32-bit floats. Throws RuntimeError
// naming `file` (used in messages only) when OpenEXR refuses the image.
std::string encode_exr(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options);

// encode_exr, written by the atomic file writer. Throws as write_image does.
void write_exr(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options);

}  // namespace rtpro
