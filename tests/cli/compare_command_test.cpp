// Runs the real `rtpro compare` binary: exit codes, report and JSON.
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace rtpro {
namespace compare_command_test {

namespace fs = std::filesystem;

struct ImagePair {
  fs::path reference;
  fs::path test;
};

// A gradient and a copy of it with `changed_pixels` pixels brightened by `offset`.
ImagePair write_pair(const fs::path& folder, int changed_pixels, float offset, const std::string& extension = ".exr") {
  Image reference(10, 10);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      for (int c = 0; c < 3; ++c) reference.at(x, y, c) = 0.05f * x + 0.02f * y + 0.1f * c;
  Image test = reference;
  for (int i = 0; i < changed_pixels; ++i) test.at(i, 3, 1) += offset;
  ImagePair pair{folder / ("reference" + extension), folder / ("test" + extension)};
  write_image(pair.reference, reference, {});
  write_image(pair.test, test, {});
  return pair;
}

// Built by appending: GCC 12 at -O3 warns (-Wrestrict, a false positive) on "'" + string + "'".
std::string quoted(const fs::path& path) {
  std::string text = "'";
  text.append(path.string()).append("'");
  return text;
}

int compare(const std::string& arguments, std::string* output) {
  return test::run_command(quoted(test::rtpro_executable()) + " compare " + arguments, output);
}

// The JSON report is all of stdout; run_command merges stderr in, so keep it apart.
nlohmann::json compare_json(const std::string& arguments, int* exit_code) {
  std::string output;
  *exit_code = compare(arguments + " --json 2>/dev/null", &output);
  return nlohmann::json::parse(output);
}

TEST(CompareCommand, IdenticalImagesPass) {
  const auto pair = write_pair(test::scratch_dir(), 0, 0.0f);
  std::string output;
  EXPECT_EQ(compare(quoted(pair.reference) + " " + quoted(pair.test), &output), 0) << output;
  EXPECT_NE(output.find("PASS"), std::string::npos) << output;
  EXPECT_NE(output.find("PSNR        inf"), std::string::npos) << output;
}

TEST(CompareCommand, DifferentImagesFailWithExitCodeOne) {
  const auto pair = write_pair(test::scratch_dir(), 2, 0.25f);
  std::string output;
  EXPECT_EQ(compare(quoted(pair.reference) + " " + quoted(pair.test), &output), 1) << output;
  EXPECT_NE(output.find("FAIL"), std::string::npos) << output;
  EXPECT_NE(output.find("x=0 y=3 channel G"), std::string::npos) << output;
}

TEST(CompareCommand, ThresholdsDecideTheVerdict) {
  const auto pair = write_pair(test::scratch_dir(), 2, 0.25f);
  const std::string images = quoted(pair.reference) + " " + quoted(pair.test);
  std::string output;
  EXPECT_EQ(compare(images + " --fail 0.3", &output), 0) << output;
  EXPECT_EQ(compare(images + " --fail-percent 2", &output), 0) << output;
  EXPECT_EQ(compare(images + " --fail-percent 1", &output), 1) << output;
  EXPECT_EQ(compare(images + " --fail 0.3 --max-mean-error 0.001", &output), 1) << output;
}

TEST(CompareCommand, JsonReportParses) {
  const auto pair = write_pair(test::scratch_dir(), 3, 0.5f);
  int exit_code = -1;
  const auto report = compare_json(quoted(pair.reference) + " " + quoted(pair.test) + " --warn 0.1", &exit_code);
  EXPECT_EQ(exit_code, 1);
  EXPECT_EQ(report["passed"], false);
  EXPECT_EQ(report["fail_pixels"], 3);
  EXPECT_EQ(report["warn_pixels"], 3);
  EXPECT_EQ(report["pixels"], 100);
  EXPECT_NEAR(report["max_error"].get<double>(), 0.5, 1e-6);
  EXPECT_EQ(report["max_error_at"]["channel"], "G");
  EXPECT_EQ(report["channels"], nlohmann::json({"R", "G", "B"}));
}

TEST(CompareCommand, JsonWritesInfinitePsnrAsNull) {
  const auto pair = write_pair(test::scratch_dir(), 0, 0.0f);
  int exit_code = -1;
  const auto report = compare_json(quoted(pair.reference) + " " + quoted(pair.test), &exit_code);
  EXPECT_EQ(exit_code, 0);
  EXPECT_EQ(report["passed"], true);
  EXPECT_TRUE(report["psnr"].is_null());
}

TEST(CompareCommand, DifferentSizesFailWithExitCodeOne) {
  const auto folder = test::scratch_dir();
  write_image(folder / "small.exr", Image(4, 4), {});
  write_image(folder / "large.exr", Image(4, 5), {});
  std::string output;
  EXPECT_EQ(compare(quoted(folder / "small.exr") + " " + quoted(folder / "large.exr") + " --diff " +
                        quoted(folder / "diff.png"),
                    &output),
            1)
      << output;
  EXPECT_NE(output.find("differ in size"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(folder / "diff.png"));
}

TEST(CompareCommand, DiffImageIsWritten) {
  const auto folder = test::scratch_dir();
  const auto pair = write_pair(folder, 1, 0.25f, ".png");
  std::string output;
  EXPECT_EQ(
      compare(quoted(pair.reference) + " " + quoted(pair.test) + " --diff " + quoted(folder / "diff.png"), &output), 1)
      << output;
  const Image diff = read_image(folder / "diff.png");
  EXPECT_EQ(diff.at(0, 3, 0), 1.0f) << "the failing pixel is white";
  EXPECT_EQ(diff.at(5, 5, 0), 0.0f);
}

// `--diff REF` once replaced the reference with the heat map (exit 1, the reference lost).
TEST(CompareCommand, ADiffImageThatIsAnInputIsRefusedBeforeAnythingIsWritten) {
  const auto folder = test::scratch_dir();
  const auto pair = write_pair(folder, 1, 0.25f, ".png");
  const auto reference_before = read_image(pair.reference).data;
  std::string output;
  EXPECT_EQ(compare(quoted(pair.reference) + " " + quoted(pair.test) + " --diff " + quoted(pair.reference), &output), 2)
      << output;
  EXPECT_NE(output.find("--diff " + pair.reference.string() + " is the same file as the reference " +
                        pair.reference.string()),
            std::string::npos)
      << output;
  // Another spelling of the test image's path is the same file too.
  EXPECT_EQ(compare(quoted(pair.reference) + " " + quoted(pair.test) + " --diff " +
                        quoted(folder / "." / pair.test.filename()),
                    &output),
            2)
      << output;
  EXPECT_NE(output.find("is the same file as the test image"), std::string::npos) << output;
  EXPECT_EQ(read_image(pair.reference).data, reference_before);
}

TEST(CompareCommand, UnreadableFileIsExitCodeTwo) {
  const auto folder = test::scratch_dir();
  const auto pair = write_pair(folder, 0, 0.0f);
  std::string output;
  EXPECT_EQ(compare(quoted(pair.reference) + " " + quoted(folder / "missing.exr"), &output), 2) << output;
  EXPECT_NE(output.find("missing.exr"), std::string::npos) << output;
}

TEST(CompareCommand, UsageErrorsAreExitCodeTwo) {
  const auto pair = write_pair(test::scratch_dir(), 0, 0.0f);
  const std::string images = quoted(pair.reference) + " " + quoted(pair.test);
  std::string output;
  EXPECT_EQ(compare(quoted(pair.reference), &output), 2) << output;
  EXPECT_EQ(compare(images + " --fail -1", &output), 2) << output;
  EXPECT_EQ(compare(images + " --fail-percent 150", &output), 2) << output;
  EXPECT_EQ(compare(images + " --diff " + quoted(pair.reference.parent_path() / "diff.xyz"), &output), 2) << output;
}

}  // namespace compare_command_test
}  // namespace rtpro
