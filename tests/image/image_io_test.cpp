#include "rtpro/image/image_io.h"

#include "rtpro/core/error.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <Imath/half.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <functional>
#include <fstream>
#include <iterator>
#include <sys/resource.h>

namespace rtpro {
namespace image_io_test {

namespace fs = std::filesystem;
using namespace std::string_literals;

Image grey_image(int width, int height, float value) {
  Image image(width, height);
  std::fill(image.data.begin(), image.data.end(), value);
  return image;
}

// Values of every sign and magnitude, none of which a half-float or 8-bit path keeps exactly.
Image varied_image(int width, int height, std::vector<std::string> channels = {"R", "G", "B"}) {
  Image image(width, height, std::move(channels));
  std::uint32_t state = 12345;
  for (float& value : image.data) {
    state = state * 1664525u + 1013904223u;
    value = (static_cast<float>(state >> 8) / 16777216.0f - 0.25f) * 7.0f + 1e-7f;
  }
  return image;
}

std::vector<std::string> folder_listing(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

OIIO::ImageSpec spec_of(const fs::path& file) {
  const auto input = OIIO::ImageInput::open(file.string());
  EXPECT_TRUE(input) << OIIO::geterror();
  return input ? input->spec() : OIIO::ImageSpec();
}

std::string format_of(const fs::path& file) {
  const auto input = OIIO::ImageInput::open(file.string());
  return input ? input->format_name() : OIIO::geterror();
}

template <typename Error>
std::string error_message_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "the expected error was not thrown";
  return {};
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
  Image image = grey_image(2, 1, 0.5f);
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
  write_image(file, grey_image(2, 2, 0.5f), options);
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
  write_image(file, grey_image(3, 2, 0.18f), {});
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
  write_image(file, grey_image(2, 2, 0.18f), options);
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
  write_image(file, grey_image(16, 16, 0.18f), {});
  EXPECT_EQ(format_of(file), "jpeg") << "format chosen by extension, any case";
  const Image back = read_image(file);
  ASSERT_EQ(back.channel_count(), 3);
  for (float value : back.data) EXPECT_NEAR(value * 255.0f, 118.0f, 1.5f);
}

TEST(ImageIo, TiffIsSixteenBitDisplayReferred) {
  const auto file = test::scratch_dir() / "grey.tif";
  write_image(file, grey_image(3, 3, 0.18f), {});
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
  write_image(file, grey_image(1, 1, 0.25f), options);
  EXPECT_EQ(std::lround(read_image(file).data[0] * 255.0f), 128);  // 0.5 * 255 = 127.5
}

TEST(ImageIo, UnknownExtensionIsAnInputErrorAndCreatesNothing) {
  const auto folder = test::scratch_dir();
  const std::string message =
      error_message_of<InputError>([&] { write_image(folder / "picture.xyz", grey_image(2, 2, 0.5f), {}); });
  EXPECT_NE(message.find(".xyz"), std::string::npos) << message;
  EXPECT_TRUE(folder_listing(folder).empty());
  EXPECT_THROW(write_image(folder / "no_extension", grey_image(2, 2, 0.5f), {}), InputError);
  EXPECT_TRUE(folder_listing(folder).empty());
}

TEST(ImageIo, MissingFolderIsARuntimeErrorNamingIt) {
  const auto folder = test::scratch_dir() / "not" / "there";
  const std::string message =
      error_message_of<RuntimeError>([&] { write_image(folder / "out.png", grey_image(2, 2, 0.5f), {}); });
  EXPECT_NE(message.find(folder.string()), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(folder));
}

TEST(ImageIo, EmptyImageIsRefusedWithoutTouchingTheDisk) {
  const auto folder = test::scratch_dir();
  EXPECT_THROW(write_image(folder / "empty.exr", Image(0, 4), {}), RuntimeError);
  EXPECT_TRUE(folder_listing(folder).empty());
}

TEST(ImageIo, OverwritingReplacesTheFileAndLeavesNoTemporaryFile) {
  const auto folder = test::scratch_dir();
  write_image(folder / "out.exr", grey_image(2, 2, 0.25f), {});
  write_image(folder / "out.exr", grey_image(3, 1, 0.75f), {});
  EXPECT_EQ(folder_listing(folder), std::vector<std::string>{"out.exr"});
  EXPECT_EQ(read_image(folder / "out.exr").data, grey_image(3, 1, 0.75f).data);
}

TEST(ImageIo, BadViewLeavesTheExistingFileUntouched) {
  const auto folder = test::scratch_dir();
  write_image(folder / "out.png", grey_image(2, 2, 0.5f), {});
  const std::string before = file_bytes(folder / "out.png");
  ImageWriteOptions options;
  options.view = "No Such View";
  EXPECT_THROW(write_image(folder / "out.png", grey_image(2, 2, 0.9f), options), InputError);
  EXPECT_EQ(file_bytes(folder / "out.png"), before);
  EXPECT_EQ(folder_listing(folder), std::vector<std::string>{"out.png"});
}

// A failure in the middle of writing the pixels: the process may not grow any file past a few
// kilobytes (with SIGXFSZ ignored, write() then fails with EFBIG). Works as root too, unlike a
// read-only folder.
TEST(ImageIo, FailedWriteKeepsTheOldFileAndRemovesTheTemporaryOne) {
  const auto folder = test::scratch_dir();
  const auto target = folder / "render.exr";
  write_image(target, grey_image(4, 4, 0.5f), {});
  const std::string good = file_bytes(target);
  ASSERT_LT(good.size(), 4096u);

  const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit previous_limit{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &previous_limit), 0);
  rlimit small_limit = previous_limit;
  small_limit.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small_limit), 0);
  std::string message;
  try {
    write_image(target, varied_image(256, 256), {});  // about 700 kB of incompressible floats
  } catch (const RuntimeError& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &previous_limit);
  std::signal(SIGXFSZ, previous_handler);

  EXPECT_NE(message.find(target.string()), std::string::npos) << "expected a RuntimeError naming the file";
  EXPECT_EQ(file_bytes(target), good);
  EXPECT_EQ(folder_listing(folder), std::vector<std::string>{"render.exr"});
}

TEST(ImageIo, FailedRenameRemovesTheTemporaryFile) {
  const auto folder = test::scratch_dir();
  fs::create_directories(folder / "taken.png" / "inside");  // a non-empty folder cannot be replaced
  EXPECT_THROW(write_image(folder / "taken.png", grey_image(2, 2, 0.5f), {}), RuntimeError);
  EXPECT_EQ(folder_listing(folder), std::vector<std::string>{"taken.png"});
  EXPECT_TRUE(fs::is_directory(folder / "taken.png" / "inside"));
}

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
  write_image(folder / "real.png", grey_image(5, 3, 0.5f), {});
  std::ofstream(folder / "misnamed.exr", std::ios::binary) << file_bytes(folder / "real.png");
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
  for (const std::string& bytes : {huge_screen, huge_frame}) {
    const auto file = test::write_file("huge.gif", bytes);
    const std::string message = error_message_of<InputError>([&] { read_image(file, std::uint64_t{64} << 20); });
    EXPECT_NE(message.find("65535x65535"), std::string::npos) << message;
  }
}

// Writes `image` with OpenImageIO directly, in the layout `shape` gives the spec (tiles, a data
// window, per-channel types), as files from other programs come.
void write_with_oiio(const fs::path& file, const Image& image, OIIO::TypeDesc type,
                     const std::function<void(OIIO::ImageSpec&)>& shape) {
  OIIO::ImageSpec spec(image.width, image.height, static_cast<int>(image.channels.size()), type);
  spec.channelnames = image.channels;
  shape(spec);
  const auto output = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(output && output->open(file.string(), spec)) << OIIO::geterror();
  ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, image.data.data())) << output->geterror();
  ASSERT_TRUE(output->close());
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
  return file_bytes(file);
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
  const std::string written = file_bytes(folder / "caption.jpg");
  const std::size_t resource = written.find(std::string("8BIM\x04\x04", 6));
  ASSERT_NE(resource, std::string::npos) << "OpenImageIO wrote no IPTC block";
  const std::size_t segment = written.rfind("\xff\xed", resource);
  ASSERT_NE(segment, std::string::npos);

  std::string claims_more = written;  // the block's own size: 0xffff bytes of records
  claims_more[resource + 10] = '\xff';
  claims_more[resource + 11] = '\xff';
  std::ofstream(folder / "claims_more.jpg", std::ios::binary) << claims_more;
  EXPECT_THROW(read_image(folder / "claims_more.jpg"), InputError);

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

TEST(ImageIo, ReadingATruncatedExrIsAnInputError) {
  const auto folder = test::scratch_dir();
  write_image(folder / "whole.exr", varied_image(64, 64), {});
  const std::string bytes = file_bytes(folder / "whole.exr");
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
    std::string bytes = file_bytes(folder / "whole.exr");
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
  std::string bytes = file_bytes(folder / "tiled.exr");
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
  std::string bytes = file_bytes(folder / "tiled.exr");
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
  std::string bytes = file_bytes(folder / "small.exr");
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
  std::string bytes = file_bytes(folder / "small.bmp");
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
  put_u32(bytes, 18, 8);
  put_u32(bytes, 22, 0x80000000u);  // a height of INT32_MIN: top-down, and no absolute value in 32 bits
  std::ofstream(folder / "tall.bmp", std::ios::binary) << bytes;
  const std::string tall =
      error_message_of<InputError>([&] { read_image(folder / "tall.bmp", std::uint64_t{256} << 20); });
  EXPECT_NE(tall.find("8x2147483648"), std::string::npos) << tall;
}

}  // namespace image_io_test
}  // namespace rtpro
