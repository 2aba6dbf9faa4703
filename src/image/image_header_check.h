#pragma once
// A guard in front of the image libraries: Debian's OpenEXR 3.1 and libpng allocate (and clear)
// whatever size an attribute or chunk claims before reading it, so a file of a few hundred bytes
// claiming a 2 GB attribute or chunk costs gigabytes and seconds before failing (found by
// fuzzing `rtpro compare`'s image inputs). This walks EXR headers and PNG chunks itself and
// refuses any size larger than the bytes left in the file, and refuses raw PNM/PFM headers that
// declare more pixels than the file holds, and JPEG files whose Photoshop IPTC block (APP13) claims
// more bytes than its segment holds (OpenImageIO's JPEG reader reads past it). Other formats pass
// unchecked.
//
// OpenEXR also sizes its line buffers from the header's data window when a file is opened (a
// block of up to 256 rows of the full width, twice for compressed files), before any pixel is
// read; OpenImageIO's GIF reader allocates a canvas of the declared screen size, its BMP reader
// decodes a run-length-encoded image whole at open. The declared size is returned so that the read
// budget applies before opening.
#include "rtpro/image/image_size.h"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace rtpro {

// The size an image header declares, for formats whose library allocates from it at open.
struct DeclaredImageSize {
  std::uint64_t width = 0, height = 0, channels = 0;
  // An EXR's declared tile size (0 when it stores scanlines): OpenEXR allocates its tile and
  // compressor buffers from it at open, whatever the data window (a 796-byte file of a 20x18 image
  // declared 16x5063184 tiles and asked for 648 MB, a fuzz finding).
  std::uint64_t tile_width = 0, tile_height = 0;
};

// Throws InputError naming the attribute or chunk when an EXR header or a PNG chunk list is cut
// short, malformed, or claims more bytes than the file holds. Returns the data window and channel
// count of an EXR file's first part (the one read_image opens), the largest of a GIF's screen and
// frames (as RGBA), a BMP's declared size (as RGBA), a PNG's IHDR size (palette images as RGBA),
// nothing for other formats.
std::optional<DeclaredImageSize> check_image_header(const std::filesystem::path& file);

// read_image_size's answer where check_image_header gives one, after require_image_file (both
// throw InputError naming the file): without OpenImageIO. Nothing for the other formats.
std::optional<ImageSize> image_size_from_header(const std::filesystem::path& file);

}  // namespace rtpro
