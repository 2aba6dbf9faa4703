#pragma once
// For the image module's read_image and write_image tests: made-up images, and files written or
// inspected with OpenImageIO directly, as other programs write and read them.
#include "rtpro/image/image.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace rtpro::test {

// Values of every sign and magnitude, none of which a half-float or 8-bit path keeps exactly.
inline Image varied_image(int width, int height, std::vector<std::string> channels = {"R", "G", "B"}) {
  Image image(width, height, std::move(channels));
  std::uint32_t state = 12345;
  for (float& value : image.data) {
    state = state * 1664525u + 1013904223u;
    value = (static_cast<float>(state >> 8) / 16777216.0f - 0.25f) * 7.0f + 1e-7f;
  }
  return image;
}

inline OIIO::ImageSpec spec_of(const std::filesystem::path& file) {
  const auto input = OIIO::ImageInput::open(file.string());
  EXPECT_TRUE(input) << OIIO::geterror();
  return input ? input->spec() : OIIO::ImageSpec();
}

// Writes `image` with OpenImageIO directly, in the layout `shape` gives the spec (tiles, a data
// window, per-channel types), as files from other programs come.
inline void write_with_oiio(const std::filesystem::path& file, const Image& image, OIIO::TypeDesc type,
                            const std::function<void(OIIO::ImageSpec&)>& shape) {
  OIIO::ImageSpec spec(image.width, image.height, static_cast<int>(image.channels.size()), type);
  spec.channelnames = image.channels;
  shape(spec);
  const auto output = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(output && output->open(file.string(), spec)) << OIIO::geterror();
  ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, image.data.data())) << output->geterror();
  ASSERT_TRUE(output->close());
}

}  // namespace rtpro::test
