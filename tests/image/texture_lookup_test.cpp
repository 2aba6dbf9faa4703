// Image textures through OpenImageIO's TextureSystem: rtpro's lookups against OpenImageIO's own
// texture() on the same file, known pixels of a made-up image, sRGB decoding through OpenColorIO.
#include "rtpro/core/error.h"
#include "rtpro/image/texture_lookup.h"
#include "test_paths.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/texture.h>

#include <gtest/gtest.h>

#include <zlib.h>

#include <cmath>
#include <fstream>
#include <string>

namespace rtpro {
namespace texture_lookup_test {

// A width x height float EXR whose pixel (x, y) is (x / width, y / height, 0.25) + 0.001 x y.
std::filesystem::path write_ramp(const std::string& name, int width, int height) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float pixel[3] = {float(x) / float(width) + 0.001f * float(x * y), float(y) / float(height), 0.25f};
      image.setpixel(x, y, pixel);
    }
  const auto file = test::scratch_dir() / name;
  EXPECT_TRUE(image.write(file.string()));
  return file;
}

const TextureSampling kClamped{TextureWrap::kClamp, TextureWrap::kClamp, TextureFilter::kLinear};

TEST(TextureLookup, TexelCentresGiveTheMadeUpImagesPixels) {
  const auto file = write_ramp("ramp.exr", 8, 4);
  const std::vector<TextureSource> sources{{file, "Linear Rec.709 (sRGB)"}};
  const auto textures = open_textures(sources);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) {
      const Color c = textures->lookup(0, (float(x) + 0.5f) / 8.0f, (float(y) + 0.5f) / 4.0f, kClamped);
      EXPECT_NEAR(c.x, float(x) / 8.0f + 0.001f * float(x * y), 1e-6f) << x << "," << y;
      EXPECT_NEAR(c.y, float(y) / 4.0f, 1e-6f);
      EXPECT_NEAR(c.z, 0.25f, 1e-6f);
    }
}

TEST(TextureLookup, MatchesOpenImageIOsOwnTextureCallOnTheSameFile) {
  const auto file = write_ramp("ramp.exr", 16, 16);
  const std::vector<TextureSource> sources{{file, "Linear Rec.709 (sRGB)"}};
  const auto textures = open_textures(sources);
  // OpenImageIO's shared system, never destroyed: 2.4.7's destroy() has a sized-delete mismatch
  // (see src/image/texture_lookup.cpp).
  OIIO::TextureSystem* system = OIIO::TextureSystem::create(true);
  for (const TextureWrap wrap : {TextureWrap::kRepeat, TextureWrap::kClamp, TextureWrap::kMirror, TextureWrap::kBlack})
    for (const auto& [s, t] : {std::pair{0.3f, 0.7f}, {0.01f, 0.99f}, {1.37f, -0.2f}, {-0.6f, 2.45f}}) {
      OIIO::TextureOpt options;
      options.swrap = options.twrap = wrap == TextureWrap::kRepeat   ? OIIO::TextureOpt::WrapPeriodic
                                      : wrap == TextureWrap::kClamp  ? OIIO::TextureOpt::WrapClamp
                                      : wrap == TextureWrap::kMirror ? OIIO::TextureOpt::WrapMirror
                                                                     : OIIO::TextureOpt::WrapBlack;
      options.interpmode = OIIO::TextureOpt::InterpBilinear;
      float expected[3];
      ASSERT_TRUE(system->texture(OIIO::ustring(file.string()), options, s, t, 0, 0, 0, 0, 3, expected));
      const Color c = textures->lookup(0, s, t, TextureSampling{wrap, wrap, TextureFilter::kLinear});
      EXPECT_NEAR(c.x, expected[0], 1e-5f) << s << "," << t << " wrap " << int(wrap);
      EXPECT_NEAR(c.y, expected[1], 1e-5f);
      EXPECT_NEAR(c.z, expected[2], 1e-5f);
    }
}

// Each axis wraps as its own mode says, and the nearest filter gives a texel's own value where
// bilinear blends it with its neighbour (glTF samplers: wrapS, wrapT, magFilter).
TEST(TextureLookup, WrapsPerAxisAndFiltersNearestOrLinear) {
  const auto file = write_ramp("ramp.exr", 8, 4);  // red 0.125 x (+ 0.001 x y), green 0.25 y
  const std::vector<TextureSource> sources{{file, "Linear Rec.709 (sRGB)"}};
  const auto textures = open_textures(sources);
  const TextureSampling mirror_clamp{TextureWrap::kMirror, TextureWrap::kClamp, TextureFilter::kLinear};
  // s = -0.1875 mirrors onto 0.1875 (texel 1's centre); t = 1.625 clamps to the last row.
  const Color c = textures->lookup(0, -0.1875f, 1.625f, mirror_clamp);
  EXPECT_NEAR(c.x, 0.125f + 0.001f * 3.0f, 1e-6f);
  EXPECT_NEAR(c.y, 0.75f, 1e-6f);
  const TextureSampling repeat_mirror{TextureWrap::kRepeat, TextureWrap::kMirror, TextureFilter::kLinear};
  // s = 1.1875 repeats onto 0.1875; t = 1.125 mirrors onto 0.875 (row 3's centre).
  const Color d = textures->lookup(0, 1.1875f, 1.125f, repeat_mirror);
  EXPECT_NEAR(d.x, 0.125f + 0.001f * 3.0f, 1e-6f);
  EXPECT_NEAR(d.y, 0.75f, 1e-6f);
  // On the border of texels 1 and 2 (s = 0.25), bilinear gives their mean, nearest one of them.
  TextureSampling nearest = kClamped;
  nearest.filter = TextureFilter::kNearest;
  const float blended = textures->lookup(0, 0.25f - 1e-4f, 0.125f, kClamped).x;
  const float picked = textures->lookup(0, 0.25f - 1e-4f, 0.125f, nearest).x;
  EXPECT_NEAR(blended, 0.1875f, 1e-3f);
  EXPECT_NEAR(picked, 0.125f, 1e-6f);
}

TEST(TextureLookup, SrgbTexturesAreDecodedToLinearThroughOpenColorIO) {
  OIIO::ImageBuf image(OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::UINT8));
  const float grey[3] = {128.0f / 255.0f, 128.0f / 255.0f, 128.0f / 255.0f};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) image.setpixel(x, y, grey);
  const auto file = test::scratch_dir() / "grey.png";
  ASSERT_TRUE(image.write(file.string()));
  const double encoded = 128.0 / 255.0;
  const double linear = std::pow((encoded + 0.055) / 1.055, 2.4);  // the sRGB EOTF: 0.2158605
  const std::vector<TextureSource> sources{{file, "sRGB - Texture"}, {file, "Linear Rec.709 (sRGB)"}};
  const auto textures = open_textures(sources);
  EXPECT_NEAR(textures->lookup(0, 0.5f, 0.5f, kClamped).x, linear, 1e-5);
  EXPECT_NEAR(textures->lookup(1, 0.5f, 0.5f, kClamped).x, encoded, 1e-5);
}

TEST(TextureLookup, UnreadableTexturesAreInputErrorsNamingTheFile) {
  const auto file = test::write_file("not-an-image.png", "this is text");
  const std::vector<TextureSource> sources{{file, "sRGB - Texture"}};
  try {
    open_textures(sources);
    FAIL() << "a text file was opened as a texture";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
  const std::vector<TextureSource> unknown_space{{write_ramp("r.exr", 2, 2), "no such colour space"}};
  EXPECT_THROW(open_textures(unknown_space), InputError);
}

// A PNG whose header declares width x height RGB pixels, with one compressed row of data.
std::filesystem::path write_declared_png(const std::string& name, std::uint32_t width, std::uint32_t height) {
  const auto be32 = [](std::uint32_t v) {
    return std::string{char(v >> 24), char(v >> 16 & 0xff), char(v >> 8 & 0xff), char(v & 0xff)};
  };
  const auto chunk = [&](const std::string& type, const std::string& data) {
    const std::string body = type + data;
    return be32(std::uint32_t(data.size())) + body +
           be32(std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
  };
  const std::string header = be32(width) + be32(height) + std::string{8, 2, 0, 0, 0};  // 8-bit RGB
  const std::string row(1 + 3 * std::size_t(width), '\0');
  std::string compressed(compressBound(uLong(row.size())), '\0');
  uLongf size = uLongf(compressed.size());
  compress(reinterpret_cast<Bytef*>(compressed.data()), &size, reinterpret_cast<const Bytef*>(row.data()),
           uLong(row.size()));
  compressed.resize(size);
  return test::write_file(name, std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", header) +
                                    chunk("IDAT", compressed) + chunk("IEND", ""));
}

// A 0.8 MB PNG declaring 16384x16384 pixels took 7.2 GB and a minute: the decoded image fitted
// the budget, its texture copies did not. Counted from the header now, before decoding.
TEST(TextureLookup, ATextureWhoseCopiesExceedTheBudgetIsRefusedFromItsHeader) {
  const auto file = write_declared_png("huge.png", 16384, 12000);
  const std::vector<TextureSource> sources{{file, "sRGB - Texture"}};
  try {
    open_textures(sources);
    FAIL() << "a texture of 16384x12000 was prepared";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, file.string());
    EXPECT_NE(e.message().find("16384x12000, 3 channels"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("with its linear and mip-mapped texture copies; the limit is"), std::string::npos)
        << e.message();
  }
}

}  // namespace texture_lookup_test
}  // namespace rtpro
