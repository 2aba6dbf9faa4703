#pragma once
// A guard in front of OpenEXR: Debian's OpenEXR 3.1 allocates (and clears) whatever size an
// attribute claims before it reads the value, so a 700-byte EXR claiming a 2 GB string attribute
// costs 2 GB and seconds before failing (found by fuzzing `rtpro compare`'s image inputs). This
// walks the header(s) itself and refuses any attribute larger than the bytes left in the file.
#include <filesystem>

namespace rtpro {

// Whether the file starts with the OpenEXR magic number (OpenImageIO reads it as EXR whatever
// its extension says).
bool looks_like_exr(const std::filesystem::path& file);

// Throws InputError naming the attribute when the header is cut short or an attribute claims more
// bytes than the file holds.
void check_exr_header(const std::filesystem::path& file);

}  // namespace rtpro
