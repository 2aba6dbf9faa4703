#pragma once
// The checks every image read starts with, before any library touches the file.
#include <filesystem>

namespace rtpro {

// Throws InputError naming the file when it does not exist or is not a regular file (a FIFO,
// device or folder is never read as an image: opening a FIFO would wait for a writer).
void require_image_file(const std::filesystem::path& file);

}  // namespace rtpro
