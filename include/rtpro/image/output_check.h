#pragma once
// Checks an output path before an expensive render, so a typo fails in milliseconds, not after
// the render: the format must be known to OpenImageIO and the folder must exist and take a new file
// (the writer's temporary file is created there and removed).
#include <filesystem>

namespace rtpro {

// Throws InputError for an unknown format, RuntimeError for a missing or read-only folder or one
// where the file cannot be created.
void check_image_output(const std::filesystem::path& file);

}  // namespace rtpro
