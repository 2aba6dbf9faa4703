// `rtpro denoise IN -o OUT` through the real binary: what it writes, what it refuses (exit 2, a
// message naming the file) and that a failure leaves an existing output alone.
#include "rtpro/denoise/denoise.h"
#include "rtpro/image/image_io.h"
#include "noisy_fixture.h"
#include "test_fixtures.h"
#include "test_commands.h"
#include "test_paths.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace rtpro {
namespace denoise_command_test {

using noisy_fixture::without_channel;

namespace fs = std::filesystem;
using noisy_fixture::PixelTruth;

// A small render with detail: two albedos, a slanted depth, the layers render writes.
Image noisy_image(const noisy_fixture::NoisyOptions& options = {}) {
  return noisy_fixture::noisy_render(
      40, 30,
      [](int x, int) {
        PixelTruth t;
        t.albedo = x < 20 ? noisy_fixture::Rgb{0.8f, 0.7f, 0.6f} : noisy_fixture::Rgb{0.3f, 0.3f, 0.5f};
        t.depth = 2.0f + 0.05f * x;
        for (int c = 0; c < 3; ++c) t.colour[c] = 1.2f * t.albedo[c];
        return t;
      },
      options);
}

std::string quoted(const fs::path& path) {
  std::string text = "'";
  text.append(path.string()).append("'");
  return text;
}

int channel_of(const Image& image, std::string_view name) {
  const auto found = std::find(image.channels.begin(), image.channels.end(), name);
  return found == image.channels.end() ? -1 : static_cast<int>(found - image.channels.begin());
}

double squared_error(const Image& image, const Image& truth_source) {
  // The truth is the noiseless colour: 1.2 · albedo, read back from the albedo layer.
  double sum = 0.0;
  const int albedo = channel_of(truth_source, "albedo.R");
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double d = image.at(x, y, c) - 1.2 * truth_source.at(x, y, albedo + c);
        sum += d * d;
      }
  return sum;
}

TEST(DenoiseCommand, WritesTheDenoisedColourAndKeepsTheNoisyOne) {
  const fs::path dir = test::scratch_dir();
  const Image noisy = noisy_image();
  write_image(dir / "in.exr", noisy, {});
  const std::string out = test::run_rtpro("denoise " + quoted(dir / "in.exr") + " -o " + quoted(dir / "out.exr"), 0);
  EXPECT_NE(out.find("guided by albedo, normal, depth"), std::string::npos) << out;
  EXPECT_EQ(out.find("warning"), std::string::npos) << out;

  const Image result = read_image(dir / "out.exr");
  ASSERT_EQ(result.width, noisy.width);
  ASSERT_EQ(result.height, noisy.height);
  // Every input layer stays; the noisy colour is added as noisy.R/G/B.
  for (const std::string& name : noisy.channels) EXPECT_GE(channel_of(result, name), 0) << name;
  for (std::string_view name : kNoisyChannels) EXPECT_GE(channel_of(result, name), 0) << name;
  Image rgb(result.width, result.height), kept(result.width, result.height);
  for (int y = 0; y < result.height; ++y)
    for (int x = 0; x < result.width; ++x)
      for (int c = 0; c < 3; ++c) {
        rgb.at(x, y, c) = result.at(x, y, channel_of(result, kColourChannels[c]));
        kept.at(x, y, c) = result.at(x, y, channel_of(result, kNoisyChannels[c]));
        EXPECT_EQ(kept.at(x, y, c), noisy.at(x, y, c));
      }
  // The same bits as the library gives in memory.
  const Image in_memory = denoise(noisy);
  test::expect_same_channels(in_memory, rgb);
  EXPECT_LT(squared_error(rgb, noisy), squared_error(noisy, noisy) / 5.0);
}

TEST(DenoiseCommand, WorksWithoutFeaturesAndSaysSo) {
  const fs::path dir = test::scratch_dir();
  noisy_fixture::NoisyOptions options;
  options.features = false;
  write_image(dir / "in.exr", noisy_image(options), {});
  const std::string out = test::run_rtpro("denoise " + quoted(dir / "in.exr") + " -o " + quoted(dir / "out.exr"), 0);
  EXPECT_NE(out.find("warning"), std::string::npos) << out;
  EXPECT_NE(out.find("--aov albedo,normal,depth"), std::string::npos) << out;
  EXPECT_NE(out.find("guided by the colour alone"), std::string::npos) << out;
  EXPECT_TRUE(fs::exists(dir / "out.exr"));
}

// A display format gets the denoised colour alone (it cannot hold layers).
TEST(DenoiseCommand, WritesDisplayFormatsToo) {
  const fs::path dir = test::scratch_dir();
  write_image(dir / "in.exr", noisy_image(), {});
  test::run_rtpro("denoise " + quoted(dir / "in.exr") + " -o " + quoted(dir / "out.png") + " -q", 0);
  const Image png = read_image(dir / "out.png");
  EXPECT_EQ(png.width, 40);
  EXPECT_EQ(png.height, 30);
}

// Writes an EXR whose albedo.R channel is stored at half resolution (EXR's x/y sampling): one
// file with channels of two sizes.
void write_subsampled_exr(const fs::path& file) {
  constexpr int kSize = 8;
  Imf::Header header(kSize, kSize);
  for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  header.channels().insert("albedo.R", Imf::Channel(Imf::FLOAT, 2, 2));
  std::vector<float> full(kSize * kSize, 0.5f), half(kSize * kSize / 4, 0.25f);
  Imf::FrameBuffer frame;
  for (const char* name : {"R", "G", "B"})
    frame.insert(name,
                 Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(full.data()), sizeof(float), sizeof(float) * kSize));
  frame.insert("albedo.R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(half.data()), sizeof(float),
                                      sizeof(float) * (kSize / 2), 2, 2));
  Imf::OutputFile output(file.string().c_str(), header);
  output.setFrameBuffer(frame);
  output.writePixels(kSize);
}

// Each bad input exits 2 with a one-line message naming the file, and the good output written
// before stays exactly as it was.
TEST(DenoiseCommand, RefusesBadInputsAndKeepsAnExistingOutput) {
  const fs::path dir = test::scratch_dir();
  const fs::path good = dir / "good.exr", output = dir / "out.exr";
  write_image(good, noisy_image(), {});
  test::run_rtpro("denoise " + quoted(good) + " -o " + quoted(output), 0);
  const std::string output_before = test::read_file(output);
  ASSERT_FALSE(output_before.empty());

  const Image noisy = noisy_image();
  write_image(dir / "no_colour.exr", without_channel(without_channel(without_channel(noisy, "R"), "G"), "B"), {});
  write_image(dir / "torn_albedo.exr", without_channel(noisy, "albedo.B"), {});
  write_subsampled_exr(dir / "subsampled.exr");
  std::ofstream(dir / "not_an_image.exr") << "hello";

  const struct {
    const char* file;
    const char* says;
  } cases[] = {
      {"no_colour.exr", "no R, G, B colour channels"}, {"torn_albedo.exr", "albedo.R and albedo.G but not albedo.B"},
      {"subsampled.exr", "Subsampled channels"},       {"not_an_image.exr", "not_an_image.exr"},
      {"missing.exr", "no such image file"},
  };
  for (const auto& bad : cases) {
    const fs::path input = dir / bad.file;
    const std::string out = test::run_rtpro("denoise " + quoted(input) + " -o " + quoted(output), 2);
    EXPECT_NE(out.find(input.string()), std::string::npos) << out;
    EXPECT_NE(out.find(bad.says), std::string::npos) << out;
    EXPECT_EQ(out.rfind("rtpro: error: ", 0), 0u) << out;
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << out;
    EXPECT_EQ(test::read_file(output), output_before) << bad.file;
  }
}

TEST(DenoiseCommand, BadOptionsExitTwoBeforeReading) {
  const fs::path dir = test::scratch_dir();
  write_image(dir / "in.exr", noisy_image(), {});
  const std::string in = quoted(dir / "in.exr");
  test::run_rtpro("denoise " + in + " -o " + quoted(dir / "out.exr") + " --radius 0", 2);
  test::run_rtpro("denoise " + in + " -o " + quoted(dir / "no_such_folder" / "out.exr"), 1);
  test::run_rtpro("denoise " + in, 2);
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
}

TEST(DenoiseCommand, SameFileForAnyThreadCount) {
  const fs::path dir = test::scratch_dir();
  write_image(dir / "in.exr", noisy_image(), {});
  test::run_rtpro("denoise " + quoted(dir / "in.exr") + " -o " + quoted(dir / "one.exr") + " --threads 1", 0);
  test::run_rtpro("denoise " + quoted(dir / "in.exr") + " -o " + quoted(dir / "two.exr") + " --threads 2", 0);
  test::expect_same_pixels(dir / "one.exr", dir / "two.exr");
}

TEST(DenoiseCommand, ListedInCompletionAndManPage) {
  const std::string completion = test::run_rtpro("completion bash", 0);
  EXPECT_NE(completion.find("denoise)"), std::string::npos);
  const std::string manpage = test::run_rtpro("manpage", 0);
  EXPECT_NE(manpage.find(".SS denoise"), std::string::npos);
}

}  // namespace denoise_command_test
}  // namespace rtpro
