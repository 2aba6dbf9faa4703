#include "exr_output.h"

#include "rtpro/core/error.h"
#include "rtpro/image/image_io.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfVersion.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>

namespace rtpro {
namespace exr_output_test {

namespace fs = std::filesystem;

// Every kind of float a film can hold: signed zeros, denormals, huge values, infinities, NaN.
Image every_kind_of_float(int width, int height, std::vector<std::string> channels) {
  Image image(width, height, std::move(channels));
  const float specials[] = {0.0f,
                            -0.0f,
                            std::numeric_limits<float>::denorm_min(),
                            -1e-40f,
                            1e30f,
                            std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN(),
                            0.18f,
                            -3.5f};
  std::uint32_t state = 7;
  for (std::size_t i = 0; i < image.data.size(); ++i) {
    state = state * 1664525u + 1013904223u;
    image.data[i] = i % 3 == 0 ? specials[(i / 3) % std::size(specials)] : std::bit_cast<float>(state & 0xBF7FFFFFu);
  }
  return image;
}

std::map<std::string, std::string> attributes_of(const fs::path& file) {
  const auto input = OIIO::ImageInput::open(file.string());
  EXPECT_TRUE(input) << OIIO::geterror();
  std::map<std::string, std::string> attributes;
  if (!input) return attributes;
  for (const OIIO::ParamValue& p : input->spec().extra_attribs)
    if (p.name() != "DateTime") attributes[p.name().string()] = p.get_string();
  return attributes;
}

// The file's own attribute names and types, as OpenEXR reads them (OpenImageIO renames some).
std::map<std::string, std::string> raw_attributes_of(const fs::path& file) {
  Imf::InputFile input(file.c_str());
  std::map<std::string, std::string> attributes;
  for (auto it = input.header().begin(); it != input.header().end(); ++it)
    attributes[it.name()] = it.attribute().typeName();
  return attributes;
}

TEST(ExrOutput, EveryChannelReadsBackBitForBit) {
  const auto file = test::scratch_dir() / "every_float.exr";
  const std::vector<std::string> names = {"R", "G", "B", "A", "N.X", "Z"};
  const Image image = every_kind_of_float(13, 7, names);
  write_exr(file, image, {});
  test::expect_same_channels(image, read_image(file));
}

// Chunks of 16 scanlines, the last one short, each holding its channels in the file's (sorted)
// order: an image whose channels are not in that order, and whose rows differ, reads back whole.
TEST(ExrOutput, ManyChunksReadBackBitForBitInEveryChannel) {
  const auto file = test::scratch_dir() / "many_chunks.exr";
  const Image image = every_kind_of_float(37, 53, {"R", "G", "B", "albedo.R", "N.X", "depth.Z", "A"});
  write_exr(file, image, {});
  test::expect_same_channels(image, read_image(file));

  Imf::InputFile input(file.c_str());
  EXPECT_EQ(input.header().compression(), Imf::ZIP_COMPRESSION);
  const Imath::Box2i window = input.header().dataWindow();
  EXPECT_EQ(window.max.x - window.min.x + 1, 37);
  EXPECT_EQ(window.max.y - window.min.y + 1, 53);
}

// The version field after the magic number: format version 2 and its flags.
std::int32_t version_field(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  char bytes[8] = {};
  in.read(bytes, sizeof bytes);
  std::int32_t version = 0;
  std::memcpy(&version, bytes + 4, sizeof version);
  return version;
}

// A name longer than 31 bytes needs the file's long-names flag (the format's rule; readers before
// OpenEXR 1.7 refuse such files), which OpenEXR's own writer sets only then.
TEST(ExrOutput, LongAttributeNamesAreFlaggedAndReadable) {
  const auto file = test::scratch_dir() / "long_names.exr";
  ImageWriteOptions options;
  const std::string name = "rtpro:a_rather_long_attribute_name_for_a_test";
  options.metadata = {{name, "kept"}};
  write_exr(file, every_kind_of_float(3, 2, {"R", "G", "B"}), options);
  EXPECT_EQ(version_field(file), Imf::EXR_VERSION | Imf::LONG_NAMES_FLAG);
  EXPECT_EQ(attributes_of(file).at(name), "kept");
  EXPECT_EQ(raw_attributes_of(file).at(name), "string");

  const auto short_names = test::scratch_dir() / "short_names.exr";
  write_exr(short_names, every_kind_of_float(3, 2, {"R", "G", "B"}), {});
  EXPECT_EQ(version_field(short_names), Imf::EXR_VERSION);
}

// OpenEXR writes what OpenImageIO's EXR writer wrote for rtpro: the same pixel type, compression,
// primaries and metadata, read back by OpenImageIO under the same names.
TEST(ExrOutput, ReadsBackAsOpenImageIoWroteTheSameImage) {
  const Image image = every_kind_of_float(5, 4, {"R", "G", "B"});
  ImageWriteOptions options;
  options.metadata = {{"rtpro:backend", "embree"}, {"Software", "rtpro test"}, {"Copyright", "the test"}};

  const auto folder = test::scratch_dir();
  const auto ours = folder / "openexr.exr";
  write_exr(ours, image, options);

  const auto theirs = folder / "openimageio.exr";
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  static constexpr float kRec709[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
  spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), kRec709);
  spec.attribute("rtpro:colorspace", "Linear Rec.709 (sRGB)");
  spec.attribute("compression", "zip");
  spec.attribute("Software", "rtpro test");
  spec.attribute("ImageDescription", "rtpro image, scene-linear Rec.709 primaries");
  spec.attribute("DateTime", "2026:01:01 00:00:00");
  spec.attribute("rtpro:backend", "embree");
  spec.attribute("Copyright", "the test");
  const auto output = OIIO::ImageOutput::create(theirs.string());
  ASSERT_TRUE(output && output->open(theirs.string(), spec)) << OIIO::geterror();
  ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, image.data.data()));
  ASSERT_TRUE(output->close());

  EXPECT_EQ(attributes_of(ours), attributes_of(theirs));
  // The same names in the file as well: EXR's standard ones where OpenImageIO uses them.
  EXPECT_EQ(raw_attributes_of(ours), raw_attributes_of(theirs));
  EXPECT_EQ(raw_attributes_of(ours).at("comments"), "string");
  EXPECT_EQ(raw_attributes_of(ours).at("capDate"), "string");
  EXPECT_EQ(raw_attributes_of(ours).at("owner"), "string");
  EXPECT_EQ(attributes_of(ours).at("compression"), "zip");
  EXPECT_EQ(attributes_of(ours).at("Copyright"), "the test");
  const auto input = OIIO::ImageInput::open(ours.string());
  ASSERT_TRUE(input);
  EXPECT_EQ(input->spec().format, OIIO::TypeDesc::FLOAT);
  EXPECT_FALSE(input->spec().get_string_attribute("DateTime").empty());
}

TEST(ExrOutput, RefusesWhatItCannotWriteAndKeepsTheOldFile) {
  const auto file = test::write_file("kept.exr", "the old contents");
  Image repeated = every_kind_of_float(2, 2, {"R", "G", "G"});
  EXPECT_THROW(write_exr(file, repeated, {}), RuntimeError);
  Image unnamed = every_kind_of_float(2, 2, {"R", "", "B"});
  EXPECT_THROW(write_exr(file, unnamed, {}), RuntimeError);
  Image inconsistent = every_kind_of_float(2, 2, {"R", "G", "B"});
  inconsistent.data.pop_back();
  EXPECT_THROW(write_exr(file, inconsistent, {}), RuntimeError);
  EXPECT_THROW(write_exr(file, Image{}, {}), RuntimeError);
  EXPECT_EQ(test::read_file(file), "the old contents");
}

TEST(ExrOutput, KnowsTheFormatsNamesInAnyCase) {
  EXPECT_TRUE(is_exr_file("a.exr"));
  EXPECT_TRUE(is_exr_file("dir.png/a.EXR"));
  EXPECT_TRUE(is_exr_file("a.sxr"));
  EXPECT_TRUE(is_exr_file("a.mxr"));
  EXPECT_FALSE(is_exr_file("a.exr.png"));
  EXPECT_FALSE(is_exr_file("exr"));
  EXPECT_FALSE(is_exr_file("a.hdr"));
}

}  // namespace exr_output_test
}  // namespace rtpro
