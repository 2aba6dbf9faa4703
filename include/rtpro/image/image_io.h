#pragma once
// Reading and writing images through OpenImageIO. The format follows the file extension; EXR
// keeps scene-linear floats, 8-bit formats go through an OpenColorIO display/view transform.
// Writes are atomic: a temporary file in the same folder, renamed over the target on success.
#include "rtpro/image/image.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rtpro {

struct ImageWriteOptions {
  std::optional<std::filesystem::path> ocio_config;  // --ocio-config; else $OCIO; else bundled
  std::string display;                               // empty: the config's default display
  std::string view;                                  // empty: the display's default view
  // Key/value metadata, e.g. {"Software", "rtpro 0.1.0"}, {"rtpro:backend", "native"}.
  std::vector<std::pair<std::string, std::string>> metadata;
};

// Throws InputError for an unsupported extension or unknown view/display, RuntimeError when the
// file cannot be written; in both cases an existing file at `file` is left untouched.
void write_image(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options);

// Whether write_image keeps scene-linear floats for this file's format (EXR and the other float
// formats) rather than encoding it for a display.
bool writes_scene_linear(const std::filesystem::path& file);

// Throws InputError when the file is missing, unreadable, not a regular file, or declares more
// pixels than `max_bytes` of 32-bit floats hold (checked from the header, before any pixel is
// allocated: a few bytes of PNG header can declare 65535x65535). `max_bytes` 0 means
// default_memory_budget().
Image read_image(const std::filesystem::path& file, std::uint64_t max_bytes = 0);

}  // namespace rtpro
