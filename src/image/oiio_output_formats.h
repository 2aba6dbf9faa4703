#pragma once
// The output names OpenImageIO can write: lowercase file extensions without the dot, and format
// names, sorted. Generated at build time by asking the installed OpenImageIO
// (generate_oiio_output_formats.cpp), so checking an output name does not need to load it.
#include <span>
#include <string_view>

namespace rtpro {

extern const std::span<const std::string_view> kOiioOutputExtensions;

}  // namespace rtpro
