// EXR read through OpenEXR without OpenImageIO: OpenImageIO's image bit for bit where it reads,
// OpenImageIO's own reader (and its messages) everywhere else.
#include "exr_input.h"

#include "image_read_budget.h"
#include "rtpro/core/error.h"
#include "rtpro/image/image_io.h"
#include "test_paths.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfTiledOutputFile.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace rtpro {
namespace {

struct Layout {
  std::vector<std::string> channels;  // as stored
  Imf::PixelType type = Imf::HALF;
  Imf::Compression compression = Imf::ZIP_COMPRESSION;
  bool tiled = false;
  Imath::V2i origin{0, 0};
};

// A w×h EXR of `layout` whose values cover what a half or float holds: ordinary values, tiny and
// huge ones, zeros of both signs, infinities and a NaN. Every channel differs from the others.
void write_exr(const std::filesystem::path& file, int w, int h, const Layout& layout) {
  Imf::Header header(Imath::Box2i(layout.origin, layout.origin + Imath::V2i(w - 1, h - 1)),
                     Imath::Box2i(layout.origin, layout.origin + Imath::V2i(w - 1, h - 1)));
  header.compression() = layout.compression;
  for (const std::string& name : layout.channels) header.channels().insert(name, Imf::Channel(layout.type));
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::vector<std::vector<float>> floats(layout.channels.size(), std::vector<float>(n));
  std::vector<std::vector<half>> halves(layout.channels.size(), std::vector<half>(n));
  const float specials[] = {0.0f,
                            -0.0f,
                            1e-6f,
                            65504.0f,
                            3e38f,
                            std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()};
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < layout.channels.size(); ++c) {
    for (std::size_t i = 0; i < n; ++i) {
      const float value = i % 7 == 0 ? specials[(i / 7 + c) % 8] : std::sin(0.37f * float(i) + float(c)) * 4.0f;
      floats[c][i] = value;
      halves[c][i] = half(value);
    }
    void* base = layout.type == Imf::HALF ? static_cast<void*>(halves[c].data()) : floats[c].data();
    const std::size_t size = layout.type == Imf::HALF ? sizeof(half) : sizeof(float);
    frame.insert(layout.channels[c], Imf::Slice::Make(layout.type, base, header.dataWindow(), size, size * w));
  }
  if (layout.tiled) {
    header.setTileDescription(Imf::TileDescription(16, 8));
    Imf::TiledOutputFile out(file.c_str(), header);
    out.setFrameBuffer(frame);
    out.writeTiles(0, out.numXTiles() - 1, 0, out.numYTiles() - 1);
  } else {
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(h);
  }
}

// OpenImageIO's image of the file (read_image_counting is its path alone).
Image read_with_openimageio(const std::filesystem::path& file) { return read_image_counting(file, 0, 0, ""); }

void expect_identical(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.channels, b.channels);
  ASSERT_EQ(a.data.size(), b.data.size());
  EXPECT_EQ(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)), 0);
}

TEST(ExrInput, PlainColourExrsAreOpenImageIOsImagesBitForBit) {
  const std::vector<Layout> layouts = {
      {{"R", "G", "B"}, Imf::HALF, Imf::ZIP_COMPRESSION, false, {0, 0}},
      {{"R", "G", "B", "A"}, Imf::FLOAT, Imf::PIZ_COMPRESSION, false, {0, 0}},
      {{"A", "B", "G", "R"}, Imf::HALF, Imf::NO_COMPRESSION, true, {0, 0}},
      {{"B", "G", "R"}, Imf::FLOAT, Imf::ZIPS_COMPRESSION, true, {0, 0}},
      {{"R", "G", "B"}, Imf::HALF, Imf::PIZ_COMPRESSION, false, {-7, 12}},  // a data window off the origin
  };
  const auto folder = test::scratch_dir();
  int k = 0;
  for (const Layout& layout : layouts) {
    SCOPED_TRACE(k);
    const auto file = folder / ("plain" + std::to_string(k++) + ".exr");
    // 301 rows: more than one band of rows, and a last band cut short.
    write_exr(file, 53, 301, layout);
    const std::optional<Image> direct = read_exr_without_openimageio(file, 0);
    ASSERT_TRUE(direct.has_value());
    expect_identical(*direct, read_with_openimageio(file));
    expect_identical(read_image(file), *direct);
  }
}

TEST(ExrInput, OtherLayoutsAreLeftToOpenImageIO) {
  const std::vector<Layout> layouts = {
      {{"Y"}, Imf::HALF},                  // luminance
      {{"R", "G", "B", "Z"}, Imf::FLOAT},  // a depth channel
      {{"R", "G"}, Imf::HALF},             // two channels
      {{"R", "G", "B"}, Imf::UINT},        // integers: OpenImageIO decides their scale
  };
  const auto folder = test::scratch_dir();
  int k = 0;
  for (const Layout& layout : layouts) {
    SCOPED_TRACE(k);
    const auto file = folder / ("other" + std::to_string(k++) + ".exr");
    write_exr(file, 9, 5, layout);
    EXPECT_FALSE(read_exr_without_openimageio(file, 0).has_value());
    expect_identical(read_image(file), read_with_openimageio(file));
  }
  // Not an EXR at all.
  const auto text = folder / "not.exr";
  std::ofstream(text) << "not an image";
  EXPECT_FALSE(read_exr_without_openimageio(text, 0).has_value());
  EXPECT_FALSE(has_exr_signature(text));
}

// A file OpenEXR fails on, or one over the budget, goes to OpenImageIO, whose error names it.
TEST(ExrInput, ATruncatedOrTooLargeExrGetsOpenImageIOsErrorNamingTheFile) {
  const auto folder = test::scratch_dir();
  const auto whole = folder / "whole.exr";
  write_exr(whole, 64, 64, {{"R", "G", "B"}, Imf::FLOAT, Imf::NO_COMPRESSION});
  const auto cut = folder / "cut.exr";
  {
    std::ifstream in(whole, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() * 2 / 3);
  }
  EXPECT_FALSE(read_exr_without_openimageio(cut, 0).has_value());
  try {
    read_image(cut);
    FAIL() << "a truncated EXR was read";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(cut.string()), std::string::npos) << error.what();
  }
  // 64x64 RGB floats are 48 KiB; OpenEXR's band of 256 rows counts too, as OpenImageIO's path counts it.
  EXPECT_FALSE(read_exr_without_openimageio(whole, 100000).has_value());
  EXPECT_TRUE(read_exr_without_openimageio(whole, 300000).has_value());
  EXPECT_THROW(read_image(whole, 100000), InputError);
}

TEST(ExrInput, AMissingFileOrAFolderIsAnInputErrorBeforeOpenEXROpensIt) {
  const auto folder = test::scratch_dir();
  EXPECT_THROW(read_exr_without_openimageio(folder / "missing.exr", 0), InputError);
  EXPECT_THROW(read_exr_without_openimageio(folder, 0), InputError);
}

}  // namespace
}  // namespace rtpro
