// Image textures through OpenImageIO's TextureSystem: rtpro's lookups against OpenImageIO's own
// texture() on the same file, known pixels of a made-up image, sRGB decoding through OpenColorIO.
#include "rtpro/core/error.h"
#include "rtpro/image/texture_lookup.h"
#include "test_paths.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/texture.h>

#include <gtest/gtest.h>

#include <cmath>

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

TEST(TextureLookup, TexelCentresGiveTheMadeUpImagesPixels) {
  const auto file = write_ramp("ramp.exr", 8, 4);
  const std::vector<TextureSource> sources{{file, "Linear Rec.709 (sRGB)"}};
  const auto textures = open_textures(sources);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) {
      const Color c = textures->lookup(0, (float(x) + 0.5f) / 8.0f, (float(y) + 0.5f) / 4.0f, TextureWrap::kClamp);
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
      options.swrap = options.twrap = wrap == TextureWrap::kRepeat  ? OIIO::TextureOpt::WrapPeriodic
                                      : wrap == TextureWrap::kClamp ? OIIO::TextureOpt::WrapClamp
                                      : wrap == TextureWrap::kMirror ? OIIO::TextureOpt::WrapMirror
                                                                     : OIIO::TextureOpt::WrapBlack;
      options.interpmode = OIIO::TextureOpt::InterpBilinear;
      float expected[3];
      ASSERT_TRUE(system->texture(OIIO::ustring(file.string()), options, s, t, 0, 0, 0, 0, 3, expected));
      const Color c = textures->lookup(0, s, t, wrap);
      EXPECT_NEAR(c.x, expected[0], 1e-5f) << s << "," << t << " wrap " << int(wrap);
      EXPECT_NEAR(c.y, expected[1], 1e-5f);
      EXPECT_NEAR(c.z, expected[2], 1e-5f);
    }
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
  EXPECT_NEAR(textures->lookup(0, 0.5f, 0.5f, TextureWrap::kClamp).x, linear, 1e-5);
  EXPECT_NEAR(textures->lookup(1, 0.5f, 0.5f, TextureWrap::kClamp).x, encoded, 1e-5);
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

}  // namespace texture_lookup_test
}  // namespace rtpro
