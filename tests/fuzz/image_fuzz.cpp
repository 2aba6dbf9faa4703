// Fuzz target: the image inputs of `rtpro compare` — read_image, then the comparison and the diff
// heat map of the image against itself.
//
// Input: one byte choosing the file extension (OpenImageIO picks the reader by it, then by
// content), then the file's bytes. The extensions are the formats rtpro writes and the other
// common ones a user may hand to `rtpro compare`.
#include "fuzz_workspace.h"
#include "rtpro/core/error.h"
#include "rtpro/image/diff_image.h"
#include "rtpro/image/image_compare.h"
#include "rtpro/image/image_io.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace {
// As if the machine had 2 MiB to spare: a larger declared image is refused from its header. The
// seed images are far smaller; a larger budget only spends executions on clearing memory and on
// comparing big images pixel by pixel.
constexpr std::uint64_t kReadBudget = std::uint64_t{2} << 20;
constexpr std::array<std::string_view, 10> kExtensions = {".exr", ".png", ".tif", ".jpg", ".hdr",
                                                          ".pfm", ".ppm", ".bmp", ".tga", ".gif"};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string name = "image" + std::string(kExtensions[data[0] % kExtensions.size()]);
  const auto file = rtpro::fuzz::write_workspace_file(name, {reinterpret_cast<const char*>(data + 1), size - 1});
  try {
    const rtpro::Image image = rtpro::read_image(file, kReadBudget);
    rtpro::compare_images(image, image, rtpro::CompareThresholds{});
    rtpro::diff_heat_map(image, image, 0.0f);
  } catch (const rtpro::InputError&) {
  }
  return 0;
}
