// Small files that asked for gigabytes before the first pixel: each is answered within a small,
// measured cost (the real binary, its peak memory and time, against its own start-up), refused
// by the memory budget before anything large is allocated, or done in bounded memory.
#include "capped_run.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rtpro::test {
namespace memory_blowups_test {

const std::string kCamera = "camera: {position: [0, 0, -5], look_at: [0, 0, 0], resolution: [8, 8]}\n";

std::string rtpro() { return rtpro_executable().string(); }

// What the image layer (OpenImageIO, a plugin loaded on first use) costs to start: the baseline of
// commands that read an image.
const CappedRun& image_layer_startup() {
  static const CappedRun cheapest = [] {
    const auto scene = write_file("startup_with_images.yaml", "rtpro: 1\n" + kCamera + "world: [{type: sphere}]\n");
    CappedRun best;
    best.seconds = 1e9;
    for (int i = 0; i < 3; ++i) {
      const CappedRun run = run_capped(
          {rtpro(), "render", scene.string(), "-o", (scene.parent_path() / "startup.tif").string(), "--spp", "1"});
      if (run.seconds < best.seconds) best = run;
    }
    return best;
  }();
  return cheapest;
}

#ifndef RTPRO_TEST_WORK_SLOWDOWN
#define RTPRO_TEST_WORK_SLOWDOWN 1.0
#endif
// Under the sanitizers every answer costs more: ASan's shadow memory and quarantine add about
// 120 MB to reading a scene that `rtpro --version` does not pay, and the work is slower.
constexpr double kBuildFactor = RTPRO_TEST_WORK_SLOWDOWN;

// Exit code `expected`, every piece of `says` in the answer, and no more than `extra_mb` of memory
// and 2 s of CPU time beyond `baseline`'s (both scaled by kBuildFactor).
void expect_bounded(const CappedRun& run, int expected, const std::vector<std::string>& says, const CappedRun& baseline,
                    double extra_mb) {
  EXPECT_FALSE(run.killed) << "no answer within the kill limit:\n" << run.output;
  EXPECT_EQ(run.exit_code, expected) << run.output;
  for (const std::string& text : says)
    EXPECT_NE(run.output.find(text), std::string::npos) << "missing '" << text << "' in:\n" << run.output;
  EXPECT_LT(run.cpu_seconds, baseline.cpu_seconds + 2.0 * kBuildFactor)
      << "start-up alone took " << baseline.cpu_seconds << " s of CPU\n"
      << run.output;
  EXPECT_LT(run.peak_rss_mb, baseline.peak_rss_mb + extra_mb * kBuildFactor)
      << "start-up alone used " << baseline.peak_rss_mb << " MB\n"
      << run.output;
}

// A Radiance .hdr of one colour, run-length encoded: about 2 bytes per 127 pixels and channel, so
// a small file declares many pixels.
std::filesystem::path write_flat_hdr(const std::string& name, int width, int height) {
  std::string row = {2, 2, static_cast<char>(width >> 8), static_cast<char>(width & 255)};
  const unsigned char rgbe[4] = {128, 128, 128, 129};
  for (const unsigned char value : rgbe)
    for (int left = width; left > 0; left -= 127) {
      row += static_cast<char>(128 + std::min(left, 127));
      row += static_cast<char>(value);
    }
  std::string text =
      "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n";
  for (int y = 0; y < height; ++y) text += row;
  return write_file(name, text);
}

// A 36 KB .hdr of 1024x512 pixels: 6 MiB as floats, which was all the budget counted, but 12 MiB
// once the light holds its copy and sampling distribution (a 17 MB file of 16384x16384 took
// 6.3 GB and 18 s while `info` estimated 18 KiB). The header is read before the image.
TEST(MemoryBlowups, EnvironmentMapCountsInTheEstimateFromItsHeader) {
  scratch_dir();
  write_flat_hdr("sky.hdr", 1024, 512);
  const auto scene =
      write_file("sky.yaml", "rtpro: 1\n" + kCamera + "environment: {file: sky.hdr}\nworld: [{type: sphere}]\n");
  const auto output = scene.parent_path() / "sky.exr";
  expect_bounded(run_capped({rtpro(), "render", scene.string(), "-o", output.string(), "--max-memory", "10"}), 2,
                 {"sky.yaml", "environment map 12.0 MiB", "sky.hdr, 1024x512 pixels", "--max-memory 10"},
                 image_layer_startup(), 20.0);
  EXPECT_FALSE(std::filesystem::exists(output));
  expect_bounded(run_capped({rtpro(), "info", scene.string()}), 0, {"environment map 12.0 MiB"}, image_layer_startup(),
                 20.0);
}

// Two 6,000-character names a character apart from nothing: the suggestion's edit-distance table
// was their product (36 million cells, 288 MB; a 60 KB scene of two 30,000-character names took
// 6.9 GB). Names that long are never suggested, and the message stays short.
TEST(MemoryBlowups, SuggestionForAnUnknownLongNameIsBounded) {
  scratch_dir();
  const std::string defined(6000, 'a'), used(6000, 'b');
  const auto scene =
      write_file("names.yaml", "rtpro: 1\n" + kCamera + "materials:\n  ? " + defined +
                                   "\n  : {color: [0.5, 0.5, 0.5]}\nworld: [{type: sphere, material: " + used + "}]\n");
  // An explicit key (`? name`): YAML's plain keys stop at 1,024 characters.
  const CappedRun run = run_capped({rtpro(), "info", scene.string()});
  expect_bounded(run, 2, {"names.yaml:6:", "unknown material"}, startup_cost(), 100.0);
  EXPECT_EQ(run.output.find("did you mean"), std::string::npos) << run.output.substr(0, 400);
}

// 1,500 world entries each lit by every light but its own among 1,500 point lights: 1,501
// distinct sets whose light trees hold 2.25 million lights. Comparing every new set with every
// earlier one and building each tree took seconds per thousand and 2.2 GB at 3,000; the sets are
// now found by hashing and their total size refused before any tree is built.
TEST(MemoryBlowups, ManyDistinctLightLinkingSetsAreRefusedBeforeTheirLightTrees) {
  scratch_dir();
  constexpr int kLights = 1500;
  std::string text = "rtpro: 1\n" + kCamera + "render: {spp: 1, integrator: path}\nlights:\n";
  for (int i = 0; i < kLights; ++i)
    text += "  - {type: point, name: l" + std::to_string(i) + ", position: [0, 5, 0], intensity: 1}\n";
  text += "world:\n";
  for (int i = 0; i < kLights; ++i)
    text += "  - {type: sphere, radius: 0.1, light_linking: {not_illuminated_by: [l" + std::to_string(i) + "]}}\n";
  const auto scene = write_file("linked.yaml", text);
  const auto output = scene.parent_path() / "linked.exr";
  expect_bounded(run_capped({rtpro(), "render", scene.string(), "-o", output.string()}, 8.0), 2,
                 {"light linking", "1501 distinct sets", "2250000 lights", "limit of 2097152"}, startup_cost(), 100.0);
  EXPECT_FALSE(std::filesystem::exists(output));
}

// A 128x128 render's EXR (colour and features) denoised under a 1 MiB budget: the estimate from
// its header (a 1.6 MB EXR of 16384x16384 pixels ran out of memory after 18 s) is refused before
// a pixel is read, naming the file and the estimate.
TEST(MemoryBlowups, DenoiseEstimatesItsMemoryFromTheHeader) {
  scratch_dir();
  const auto scene = write_file("small.yaml",
                                "rtpro: 1\ncamera: {position: [0, 0, -5], look_at: [0, 0, 0], "
                                "resolution: [128, 128]}\nworld: [{type: sphere}]\n");
  const auto noisy = scene.parent_path() / "noisy.exr", denoised = scene.parent_path() / "denoised.exr";
  ASSERT_EQ(run_capped(
                {rtpro(), "render", scene.string(), "-o", noisy.string(), "--spp", "1", "--aov", "albedo,normal,depth"})
                .exit_code,
            0);
  expect_bounded(run_capped({rtpro(), "denoise", noisy.string(), "-o", denoised.string(), "--max-memory", "1"}), 2,
                 {"noisy.exr", "denoising this 128x128 image of 10 channels would need an estimated", "--max-memory 1"},
                 image_layer_startup(), 50.0);
  EXPECT_FALSE(std::filesystem::exists(denoised));
}

// An .hdr of one colour near the float maximum (1.4e38): every pixel of a path-traced image was
// infinite, and --denoise wrote black, all with exit 0. The radiance is refused at load, naming
// the file and the pixel.
TEST(MemoryBlowups, EnvironmentRadianceNearTheFloatMaximumIsRefused) {
  scratch_dir();
  std::string row = {2, 2, 0, 16};
  for (const unsigned char value : {200, 200, 200, 255}) row += {static_cast<char>(128 + 16), static_cast<char>(value)};
  std::string text = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n";
  for (int y = 0; y < 8; ++y) text += row;
  write_file("blinding.hdr", text);
  const auto scene = write_file("blinding.yaml", "rtpro: 1\n" + kCamera +
                                                     "render: {spp: 2, integrator: path}\nenvironment: {file: "
                                                     "blinding.hdr}\nworld: [{type: sphere}]\n");
  const auto output = scene.parent_path() / "blinding.exr";
  for (const char* backend : {"native", "embree"})
    expect_bounded(
        run_capped({rtpro(), "render", scene.string(), "-o", output.string(), "--backend", backend, "--denoise"}), 2,
        {"blinding.hdr: pixel (0, 0) is", "not finite or above 1e12", "384 values in all"}, image_layer_startup(),
        50.0);
  EXPECT_FALSE(std::filesystem::exists(output));
  // A constant environment's colour x intensity likewise, at the intensity.
  const auto constant = write_file("constant.yaml", "rtpro: 1\n" + kCamera +
                                                        "environment: {color: [1e9, 1e9, 1e9], intensity: 1e9}\n"
                                                        "world: [{type: sphere}]\n");
  expect_bounded(run_capped({rtpro(), "info", constant.string()}), 2,
                 {"constant.yaml:3:", "environment.intensity", "more than the most radiance"}, startup_cost(), 50.0);
}

// A diffuse or conductor colour above 1 reflects more than it receives: pixels near 1e33 with exit
// 0. Refused at the colour, as every other 0-to-1 value of a material is.
TEST(MemoryBlowups, ReflectanceAboveOneIsRefusedAtTheColour) {
  scratch_dir();
  for (const std::string kind : {"diffuse", "conductor", "principled"}) {
    const auto scene = write_file(kind + ".yaml", "rtpro: 1\n" + kCamera + "materials:\n  hot: {type: " + kind +
                                                      ", color: [1.5, 0.5, 0.5]}\nworld: [{type: sphere, "
                                                      "material: hot}]\n");
    expect_bounded(run_capped({rtpro(), "info", scene.string()}), 2,
                   {kind + ".yaml:4:", "material 'hot'.color is a reflectance: each channel from 0 to 1"},
                   startup_cost(), 50.0);
  }
}

}  // namespace memory_blowups_test
}  // namespace rtpro::test
