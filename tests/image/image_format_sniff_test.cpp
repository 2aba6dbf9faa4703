#include "image_format_sniff.h"

#include "test_paths.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace image_format_sniff_test {

using namespace std::string_literals;

TEST(ImageFormatSniff, KnownSignaturesNameTheirReader) {
  EXPECT_EQ(image_format_from_signature("\x76\x2f\x31\x01\x02\0\0\0"s), "openexr");
  EXPECT_EQ(image_format_from_signature("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR"s), "png");
  EXPECT_EQ(image_format_from_signature("\xff\xd8\xff\xe0\0\x10JFIF"s), "jpeg");
  EXPECT_EQ(image_format_from_signature("II*\0\x08\0\0\0"s), "tiff");
  EXPECT_EQ(image_format_from_signature("MM\0*\0\0\0\x08"s), "tiff");
  EXPECT_EQ(image_format_from_signature("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n"), "hdr");
  EXPECT_EQ(image_format_from_signature("P6\n4 4\n255\n"), "pnm");
  EXPECT_EQ(image_format_from_signature("Pf 4 4\n-1.0\n"), "pnm");
  EXPECT_EQ(image_format_from_signature("BM\x46\0\0\0"s), "bmp");
  EXPECT_EQ(image_format_from_signature("GIF89a\x01\0\x01\0"s), "gif");
}

TEST(ImageFormatSniff, TextAndShortHeadsNameNoReader) {
  EXPECT_EQ(image_format_from_signature(""), "");
  EXPECT_EQ(image_format_from_signature("this is not a PNG file at all"), "");
  EXPECT_EQ(image_format_from_signature("P7 is not netpbm"), "");
  EXPECT_EQ(image_format_from_signature("P6"), "");           // no separator yet: too short to trust
  EXPECT_EQ(image_format_from_signature("\x89PNG\r\n"), "");  // a cut signature
  // Formats read by their extension alone: DPX, WebP.
  EXPECT_EQ(image_format_from_signature("SDPX\0\0\x20\0"s), "");
  EXPECT_EQ(image_format_from_signature("RIFF\x24\0\0\0WEBPVP8 "s), "");
}

TEST(ImageFormatSniff, SignatureWinsOverTheExtension) {
  const auto file = test::write_file("really_png.exr", "\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR"s);
  EXPECT_EQ(image_reader_name(file), "png");
}

TEST(ImageFormatSniff, WithoutASignatureTheLowerCaseExtensionNamesTheReader) {
  EXPECT_EQ(image_reader_name(test::write_file("picture.TGA", "\0\0\x02\0\0\0\0\0"s)), "tga");
  EXPECT_EQ(image_reader_name(test::write_file("no_extension", "plain text")), "");
  EXPECT_EQ(image_reader_name(test::scratch_dir() / "missing.Png"), "png");
}

}  // namespace image_format_sniff_test
}  // namespace rtpro
