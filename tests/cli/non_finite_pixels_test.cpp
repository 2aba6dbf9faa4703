// The warning of pixels a render or a denoise gave no finite colour: counted over the colour
// channels only (an AOV such as a miss's depth may be infinite), naming the first.
#include "non_finite_pixels.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace rtpro::cli {
namespace non_finite_pixels_test {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

Image image_of(int width, int height, std::vector<std::string> channels) {
  Image image(width, height, std::move(channels));
  for (std::size_t i = 0; i < image.data.size(); ++i) image.data[i] = 0.001f * static_cast<float>(i);
  return image;
}

TEST(NonFinitePixels, AFiniteImageHasNoWarning) {
  EXPECT_EQ(non_finite_pixels_warning(image_of(37, 21, {"R", "G", "B"})), std::nullopt);
  EXPECT_EQ(non_finite_pixels_warning(image_of(1, 1, {"Y"})), std::nullopt);
  EXPECT_EQ(non_finite_pixels_warning(Image(0, 0, {"R", "G", "B"})), std::nullopt);
}

TEST(NonFinitePixels, CountsPixelsAndNamesTheFirst) {
  Image image = image_of(37, 21, {"R", "G", "B"});
  image.at(3, 1, 1) = kNaN;
  image.at(3, 1, 2) = kInf;  // the same pixel again
  image.at(36, 20, 0) = -kInf;
  image.at(5, 7, 2) = kNaN;
  EXPECT_EQ(non_finite_pixels_warning(image), "3 pixels are not finite (infinite or NaN; the first at x 3, y 1)");

  Image one = image_of(37, 21, {"R", "G", "B"});
  one.at(36, 20, 2) = kNaN;  // the very last value
  EXPECT_EQ(non_finite_pixels_warning(one), "1 pixel is not finite (infinite or NaN; the first at x 36, y 20)");
}

TEST(NonFinitePixels, OnlyTheColourChannelsCount) {
  Image image = image_of(9, 4, {"R", "G", "B", "A", "Z"});
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 9; ++x) image.at(x, y, 4) = kInf;  // every miss's depth
  EXPECT_EQ(non_finite_pixels_warning(image), std::nullopt);
  image.at(8, 3, 3) = kNaN;  // alpha is not colour either
  EXPECT_EQ(non_finite_pixels_warning(image), std::nullopt);
  image.at(2, 3, 0) = kNaN;
  EXPECT_EQ(non_finite_pixels_warning(image), "1 pixel is not finite (infinite or NaN; the first at x 2, y 3)");

  Image grey = image_of(6, 2, {"Y"});
  grey.at(4, 0, 0) = kNaN;
  EXPECT_EQ(non_finite_pixels_warning(grey), "1 pixel is not finite (infinite or NaN; the first at x 4, y 0)");
}

}  // namespace non_finite_pixels_test
}  // namespace rtpro::cli
