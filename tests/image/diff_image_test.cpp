#include "rtpro/image/diff_image.h"

#include "rtpro/image/image_io.h"
#include "test_paths.h"

#include "test_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rtpro {
namespace diff_image_test {

using test::gradient_image;

// Where the heat map is brightest (the ramp's brightness rises with the error).
std::pair<int, int> hottest_pixel(const Image& image) {
  std::pair<int, int> hottest{-1, -1};
  float best = -1.0f;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float sum = image.at(x, y, 0) + image.at(x, y, 1) + image.at(x, y, 2);
      if (sum > best) best = sum, hottest = {x, y};
    }
  return hottest;
}

TEST(DiffImage, HottestPixelIsWhereTheErrorIs) {
  const Image reference = gradient_image(9, 7);
  Image test = reference;
  test.at(7, 2, 0) += 0.4f;
  test.at(1, 5, 1) += 0.1f;
  const Image heat_map = diff_heat_map(reference, test, 0.0f);
  EXPECT_EQ(heat_map.channels, (std::vector<std::string>{"R", "G", "B", "error"}));
  EXPECT_EQ(hottest_pixel(heat_map), std::make_pair(7, 2));
  EXPECT_EQ(heat_map.at(7, 2, 0), 1.0f);  // the largest error is white
  EXPECT_EQ(heat_map.at(7, 2, 2), 1.0f);
  EXPECT_NEAR(heat_map.at(7, 2, 3), 0.4f, 1e-6f);
  EXPECT_EQ(heat_map.at(0, 0, 0) + heat_map.at(0, 0, 1) + heat_map.at(0, 0, 2), 0.0f);  // no error: black
  EXPECT_GT(heat_map.at(1, 5, 2), 0.0f);                                                // a quarter of the scale: blue
}

TEST(DiffImage, ErrorsAtTheFailThresholdAreWhiteAndNanIsMagenta) {
  const Image reference = gradient_image(4, 4);
  Image test = reference;
  test.at(0, 0, 0) += 0.01f;
  test.at(3, 3, 1) = NAN;
  const Image heat_map = diff_heat_map(reference, test, 0.001f);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(heat_map.at(0, 0, c), 1.0f);
  EXPECT_EQ(heat_map.at(3, 3, 0), 1.0f);
  EXPECT_EQ(heat_map.at(3, 3, 1), 0.0f);
  EXPECT_EQ(heat_map.at(3, 3, 2), 1.0f);
}

TEST(DiffImage, WrittenPngAndExrShowTheSameHotSpot) {
  const auto folder = test::scratch_dir();
  const Image reference = gradient_image(9, 7);
  Image test = reference;
  test.at(4, 6, 2) -= 0.3f;
  for (const char* name : {"diff.png", "diff.exr"}) {
    write_diff_image(folder / name, reference, test, 0.0f);
    const Image written = read_image(folder / name);
    EXPECT_EQ(hottest_pixel(written), std::make_pair(4, 6)) << name;
    EXPECT_EQ(written.width, 9);
  }
  // The PNG holds the ramp colours unchanged (Raw view): white at the hot spot, pure blue at a
  // quarter of the scale would be (0, 0, 255).
  const Image png = read_image(folder / "diff.png");
  EXPECT_EQ(png.at(4, 6, 0), 1.0f);
  EXPECT_EQ(png.at(0, 0, 0), 0.0f);
  const Image exr = read_image(folder / "diff.exr");
  EXPECT_EQ(exr.channel_count(), 4);
}

}  // namespace diff_image_test
}  // namespace rtpro
