// read_image on files it did not write: missing, garbage or misnamed files, tiles, strips and
// per-channel types.
#include "rtpro/image/image_io.h"

#include "image_io_fixtures.h"
#include "rtpro/core/error.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <Imath/half.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>

namespace rtpro::test {
namespace image_read_test {

namespace fs = std::filesystem;
using namespace std::string_literals;

TEST(ImageIo, ReadingAMissingFileIsAnInputErrorNamingIt) {
  const auto file = test::scratch_dir() / "absent.exr";
  const std::string message = error_message_of<InputError>([&] { read_image(file); });
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
}

TEST(ImageIo, ReadingGarbageIsAnInputErrorNamingIt) {
  const auto file = test::write_file("garbage.png", "this is not a PNG file at all");
  const std::string message = error_message_of<InputError>([&] { read_image(file); });
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
}

TEST(ImageIo, AnImageIsReadByItsSignatureWhateverItsExtension) {
  const auto folder = test::scratch_dir();
  write_image(folder / "real.png", uniform_image(5, 3, 0.5f), {});
  std::ofstream(folder / "misnamed.exr", std::ios::binary) << read_file(folder / "real.png");
  const Image image = read_image(folder / "misnamed.exr");
  EXPECT_EQ(image.width, 5);
  EXPECT_EQ(image.height, 3);
}

TEST(ImageIo, GarbageIsTriedOnlyByTheReaderItsExtensionNames) {
  // OpenImageIO alone would hand these bytes to every reader it has after the PNG reader refused.
  const auto file = test::write_file("garbage_named.png", "this is not a PNG file at all");
  const std::string message = error_message_of<InputError>([&] { read_image(file); });
  EXPECT_NE(message.find("as png"), std::string::npos) << message;
}

TEST(ImageIo, AFileWithNeitherExtensionNorSignatureIsRefusedSayingSo) {
  const auto file = test::write_file("image_without_extension", "plain text, no image signature");
  const std::string message = error_message_of<InputError>([&] { read_image(file); });
  EXPECT_NE(message.find("cannot tell what kind of image"), std::string::npos) << message;
}

TEST(ImageIo, AGifWhoseScreenOrFrameExceedsTheReadBudgetIsRefusedBeforeOpening) {
  // OpenImageIO's GIF reader allocates an RGBA canvas of the screen's size when it opens the file.
  const std::string huge_screen = "GIF89a\xff\xff\xff\xff\0\0\0;"s;
  const std::string huge_frame = "GIF89a\x01\0\x01\0\0\0\0,\0\0\0\0\xff\xff\xff\xff\0\x02\0;"s;
  // giflib reads any version after "GIF": chosen by its .gif name, this one opened unchecked, and
  // OpenImageIO asked for a 16 GiB canvas.
  const std::string other_version = "GIF00a\xff\xff\xff\xff\0\0\0;"s;
  for (const std::string& bytes : {huge_screen, huge_frame, other_version}) {
    const auto file = test::write_file("huge.gif", bytes);
    const std::string message = error_message_of<InputError>([&] { read_image(file, std::uint64_t{64} << 20); });
    EXPECT_NE(message.find("65535x65535"), std::string::npos) << message;
  }
}

TEST(ImageIo, TiledFilesReadAsTheirScanlineTwins) {
  // OpenImageIO 2.4's own converting read divides by zero on tiled files (SIGFPE).
  const auto folder = test::scratch_dir();
  const Image image = varied_image(37, 29);  // tiles of 16 leave partial tiles at both edges
  const auto tiled = [](OIIO::ImageSpec& spec) { spec.tile_width = spec.tile_height = 16; };
  write_with_oiio(folder / "tiled.exr", image, OIIO::TypeDesc::FLOAT, tiled);
  EXPECT_EQ(read_image(folder / "tiled.exr").data, image.data);
  write_with_oiio(folder / "tiled.tif", image, OIIO::TypeDesc::FLOAT, tiled);
  EXPECT_EQ(read_image(folder / "tiled.tif").data, image.data);
}

// An RGB image whose value i is ((i * step) mod 256) / 255, exact in 8 bits.
Image ramp_image(int width, int height, std::size_t step) {
  Image image(width, height, {"R", "G", "B"});
  for (std::size_t i = 0; i < image.data.size(); ++i) image.data[i] = static_cast<float>((i * step) % 256) / 255.0f;
  return image;
}

// `image` as an 8-bit deflate TIFF in strips of `rows_per_strip`, written by OpenImageIO; the
// file's bytes, for a test to alter.
std::string deflate_tiff_bytes(const fs::path& file, const Image& image, int rows_per_strip) {
  write_with_oiio(file, image, OIIO::TypeDesc::UINT8, [&](OIIO::ImageSpec& spec) {
    spec.attribute("compression", "zip");
    spec.attribute("tiff:RowsPerStrip", rows_per_strip);
  });
  return read_file(file);
}

TEST(ImageIo, AMinIsWhiteRgbTiffInDeflateStripsIsReadInvertedAndWithinItsBuffer) {
  // OpenImageIO 2.4 inverts nchannels times too many values on whole deflate strips of a MinIsWhite
  // TIFF, up to two strips past the caller's buffer for RGB (a fuzz finding: the overrun corrupted
  // the heap). read_image takes such a file one scanline at a time, and the guard after its buffer
  // turns an overrun into an error: without the first, this test fails on the second.
  const auto folder = test::scratch_dir();
  const Image image = ramp_image(8, 64, 37);
  std::string bytes = deflate_tiff_bytes(folder / "rgb.tif", image, 16);
  // The PhotometricInterpretation entry (tag 262, SHORT, count 1, RGB = 2) becomes MinIsWhite (0).
  const std::string rgb_entry("\x06\x01\x03\x00\x01\x00\x00\x00\x02\x00", 10);
  const std::size_t entry = bytes.find(rgb_entry);
  ASSERT_NE(entry, std::string::npos) << "no little-endian RGB PhotometricInterpretation entry";
  bytes[entry + 8] = 0;
  std::ofstream(folder / "white_is_zero.tif", std::ios::binary) << bytes;
  ASSERT_EQ(spec_of(folder / "white_is_zero.tif").get_int_attribute("tiff:PhotometricInterpretation", -1), 0);
  ASSERT_EQ(spec_of(folder / "white_is_zero.tif").get_int_attribute("tiff:Compression", -1), 8);  // Adobe deflate

  const Image read = read_image(folder / "white_is_zero.tif");
  ASSERT_EQ(read.data.size(), image.data.size());
  for (std::size_t i = 0; i < image.data.size(); ++i)
    ASSERT_EQ(std::lround(read.data[i] * 255.0f), 255 - static_cast<long>((i * 37) % 256)) << "value " << i;
}

TEST(ImageIo, ATiffWhoseRowsPerStripExceedItsHeightIsReadAsOneStrip) {
  // RowsPerStrip above the height is legal TIFF (one strip holds the image; 2^32 - 1 is the
  // specification's default), but OpenImageIO 2.4 sizes its whole-strip scratch from it: a 366-byte
  // fuzz input declaring 704,662,861 rows per strip asked for 5.6 PB. read_image takes such a file
  // one scanline at a time; without that this test fails (std::bad_alloc, or an ASan abort).
  const auto folder = test::scratch_dir();
  const Image image = ramp_image(8, 20, 29);
  const std::string written = deflate_tiff_bytes(folder / "one_strip.tif", image, 20);
  // The RowsPerStrip entry (tag 278, SHORT, count 1, 20) becomes a LONG of the declared value.
  const std::string rows_entry("\x16\x01\x03\x00\x01\x00\x00\x00\x14\x00", 10);
  const std::size_t entry = written.find(rows_entry);
  ASSERT_NE(entry, std::string::npos) << "no little-endian SHORT RowsPerStrip entry of 20";
  for (const std::uint32_t rows_per_strip : {std::uint32_t{0x2a004d4d}, std::uint32_t{0xffffffff}, std::uint32_t{21}}) {
    SCOPED_TRACE(rows_per_strip);
    std::string bytes = written;
    bytes[entry + 2] = 4;
    for (int b = 0; b < 4; ++b) bytes[entry + 8 + b] = static_cast<char>((rows_per_strip >> (8 * b)) & 0xff);
    std::ofstream(folder / "declared.tif", std::ios::binary | std::ios::trunc) << bytes;
    const Image read = read_image(folder / "declared.tif");
    ASSERT_EQ(read.data.size(), image.data.size());
    for (std::size_t i = 0; i < image.data.size(); ++i)
      ASSERT_EQ(std::lround(read.data[i] * 255.0f), static_cast<long>((i * 29) % 256)) << "value " << i;
  }
}

TEST(ImageIo, PerChannelTypesAndAnOffsetDataWindowAreReadInPlace) {
  const auto folder = test::scratch_dir();
  Image image = varied_image(9, 7, {"R", "G", "B", "Z"});
  write_with_oiio(folder / "mixed.exr", image, OIIO::TypeDesc::FLOAT, [](OIIO::ImageSpec& spec) {
    spec.channelformats = {OIIO::TypeDesc::HALF, OIIO::TypeDesc::HALF, OIIO::TypeDesc::HALF, OIIO::TypeDesc::FLOAT};
    spec.x = 3;
    spec.y = 5;
  });
  const Image read = read_image(folder / "mixed.exr");
  ASSERT_EQ(read.data.size(), image.data.size());
  for (std::size_t i = 0; i < image.data.size(); ++i) {
    // Colour went through half, depth stayed float.
    const bool depth = i % 4 == 3;
    const float expected = depth ? image.data[i] : static_cast<float>(Imath::half(image.data[i]));
    ASSERT_EQ(read.data[i], expected) << "value " << i;
  }
}

}  // namespace image_read_test
}  // namespace rtpro::test
