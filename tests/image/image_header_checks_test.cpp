// read_image refuses files whose headers claim more than their bytes hold, or more than the read
// budget allows, before a library trusts them.
#include "rtpro/image/image_io.h"

#include "image_io_fixtures.h"
#include "rtpro/core/error.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <utility>

namespace rtpro::test {
namespace image_header_checks_test {

namespace fs = std::filesystem;

TEST(ImageIo, AJpegWhosePhotoshopBlockClaimsMoreThanItsSegmentIsRefused) {
  // OpenImageIO 2.4 reads a Photoshop IPTC block by the size it states: a fuzz input made it read
  // 111 bytes past the segment while opening. Without the header check this test fails on the
  // first EXPECT_THROW (the library reads past its buffer and the image comes back).
  const auto folder = test::scratch_dir();
  const Image image = varied_image(5, 4);
  write_with_oiio(folder / "caption.jpg", image, OIIO::TypeDesc::UINT8, [](OIIO::ImageSpec& spec) {
    spec.attribute("ImageDescription", "a caption that goes into the IPTC block of the JPEG file");
  });
  EXPECT_EQ(read_image(folder / "caption.jpg").width, 5);
  const std::string written = read_file(folder / "caption.jpg");
  const std::size_t resource = written.find(std::string("8BIM\x04\x04", 6));
  ASSERT_NE(resource, std::string::npos) << "OpenImageIO wrote no IPTC block";
  const std::size_t segment = written.rfind("\xff\xed", resource);
  ASSERT_NE(segment, std::string::npos);

  std::string claims_more = written;  // the block's own size: 0xffff bytes of records
  claims_more[resource + 10] = '\xff';
  claims_more[resource + 11] = '\xff';
  std::ofstream(folder / "claims_more.jpg", std::ios::binary) << claims_more;
  EXPECT_THROW(read_image(folder / "claims_more.jpg"), InputError);
  // The same with a stray byte for the first segment's marker, which libjpeg skips up to the next
  // one (a fuzz finding: the file no longer starts with JPEG's three-byte signature, so it was
  // opened as JPEG by its extension, unchecked).
  std::string stray_byte = claims_more;
  ASSERT_EQ(stray_byte[2], '\xff');
  stray_byte[2] = '\x5d';
  std::ofstream(folder / "stray_byte.jpg", std::ios::binary) << stray_byte;
  EXPECT_THROW(read_image(folder / "stray_byte.jpg"), InputError);

  std::string cut_short = written;  // the segment ends inside the block's header (16 bytes of data)
  cut_short[segment + 2] = 0;
  cut_short[segment + 3] = 18;
  std::ofstream(folder / "cut_short.jpg", std::ios::binary) << cut_short;
  try {
    read_image(folder / "cut_short.jpg");
    ADD_FAILURE() << "a block cut short was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("APP13"), std::string::npos) << e.what();
  }
}

TEST(ImageIo, ReadingATruncatedExrIsAnInputError) {
  const auto folder = test::scratch_dir();
  write_image(folder / "whole.exr", varied_image(64, 64), {});
  const std::string bytes = read_file(folder / "whole.exr");
  std::ofstream(folder / "cut.exr", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_THROW(read_image(folder / "cut.exr"), InputError);
}

// The position of the little-endian size field of the EXR header attribute `name`.
std::size_t exr_attribute_size_field(const std::string& bytes, const std::string& name, const std::string& type) {
  const std::size_t at = bytes.find(name + std::string(1, '\0') + type + std::string(1, '\0'));
  EXPECT_NE(at, std::string::npos) << name;
  return at + name.size() + 1 + type.size() + 1;
}

void put_u32(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<char>(value >> (8 * i) & 0xff);
}

TEST(ImageIo, AnExrAttributeWhoseStatedSizeItsContentsDoNotFillIsRefused) {
  const auto folder = test::scratch_dir();
  write_image(folder / "whole.exr", varied_image(8, 8, {"R", "G", "B", "A", "depth.Z"}), {});
  ASSERT_NO_THROW(read_image(folder / "whole.exr"));
  for (const auto& [name, type] :
       {std::pair<std::string, std::string>{"channels", "chlist"}, {"dataWindow", "box2i"}}) {
    std::string bytes = read_file(folder / "whole.exr");
    const std::size_t field = exr_attribute_size_field(bytes, name, type);
    const std::uint32_t size = static_cast<unsigned char>(bytes[field]);  // both are under 256 bytes
    put_u32(bytes, field, size - 1);
    std::ofstream(folder / "skewed.exr", std::ios::binary) << bytes;
    const std::string message = error_message_of<InputError>([&] { read_image(folder / "skewed.exr"); });
    EXPECT_NE(message.find("attribute '" + name + "' of type " + type), std::string::npos) << message;
  }
}

TEST(ImageIo, AnExrWhoseTilesExceedTheReadBudgetIsRefusedBeforeOpenExrAllocatesThem) {
  // OpenEXR sizes its tile buffers from the declared tile size when it opens the file.
  const auto folder = test::scratch_dir();
  write_with_oiio(folder / "tiled.exr", varied_image(20, 18), OIIO::TypeDesc::HALF,
                  [](OIIO::ImageSpec& spec) { spec.tile_width = spec.tile_height = 16; });
  ASSERT_NO_THROW(read_image(folder / "tiled.exr"));
  std::string bytes = read_file(folder / "tiled.exr");
  const std::size_t size_field = exr_attribute_size_field(bytes, "tiles", "tiledesc");
  put_u32(bytes, size_field + 8, 5063184);  // tile height
  std::ofstream(folder / "huge_tiles.exr", std::ios::binary) << bytes;
  const std::string message =
      error_message_of<InputError>([&] { read_image(folder / "huge_tiles.exr", std::uint64_t{64} << 20); });
  EXPECT_NE(message.find("in tiles of"), std::string::npos) << message;
}

TEST(ImageIo, AnExrWithoutADataWindowIsRefusedBeforeOpenExrSizesItsTiles) {
  // Renaming the attribute leaves OpenEXR its default window and a tile description alone, from
  // which it sized a 1.6 GB compressor buffer at open (a fuzz finding).
  const auto folder = test::scratch_dir();
  write_with_oiio(folder / "tiled.exr", varied_image(20, 18), OIIO::TypeDesc::HALF,
                  [](OIIO::ImageSpec& spec) { spec.tile_width = spec.tile_height = 16; });
  std::string bytes = read_file(folder / "tiled.exr");
  const std::size_t window = bytes.find(std::string("dataWindow\0box2i", 16));
  ASSERT_NE(window, std::string::npos);
  bytes[window + 10] = 'b';  // "dataWindowb", of type "ox2i": the same number of bytes
  std::ofstream(folder / "no_window.exr", std::ios::binary) << bytes;
  const std::string message = error_message_of<InputError>([&] { read_image(folder / "no_window.exr"); });
  EXPECT_NE(message.find("no dataWindow"), std::string::npos) << message;
}

TEST(ImageIo, AnExrWhoseDataWindowExceedsTheReadBudgetIsRefusedNamingItsSize) {
  const auto folder = test::scratch_dir();
  write_image(folder / "small.exr", varied_image(8, 2), {});
  std::string bytes = read_file(folder / "small.exr");
  const std::size_t window = exr_attribute_size_field(bytes, "dataWindow", "box2i") + 4;
  put_u32(bytes, window + 8, 681552);  // xMax: 681553 pixels wide, 2 rows, as a fuzzer wrote it
  std::ofstream(folder / "wide.exr", std::ios::binary) << bytes;
  const std::string message =
      error_message_of<InputError>([&] { read_image(folder / "wide.exr", std::uint64_t{256} << 20); });
  EXPECT_NE(message.find("681553x2"), std::string::npos) << message;
  EXPECT_NE(message.find("too large"), std::string::npos) << message;
}

TEST(ImageIo, ABmpDeclaringMorePixelsThanTheBudgetIsRefusedBeforeOpenImageIoDecodesIt) {
  // OpenImageIO's BMP reader decodes a run-length-encoded image whole at open, into a buffer of the
  // declared size: a 118-byte file declaring 536870917x4 made it throw std::length_error there (a
  // fuzz finding that ended in std::terminate). The info header's size is checked first.
  const auto folder = test::scratch_dir();
  write_with_oiio(folder / "small.bmp", varied_image(8, 2), OIIO::TypeDesc::UINT8, [](OIIO::ImageSpec&) {});
  ASSERT_NO_THROW(read_image(folder / "small.bmp"));
  std::string bytes = read_file(folder / "small.bmp");
  ASSERT_EQ(bytes.substr(0, 2), "BM");
  // The finding's shape: run-length encoded (compression 2), 536870917x4.
  put_u32(bytes, 18, 536870917);
  put_u32(bytes, 22, 4);
  put_u32(bytes, 30, 2);
  std::ofstream(folder / "wide.bmp", std::ios::binary) << bytes;
  const std::string message =
      error_message_of<InputError>([&] { read_image(folder / "wide.bmp", std::uint64_t{256} << 20); });
  EXPECT_NE(message.find("536870917x4"), std::string::npos) << message;
  EXPECT_NE(message.find("too large"), std::string::npos) << message;
  // The reader takes OS/2's magic numbers too: each was opened unchecked, and the decode asked for
  // the declared size.
  for (const std::string magic : {"BA", "CI", "CP", "PT"}) {
    std::string os2 = bytes;
    os2.replace(0, 2, magic);
    std::ofstream(folder / "wide_os2.bmp", std::ios::binary) << os2;
    const std::string refused =
        error_message_of<InputError>([&] { read_image(folder / "wide_os2.bmp", std::uint64_t{256} << 20); });
    EXPECT_NE(refused.find("536870917x4"), std::string::npos) << magic << ": " << refused;
  }
  put_u32(bytes, 18, 8);
  put_u32(bytes, 22, 0x80000000u);  // a height of INT32_MIN: top-down, and no absolute value in 32 bits
  std::ofstream(folder / "tall.bmp", std::ios::binary) << bytes;
  const std::string tall =
      error_message_of<InputError>([&] { read_image(folder / "tall.bmp", std::uint64_t{256} << 20); });
  EXPECT_NE(tall.find("8x2147483648"), std::string::npos) << tall;
}

}  // namespace image_header_checks_test
}  // namespace rtpro::test
