#pragma once
// An image file's size as its header declares it, read without decoding a pixel: what a caller
// that keeps more than the decoded floats (the environment light, with its copy and sampling
// distribution) estimates its memory from before reading the image.
#include <cstdint>
#include <filesystem>

namespace rtpro {

struct ImageSize {
  std::uint64_t width = 0, height = 0, channels = 0;
  std::uint64_t pixels() const { return width * height; }  // each at most 2^32: no overflow
};

// Throws InputError naming the file when it is missing, not a regular file, or has no header
// rtpro can read (the same checks read_image makes before it opens a file).
ImageSize read_image_size(const std::filesystem::path& file);

}  // namespace rtpro
