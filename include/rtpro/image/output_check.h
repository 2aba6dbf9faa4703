#pragma once
// Checks an output path before an expensive render, so a typo fails in milliseconds, not after
// the render: the format must be known to OpenImageIO and the folder must exist and be writable.
#include <filesystem>

namespace rtpro {

// Throws InputError for an unknown format, RuntimeError for a missing or read-only folder.
void check_image_output(const std::filesystem::path& file);

}  // namespace rtpro
