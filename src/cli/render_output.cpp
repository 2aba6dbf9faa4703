#include "render_output.h"

#include <cctype>
#include <string>

namespace rtpro::cli {

// Only EXR has named layers for the AOVs; every other format would drop them without a word.
bool holds_layers(const std::filesystem::path& output) {
  std::string extension = output.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".exr" || extension == ".sxr" || extension == ".mxr";
}

Image crop_image(const Image& full, const PixelRegion& r) {
  Image out(r.width(), r.height(), full.channels);
  for (int y = 0; y < r.height(); ++y)
    for (int x = 0; x < r.width(); ++x)
      for (int c = 0; c < full.channel_count(); ++c) out.at(x, y, c) = full.at(r.x0 + x, r.y0 + y, c);
  return out;
}

// "out.png" → "out.partial.png": an interrupted render never replaces a finished image.
std::filesystem::path partial_path(const std::filesystem::path& output) {
  std::filesystem::path p = output;
  p.replace_filename(output.stem().string() + ".partial" + output.extension().string());
  return p;
}

}  // namespace rtpro::cli
