#include "rtpro/image/color_config.h"

#include "rtpro/core/error.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rtpro {
namespace color_config_test {

using test::error_message_of;

// A config whose only view doubles the values, so a test can tell it was really used.
constexpr const char* kDoublingConfig = R"(ocio_profile_version: 2
roles:
  default: linear
  scene_linear: linear
displays:
  Test Display:
    - !<View> {name: Doubled, colorspace: doubled}
colorspaces:
  - !<ColorSpace>
    name: linear
  - !<ColorSpace>
    name: doubled
    from_scene_reference: !<MatrixTransform> {matrix: [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]}
)";

// Sets $OCIO for one test and restores the previous value afterwards.
class ScopedOcioVariable {
 public:
  explicit ScopedOcioVariable(const std::string& value) {
    if (const char* old = std::getenv("OCIO")) previous_ = old;
    setenv("OCIO", value.c_str(), 1);
  }
  ~ScopedOcioVariable() {
    if (previous_) setenv("OCIO", previous_->c_str(), 1);
    else unsetenv("OCIO");
  }

 private:
  std::optional<std::string> previous_;
};

float encode_grey(const DisplayTransform& transform, float value) {
  float rgb[3] = {value, value, value};
  transform.apply(rgb, 1);
  EXPECT_NEAR(rgb[0], rgb[1], 1e-5f) << "grey stays grey";
  EXPECT_NEAR(rgb[1], rgb[2], 1e-5f) << "grey stays grey";
  return rgb[0];
}

TEST(ColorConfig, BundledConfigHasTheSrgbDisplayWithThreeViews) {
  const ColorConfig config = ColorConfig::bundled();
  EXPECT_EQ(config.source(), "bundled");
  EXPECT_EQ(config.displays(), std::vector<std::string>{"sRGB"});
  EXPECT_EQ(config.default_display(), "sRGB");
  EXPECT_EQ(config.views("sRGB"), (std::vector<std::string>{"Standard", "ACES 1.0 SDR-video", "Raw"}));
  EXPECT_EQ(config.default_view("sRGB"), "Standard");
}

TEST(ColorConfig, BundledSourceFileIsAValidConfigToo) {
  const ColorConfig config = ColorConfig::load(test::source_dir() / "src/image/rtpro_config.ocio");
  EXPECT_EQ(config.views("sRGB"), ColorConfig::bundled().views("sRGB"));
}

TEST(ColorConfig, StandardViewIsThePlainSrgbCurve) {
  const DisplayTransform standard = ColorConfig::bundled().display_transform("", "");
  EXPECT_EQ(standard.display(), "sRGB");
  EXPECT_EQ(standard.view(), "Standard");
  EXPECT_NEAR(encode_grey(standard, 0.18f), 0.4614f, 1e-4f);
  EXPECT_NEAR(encode_grey(standard, 0.18f), 1.055 * std::pow(0.18, 1.0 / 2.4) - 0.055, 1e-5);
  EXPECT_NEAR(encode_grey(standard, 0.002f), 0.002f * 12.92f, 1e-5f);  // the linear toe
  EXPECT_NEAR(encode_grey(standard, 1.0f), 1.0f, 1e-5f);
  EXPECT_GT(encode_grey(standard, 4.0f), 1.0f) << "the view does not clamp: the writer must";
}

TEST(ColorConfig, AcesViewToneMapsMiddleGrey) {
  const DisplayTransform aces = ColorConfig::bundled().display_transform("sRGB", "ACES 1.0 SDR-video");
  EXPECT_NEAR(encode_grey(aces, 0.18f), 0.356f, 2e-3f);
  EXPECT_LT(encode_grey(aces, 0.0f), 1e-3f);
  // Highlights roll off towards (slightly above) display white instead of growing without bound.
  EXPECT_GT(encode_grey(aces, 100.0f), 0.95f);
  EXPECT_LT(encode_grey(aces, 100.0f), 1.05f);
  EXPECT_LT(encode_grey(aces, 1000.0f), 1.05f);
}

TEST(ColorConfig, RawViewLeavesValuesAlone) {
  const DisplayTransform raw = ColorConfig::bundled().display_transform("sRGB", "Raw");
  float rgb[6] = {0.1f, 0.5f, 2.0f, -1.0f, 0.0f, 0.25f};
  raw.apply(rgb, 2);
  EXPECT_EQ(std::vector<float>(rgb, rgb + 6), (std::vector<float>{0.1f, 0.5f, 2.0f, -1.0f, 0.0f, 0.25f}));
}

// An image's pixels are transformed in chunks side by side: each comes out as it does alone, the
// chunks' seams and the last, short chunk included.
TEST(ColorConfig, ApplyingToAnImageTransformsEachPixelAsAlone) {
  for (const char* view : {"Standard", "ACES 1.0 SDR-video"}) {
    const DisplayTransform transform = ColorConfig::bundled().display_transform("sRGB", view);
    const std::size_t pixels = 3 * 16384 + 77;
    std::vector<float> image(3 * pixels);
    for (std::size_t i = 0; i < image.size(); ++i) image[i] = 0.0003f * static_cast<float>(i % 9973);
    std::vector<float> alone = image;
    transform.apply(image.data(), pixels);
    for (std::size_t p = 0; p < pixels; ++p) transform.apply(&alone[3 * p], 1);
    for (std::size_t i = 0; i < image.size(); ++i) ASSERT_EQ(image[i], alone[i]) << view << ", value " << i;
  }
}

TEST(ColorConfig, UnknownViewListsTheAvailableOnes) {
  const std::string message =
      error_message_of<InputError>([] { ColorConfig::bundled().display_transform("sRGB", "Filmic"); });
  EXPECT_NE(message.find("\"Filmic\""), std::string::npos) << message;
  for (const char* view : {"Standard", "ACES 1.0 SDR-video", "Raw"})
    EXPECT_NE(message.find(view), std::string::npos) << message;
}

TEST(ColorConfig, UnknownDisplayListsTheAvailableOnes) {
  const std::string message = error_message_of<InputError>([] { ColorConfig::bundled().display_transform("P3", ""); });
  EXPECT_NE(message.find("\"P3\""), std::string::npos) << message;
  EXPECT_NE(message.find("\"sRGB\""), std::string::npos) << message;
}

// A colour-space or view name from a scene file reached the terminal raw, escape sequences and all.
TEST(ColorConfig, NamesFromInputFilesAreShownWithoutControlCharacters) {
  const ColorConfig config = ColorConfig::bundled();
  for (const std::function<void()>& attempt :
       std::vector<std::function<void()>>{[&] { config.to_scene_linear("evil\x1b[2J\nname"); },
                                          [&] { config.display_transform("sRGB", "evil\x1b[2J\nname"); },
                                          [&] { config.display_transform("evil\x1b[2J\nname", ""); }}) {
    try {
      attempt();
      ADD_FAILURE() << "an unknown name was accepted";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_NE(message.find("evil\\x1b[2J\\x0aname"), std::string::npos) << message;
    }
  }
}

TEST(ColorConfig, OcioVariableBeatsTheBundledConfig) {
  const auto file = test::write_file("doubling.ocio", kDoublingConfig);
  ScopedOcioVariable ocio(file.string());
  const ColorConfig config = ColorConfig::load(std::nullopt);
  EXPECT_EQ(config.source(), "$OCIO=" + file.string());
  EXPECT_EQ(config.displays(), std::vector<std::string>{"Test Display"});
  EXPECT_FLOAT_EQ(encode_grey(config.display_transform("", ""), 0.25f), 0.5f);
}

TEST(ColorConfig, CommandLineConfigBeatsTheOcioVariable) {
  ScopedOcioVariable ocio((test::scratch_dir() / "does-not-exist.ocio").string());
  const auto doubling = test::write_file("doubling.ocio", kDoublingConfig);
  const ColorConfig config = ColorConfig::load(doubling);
  EXPECT_EQ(config.source(), "--ocio-config " + doubling.string());
  EXPECT_EQ(config.default_view("Test Display"), "Doubled");
}

TEST(ColorConfig, EmptyOcioVariableMeansBundled) {
  ScopedOcioVariable ocio("");
  EXPECT_EQ(ColorConfig::load(std::nullopt).source(), "bundled");
}

TEST(ColorConfig, MissingConfigFileIsAnInputErrorNamingIt) {
  const auto missing = test::scratch_dir() / "missing.ocio";
  ScopedOcioVariable ocio(missing.string());
  const std::string message = error_message_of<InputError>([] { ColorConfig::load(std::nullopt); });
  EXPECT_NE(message.find(missing.string()), std::string::npos) << message;
  EXPECT_NE(message.find("$OCIO"), std::string::npos) << message;
}

TEST(ColorConfig, MalformedConfigFileIsAnInputErrorNamingIt) {
  const auto broken = test::write_file("broken.ocio", "ocio_profile_version: 2\ncolorspaces: [\n");
  const std::string message = error_message_of<InputError>([&] { ColorConfig::load(broken); });
  EXPECT_NE(message.find(broken.string()), std::string::npos) << message;
  EXPECT_NE(message.find("--ocio-config"), std::string::npos) << message;
}

}  // namespace color_config_test
}  // namespace rtpro
