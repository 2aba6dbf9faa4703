#include "png_output.h"

#include "display_encoding.h"
#include "rtpro/core/error.h"
#include "rtpro/image/image_io.h"
#include "test_paths.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rtpro {
namespace png_output_test {

namespace fs = std::filesystem;

// A ramp in every channel, with values past both ends of [0, 1] and a NaN.
Image ramp_image(int width, int height, std::vector<std::string> channels) {
  Image image(width, height, std::move(channels));
  for (std::size_t i = 0; i < image.data.size(); ++i) image.data[i] = -0.2f + 0.013f * static_cast<float>(i % 101);
  image.data[4] = std::numeric_limits<float>::quiet_NaN();
  image.data[5] = std::numeric_limits<float>::infinity();
  return image;
}

struct Chunk {
  std::string type, data;
  bool operator==(const Chunk&) const = default;
};

// The file's chunks in order, the IDAT chunks' data joined and inflated into one "pixels" chunk.
std::vector<Chunk> chunks_of(const fs::path& file) {
  const std::string bytes = test::read_file(file);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  std::vector<Chunk> chunks;
  std::string compressed;
  for (std::size_t at = 8; at + 12 <= bytes.size();) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + at);
    const std::size_t length = std::size_t{b[0]} << 24 | std::size_t{b[1]} << 16 | std::size_t{b[2]} << 8 | b[3];
    Chunk chunk{bytes.substr(at + 4, 4), bytes.substr(at + 8, length)};
    at += 12 + length;
    if (chunk.type != "IDAT") {
      chunks.push_back(std::move(chunk));
      continue;
    }
    if (compressed.empty()) chunks.push_back({"pixels", ""});
    compressed += chunk.data;
  }
  for (Chunk& chunk : chunks) {
    if (chunk.type != "pixels") continue;
    uLongf size = 1 << 20;
    chunk.data.resize(size);
    EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(chunk.data.data()), &size,
                         reinterpret_cast<const Bytef*>(compressed.data()), compressed.size()),
              Z_OK);
    chunk.data.resize(size);
  }
  return chunks;
}

std::vector<std::string> types_of(const std::vector<Chunk>& chunks) {
  std::vector<std::string> types;
  for (const Chunk& chunk : chunks) types.push_back(chunk.type);
  return types;
}

// What rtpro wrote through OpenImageIO's PNG writer before libpng was called directly: the same
// codes, the sRGB tag for an sRGB display, and the metadata as attributes.
void write_through_openimageio(const fs::path& file, const Image& image, const ImageWriteOptions& options,
                               const std::vector<std::pair<std::string, std::string>>& metadata) {
  const DisplayEncoding display = display_encoding(options);
  const std::vector<std::uint8_t> codes = encode_for_display_8bit(image, display.transform);
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  if (display.srgb) spec.attribute("oiio:ColorSpace", "sRGB");
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  const auto output = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(output && output->open(file.string(), spec)) << OIIO::geterror();
  ASSERT_TRUE(output->write_image(OIIO::TypeDesc::UINT8, codes.data()));
  ASSERT_TRUE(output->close());
}

// Chunk for chunk what OpenImageIO 2.4 wrote for the same image and metadata: sRGB with gAMA and
// cHRM, oFFs, DateTime as tIME, the entries as tEXt under PNG's keywords where OpenImageIO maps
// them (Description, Author), and the same filtered rows.
TEST(PngOutput, IsWhatOpenImageIoWroteForTheSameImage) {
  const Image image = ramp_image(37, 23, {"R", "G", "B", "A", "N.X"});
  ImageWriteOptions options;
  options.metadata = {{"DateTime", "2026:01:02 03:04:05"},
                      {"rtpro:backend", "embree"},
                      {"Software", "rtpro test"},
                      {"Artist", "the test"},
                      {"Copyright", "none"}};
  const auto folder = test::scratch_dir();
  write_png(folder / "libpng.png", image, options);
  write_through_openimageio(folder / "openimageio.png", image, options,
                            {{"Software", "rtpro test"},
                             {"ImageDescription", display_encoding(options).description},
                             {"DateTime", "2026:01:02 03:04:05"},
                             {"rtpro:backend", "embree"},
                             {"Artist", "the test"},
                             {"Copyright", "none"}});

  const std::vector<Chunk> ours = chunks_of(folder / "libpng.png");
  EXPECT_EQ(ours, chunks_of(folder / "openimageio.png"));
  EXPECT_EQ(types_of(ours), (std::vector<std::string>{"IHDR", "gAMA", "sRGB", "cHRM", "oFFs", "tIME", "tEXt", "tEXt",
                                                      "tEXt", "tEXt", "tEXt", "tEXt", "pixels", "IEND"}));
  const auto input = OIIO::ImageInput::open((folder / "libpng.png").string());
  ASSERT_TRUE(input) << OIIO::geterror();
  EXPECT_EQ(input->spec().get_string_attribute("DateTime"), "2026:01:02 03:04:05");
  EXPECT_EQ(input->spec().get_string_attribute("Artist"), "the test");
  EXPECT_EQ(input->spec().get_string_attribute("rtpro:backend"), "embree");
  EXPECT_NE(input->spec().get_string_attribute("ImageDescription").find("display \"sRGB\""), std::string::npos);
}

// The codes are the display encoding's, row by row, whatever the view: read back through
// OpenImageIO, each pixel is the 8-bit code of the first three channels (grey for one channel).
TEST(PngOutput, PixelsAreTheDisplayEncodingsCodes) {
  for (const char* view : {"Standard", "ACES 1.0 SDR-video", "Raw"}) {
    for (const std::vector<std::string>& channels :
         {std::vector<std::string>{"Y"}, std::vector<std::string>{"R", "G", "B", "A", "Z"}}) {
      SCOPED_TRACE(std::string(view) + ", " + std::to_string(channels.size()) + " channels");
      const Image image = ramp_image(19, 11, channels);
      ImageWriteOptions options;
      options.view = view;
      const auto file = test::scratch_dir() / "codes.png";
      write_png(file, image, options);
      const std::vector<std::uint8_t> expected = encode_for_display_8bit(image, display_encoding(options).transform);
      const auto input = OIIO::ImageInput::open(file.string());
      ASSERT_TRUE(input) << OIIO::geterror();
      ASSERT_EQ(input->spec().nchannels, 3);
      ASSERT_EQ(input->spec().format, OIIO::TypeDesc::UINT8);
      std::vector<std::uint8_t> codes(expected.size());
      ASSERT_TRUE(input->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, codes.data()));
      EXPECT_EQ(codes, expected);
    }
  }
}

// A code is the value's rounding to the nearest code, halves away from zero (lround's), also for
// the floats nearest the halfway points; out-of-range values, infinities and NaN clamp.
TEST(PngOutput, CodesRoundAsLroundDoes) {
  std::vector<float> values{0.0f,
                            1.0f,
                            -0.0f,
                            -1.0f,
                            2.0f,
                            std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()};
  for (const float top : {255.0f, 65535.0f})
    for (int code = 0; code < 256; ++code) {
      const float half = (static_cast<float>(code) + 0.5f) / top;
      values.insert(values.end(), {std::nextafter(half, 0.0f), half, std::nextafter(half, 1.0f)});
    }
  Image image(static_cast<int>(values.size()), 1, {"R", "G", "B"});
  for (std::size_t i = 0; i < values.size(); ++i)
    image.data[3 * i] = image.data[3 * i + 1] = image.data[3 * i + 2] = values[i];
  ImageWriteOptions options;
  options.view = "Raw";
  const DisplayTransform raw = display_encoding(options).transform;
  const std::vector<std::uint8_t> codes8 = encode_for_display_8bit(image, raw);
  const std::vector<std::uint16_t> codes16 = encode_for_display_16bit(image, raw);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const float clamped = values[i] > 0.0f ? std::min(values[i], 1.0f) : 0.0f;
    EXPECT_EQ(codes8[3 * i], std::lround(clamped * 255.0f)) << values[i];
    EXPECT_EQ(codes16[3 * i], std::lround(clamped * 65535.0f)) << values[i];
  }
}

// libpng's own refusal (a text chunk needs a keyword) is an error naming the file, and the file
// already there stays as it was.
TEST(PngOutput, RefusalsNameTheFileAndKeepTheOldOne) {
  const auto file = test::write_file("kept.png", "the old contents");
  ImageWriteOptions nameless;
  nameless.metadata = {{"", "a value without a name"}};
  try {
    write_png(file, ramp_image(4, 3, {"R", "G", "B"}), nameless);
    ADD_FAILURE() << "a nameless text chunk was written";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("keyword"), std::string::npos) << e.what();
  }
  Image inconsistent = ramp_image(4, 3, {"R", "G", "B"});
  inconsistent.data.pop_back();
  EXPECT_THROW(write_png(file, inconsistent, {}), RuntimeError);
  ImageWriteOptions unknown_view;
  unknown_view.view = "no such view";
  EXPECT_THROW(write_png(file, ramp_image(4, 3, {"R", "G", "B"}), unknown_view), InputError);
  EXPECT_EQ(test::read_file(file), "the old contents");
  EXPECT_EQ(std::distance(fs::directory_iterator(file.parent_path()), fs::directory_iterator()), 1);
}

TEST(PngOutput, KnowsItsFilesByExtensionInAnyCase) {
  EXPECT_TRUE(is_png_file("a.png"));
  EXPECT_TRUE(is_png_file("dir.exr/A.PNG"));
  EXPECT_FALSE(is_png_file("a.png.exr"));
  EXPECT_FALSE(is_png_file("png"));
}

}  // namespace png_output_test
}  // namespace rtpro
