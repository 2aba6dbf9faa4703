// write_image and read_image per format: EXR keeps floats and channels exactly; 8- and 16-bit
// formats go through the display view.
#include "rtpro/image/image_io.h"

#include "image_io_fixtures.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace rtpro::test {
namespace image_io_test {

namespace fs = std::filesystem;

std::string format_of(const fs::path& file) {
  const auto input = OIIO::ImageInput::open(file.string());
  return input ? input->format_name() : OIIO::geterror();
}

TEST(ImageIo, ExrKeepsScenelinearFloatsExactly) {
  const auto file = test::scratch_dir() / "beauty.exr";
  const Image image = varied_image(17, 9);
  write_image(file, image, {});
  const Image back = read_image(file);
  EXPECT_EQ(back.width, 17);
  EXPECT_EQ(back.height, 9);
  EXPECT_EQ(back.channels, image.channels);
  EXPECT_EQ(back.data, image.data);
  EXPECT_EQ(spec_of(file).format, OIIO::TypeDesc::FLOAT);
}

TEST(ImageIo, ExrKeepsNanAndInfinity) {
  const auto file = test::scratch_dir() / "broken_pixels.exr";
  Image image = uniform_image(2, 1, 0.5f);
  image.at(0, 0, 0) = NAN;
  image.at(1, 0, 2) = -INFINITY;
  write_image(file, image, {});
  const Image back = read_image(file);
  EXPECT_TRUE(std::isnan(back.at(0, 0, 0)));
  EXPECT_EQ(back.at(1, 0, 2), -INFINITY);
  EXPECT_EQ(back.at(1, 0, 1), 0.5f);
}

TEST(ImageIo, ExrKeepsEveryChannelByName) {
  const auto file = test::scratch_dir() / "aovs.exr";
  const std::vector<std::string> names = {"R",        "G",   "B",   "A",   "albedo.R", "albedo.G",
                                          "albedo.B", "N.X", "N.Y", "N.Z", "Z"};
  const Image image = varied_image(5, 4, names);
  write_image(file, image, {});
  test::expect_same_channels(image, read_image(file));
}

TEST(ImageIo, ExrCarriesChromaticitiesAndMetadata) {
  const auto file = test::scratch_dir() / "tagged.exr";
  ImageWriteOptions options;
  options.metadata = {{"rtpro:backend", "embree"}, {"Software", "rtpro test"}};
  write_image(file, uniform_image(2, 2, 0.5f), options);
  const OIIO::ImageSpec spec = spec_of(file);
  EXPECT_EQ(spec.get_string_attribute("rtpro:backend"), "embree");
  EXPECT_EQ(spec.get_string_attribute("Software"), "rtpro test");
  EXPECT_FALSE(spec.get_string_attribute("DateTime").empty());
  const OIIO::ParamValue* chromaticities = spec.find_attribute("chromaticities");
  ASSERT_NE(chromaticities, nullptr);
  ASSERT_EQ(chromaticities->type(), OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8));
  const float* xy = static_cast<const float*>(chromaticities->data());
  EXPECT_FLOAT_EQ(xy[0], 0.64f);    // Rec.709 red x
  EXPECT_FLOAT_EQ(xy[7], 0.3290f);  // D65 white y
}

TEST(ImageIo, PngGoesThroughTheSrgbView) {
  const auto file = test::scratch_dir() / "grey.png";
  write_image(file, uniform_image(3, 2, 0.18f), {});
  const OIIO::ImageSpec spec = spec_of(file);
  EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT8);
  EXPECT_EQ(spec.get_string_attribute("oiio:ColorSpace"), "sRGB");
  EXPECT_NE(spec.get_string_attribute("ImageDescription").find("Standard"), std::string::npos);
  const Image back = read_image(file);
  EXPECT_EQ(back.channels, (std::vector<std::string>{"R", "G", "B"}));
  for (float value : back.data) EXPECT_EQ(std::lround(value * 255.0f), 118);  // 0.4614 * 255 = 117.66
}

TEST(ImageIo, PngThroughTheAcesView) {
  const auto file = test::scratch_dir() / "aces.png";
  ImageWriteOptions options;
  options.view = "ACES 1.0 SDR-video";
  write_image(file, uniform_image(2, 2, 0.18f), options);
  for (float value : read_image(file).data) EXPECT_EQ(std::lround(value * 255.0f), 91);  // 0.356 * 255 = 90.8
}

TEST(ImageIo, PngClampsAndMapsNanToBlack) {
  const auto file = test::scratch_dir() / "extremes.png";
  Image image(6, 1);
  const float values[6] = {NAN, INFINITY, -INFINITY, -0.5f, 7.0f, 1.0f};
  for (int x = 0; x < 6; ++x)
    for (int c = 0; c < 3; ++c) image.at(x, 0, c) = values[x];
  write_image(file, image, {});
  const Image back = read_image(file);
  const int expected[6] = {0, 255, 0, 0, 255, 255};
  for (int x = 0; x < 6; ++x) EXPECT_EQ(std::lround(back.at(x, 0, 0) * 255.0f), expected[x]) << "pixel " << x;
}

TEST(ImageIo, PngKeepsOnlyTheFirstThreeChannels) {
  const auto file = test::scratch_dir() / "aovs.png";
  Image image(2, 2, {"R", "G", "B", "N.X"});
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      image.at(x, y, 0) = 1.0f;
      image.at(x, y, 3) = 0.5f;
    }
  write_image(file, image, {});
  const Image back = read_image(file);
  EXPECT_EQ(back.channel_count(), 3);
  EXPECT_EQ(back.at(1, 1, 0), 1.0f);
  EXPECT_EQ(back.at(1, 1, 1), 0.0f);
}

TEST(ImageIo, JpegRoundTripIsCloseToTheSrgbValue) {
  const auto file = test::scratch_dir() / "grey.JPG";
  write_image(file, uniform_image(16, 16, 0.18f), {});
  EXPECT_EQ(format_of(file), "jpeg") << "format chosen by extension, any case";
  const Image back = read_image(file);
  ASSERT_EQ(back.channel_count(), 3);
  for (float value : back.data) EXPECT_NEAR(value * 255.0f, 118.0f, 1.5f);
}

TEST(ImageIo, TiffIsSixteenBitDisplayReferred) {
  const auto file = test::scratch_dir() / "grey.tif";
  write_image(file, uniform_image(3, 3, 0.18f), {});
  EXPECT_EQ(spec_of(file).format, OIIO::TypeDesc::UINT16);
  const double expected = 1.055 * std::pow(0.18, 1.0 / 2.4) - 0.055;
  for (float value : read_image(file).data) EXPECT_NEAR(value, expected, 1.0 / 65535.0);
}

TEST(ImageIo, OcioConfigOptionChoosesTheConfigForEightBitFormats) {
  const auto file = test::scratch_dir() / "doubled.png";  // first: scratch_dir() empties the folder
  const auto config = test::write_file("doubling.ocio", R"(ocio_profile_version: 2
roles: {default: linear, scene_linear: linear}
displays:
  Test Display:
    - !<View> {name: Doubled, colorspace: doubled}
colorspaces:
  - !<ColorSpace> {name: linear}
  - !<ColorSpace>
    name: doubled
    from_scene_reference: !<MatrixTransform> {matrix: [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]}
)");
  ImageWriteOptions options;
  options.ocio_config = config;
  write_image(file, uniform_image(1, 1, 0.25f), options);
  EXPECT_EQ(std::lround(read_image(file).data[0] * 255.0f), 128);  // 0.5 * 255 = 127.5
}

}  // namespace image_io_test
}  // namespace rtpro::test
