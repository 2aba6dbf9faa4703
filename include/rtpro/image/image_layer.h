#pragma once
// How the rtpro executable reaches OpenImageIO. Debian's OpenImageIO pulls in some 260 shared
// libraries that take about half a second and 120 MB to load, so the executable does not link it:
// write_image, read_image, read_image_size, compare_images and write_diff_image go through librtpro_image_oiio.so,
// a plugin loaded from the executable's own folder on first use. Everything else in this module
// (output checks, OpenColorIO colour configs, writing EXR files through OpenEXR and PNG files
// through libpng, reading RGB(A) EXR files through OpenEXR) works without it. Tests and other programs that link
// rtpro_image call OpenImageIO directly and never load the plugin; these functions exist only in
// the executable's rtpro_image_loader.

#include <filesystem>

namespace rtpro {

// Whether write_image needs the plugin for this file (every format but EXR and PNG).
bool writing_needs_image_layer(const std::filesystem::path& file);

// Whether read_image is likely to need the plugin for this file: every file but an EXR (most of
// which are read through OpenEXR, exr_input.h; the others load the plugin when they are read).
bool reading_needs_image_layer(const std::filesystem::path& file);

// Starts loading the plugin on a background thread and returns at once, so that the image layer
// is ready by the time a render finishes. A failure is reported by the first call that needs it.
void start_loading_image_layer();

// True while a background load is still running. The C library's exit() waits for it (it takes
// the dynamic loader's lock), so a command that fails early leaves with _Exit instead.
bool image_layer_loading();

}  // namespace rtpro
