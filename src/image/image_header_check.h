#pragma once
// A guard in front of the image libraries: Debian's OpenEXR 3.1 and libpng allocate (and clear)
// whatever size an attribute or chunk claims before reading it, so a file of a few hundred bytes
// claiming a 2 GB attribute or chunk costs gigabytes and seconds before failing (found by
// fuzzing `rtpro compare`'s image inputs). This walks EXR headers and PNG chunks itself and
// refuses any size larger than the bytes left in the file, and refuses raw PNM/PFM headers that
// declare more pixels than the file holds. Other formats pass unchecked.
#include <filesystem>

namespace rtpro {

// Throws InputError naming the attribute or chunk when an EXR header or a PNG chunk list is cut
// short, malformed, or claims more bytes than the file holds.
void check_image_header(const std::filesystem::path& file);

}  // namespace rtpro
