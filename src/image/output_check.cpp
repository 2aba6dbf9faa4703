#include "rtpro/image/output_check.h"

#include "oiio_output_formats.h"
#include "rtpro/core/error.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace rtpro {

namespace {

// Answers from the list generated from OpenImageIO at build time, not from OpenImageIO itself,
// which is only loaded when an image is written (see image_layer.h).
bool openimageio_writes(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  if (extension.size() < 2) return false;  // no extension, or a bare "."
  extension.erase(0, 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return std::binary_search(kOiioOutputExtensions.begin(), kOiioOutputExtensions.end(), extension);
}

}  // namespace

void check_image_output(const std::filesystem::path& file) {
  if (file.empty()) throw InputError("no output file given");
  if (!openimageio_writes(file))
    throw InputError("cannot write '" + file.string() + "': unknown image format '" + file.extension().string() +
                     "' (use .exr, .png, .jpg or .tif)");
  const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw RuntimeError("cannot write '" + file.string() + "': folder '" + folder.string() + "' does not exist");
  if (access(folder.c_str(), W_OK) != 0)
    throw RuntimeError("cannot write '" + file.string() + "': folder '" + folder.string() + "' is not writable");
  if (std::filesystem::is_directory(file, error))
    throw RuntimeError("cannot write '" + file.string() + "': it is a folder");
}

}  // namespace rtpro
