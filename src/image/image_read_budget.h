#pragma once
// read_image for callers that keep more than the decoded floats: `extra_bytes_per_pixel` more per
// pixel count against `max_bytes` (0: default_memory_budget()), checked from the header before
// any pixel is decoded; `extra_purpose` says what for in the refusal ("with its texture copies").
#include "rtpro/image/image.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace rtpro {

Image read_image_counting(const std::filesystem::path& file, std::uint64_t max_bytes,
                          std::uint64_t extra_bytes_per_pixel, const std::string& extra_purpose);

}  // namespace rtpro
