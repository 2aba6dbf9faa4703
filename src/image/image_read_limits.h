#pragma once
// The limits every image read checks from the header's declared size before a library allocates
// for it: read_image's OpenImageIO path (image_io.cpp, which explains a refusal) and the EXR read
// through OpenEXR (exr_input.h, which leaves a refused file to it) count alike.
#include <cstddef>
#include <cstdint>

namespace rtpro {

// The bytes a read of a width × height image of `channels` costs: its floats, or more where the
// library buffers more. OpenImageIO reads up to 256 scanlines at once into a buffer of its own,
// whatever the image's height (a 2-row image 681553 pixels wide made it allocate 3.5 GB, a fuzz
// finding); a tiled file costs two tiles of `tile_pixels` (a tile and its compressor's). Plus
// `extra_bytes_per_pixel` for a caller that keeps more than the floats. Saturates.
std::uint64_t image_read_bytes(std::uint64_t width, std::uint64_t height, std::uint64_t channels,
                               std::uint64_t tile_pixels, std::uint64_t extra_bytes_per_pixel);

// Whether such a read is allowed: at most 2^30 pixels and 2^30 values (4 GiB of floats, a 16k x 16k
// RGBA image), and image_read_bytes within `max_bytes`.
bool image_read_allowed(std::uint64_t width, std::uint64_t height, std::uint64_t channels, std::uint64_t tile_pixels,
                        std::uint64_t extra_bytes_per_pixel, std::uint64_t max_bytes);

// The rows a read decodes per call for rows of `row_values` floats: at least 64 and about a million
// values, so that a narrow image does not take one library call per 64 rows (a 5x32864 TIFF took
// 514 calls and 53 s under ASan, a fuzz finding).
std::size_t image_read_band_rows(std::size_t row_values);

}  // namespace rtpro
