#include "pixel_encoding.h"

#include "rtpro/image/image_io.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace rtpro {

std::string lowercase_extension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

PixelEncoding encoding_for(const std::filesystem::path& file) {
  const std::string extension = lowercase_extension(file);
  for (const char* float_format : {".exr", ".sxr", ".mxr", ".hdr", ".rgbe", ".pfm"})
    if (extension == float_format) return PixelEncoding::kSceneLinearFloat;
  if (extension == ".tif" || extension == ".tiff") return PixelEncoding::kDisplay16Bit;
  return PixelEncoding::kDisplay8Bit;
}

bool writes_scene_linear(const std::filesystem::path& file) {
  return encoding_for(file) == PixelEncoding::kSceneLinearFloat;
}

}  // namespace rtpro
