#include "image_metadata.h"

#include "rtpro/core/error.h"

#include <algorithm>
#include <ctime>

namespace rtpro {

namespace {

std::string current_date_time() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[32];
  std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &local);  // the TIFF/EXIF DateTime form
  return text;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> image_metadata(std::string description,
                                                                const ImageWriteOptions& options) {
  std::vector<std::pair<std::string, std::string>> entries = {{"Software", "rtpro " RTPRO_VERSION},
                                                              {"ImageDescription", std::move(description)},
                                                              {"DateTime", current_date_time()}};
  for (const auto& given : options.metadata) {
    const auto same =
        std::find_if(entries.begin(), entries.end(), [&](const auto& entry) { return entry.first == given.first; });
    if (same != entries.end()) same->second = given.second;
    else entries.push_back(given);
  }
  return entries;
}

std::vector<std::pair<std::string, std::string>> scene_linear_metadata(const ImageWriteOptions& options) {
  ImageWriteOptions with_colorspace = options;
  with_colorspace.metadata.insert(with_colorspace.metadata.begin(), {"rtpro:colorspace", "Linear Rec.709 (sRGB)"});
  return image_metadata("rtpro image, scene-linear Rec.709 primaries", with_colorspace);
}

void require_writable_image(const std::filesystem::path& file, const Image& image) {
  const std::size_t expected = static_cast<std::size_t>(std::max(image.width, 0)) *
                               static_cast<std::size_t>(std::max(image.height, 0)) * image.channels.size();
  if (image.width <= 0 || image.height <= 0 || image.channels.empty() || image.data.size() != expected)
    throw RuntimeError("cannot write " + file.string() + ": the image is empty or inconsistent (" +
                       std::to_string(image.width) + "x" + std::to_string(image.height) + ", " +
                       std::to_string(image.channels.size()) + " channels, " + std::to_string(image.data.size()) +
                       " values)");
}

}  // namespace rtpro
