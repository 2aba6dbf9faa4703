#pragma once
// PNG files written without OpenImageIO, through libpng, as EXR files are through OpenEXR
// (exr_output.h): a render that writes a PNG then never loads OpenImageIO's 260 libraries, whose
// 0.13 s of CPU a two-thread render would lose while it runs (third_party_notes/libpng.md). The
// file is what OpenImageIO 2.4's PNG writer made of the same image: 8-bit RGB through the display
// transform, the sRGB chunk (with gAMA and cHRM) for an sRGB display, a zero oFFs, DateTime as
// tIME and every other entry of the metadata as a tEXt chunk (ImageDescription as Description),
// zlib level 6 with libpng's own choice of row filters.
#include "rtpro/image/image.h"
#include "rtpro/image/image_io.h"

#include <filesystem>
#include <string>

namespace rtpro {

// .png, in any case.
bool is_png_file(const std::filesystem::path& file);

// The whole file in memory. Throws InputError for an unknown display or view, RuntimeError naming
// `file` (used in messages only) when the image is inconsistent or libpng refuses it.
std::string encode_png(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options);

// encode_png, written by the atomic file writer. Throws as write_image does.
void write_png(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options);

}  // namespace rtpro
