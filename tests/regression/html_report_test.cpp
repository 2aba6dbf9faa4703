// The failure folders and the HTML report that the regression tests leave behind.
#include "html_report.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <fstream>

namespace rtpro::regression {
namespace html_report_test {

using test::read_file;
using test::uniform_image;

// The failure folder a native render of `scene` leaves when `rendered` fails against `reference`.
void write_failing_render(const std::filesystem::path& folder, const std::string& scene, const Image& reference,
                          const Image& rendered) {
  CompareThresholds thresholds;
  thresholds.fail = thresholds.warn = 1e-5f;
  nlohmann::json figures = comparison_figures(compare_images(reference, rendered, thresholds), thresholds);
  figures["scene"] = scene;
  figures["backend"] = "native";
  write_failure_folder(folder, reference, rendered, figures);
}

TEST(RegressionReport, ListsEveryFailureWithItsImagesAndFigures) {
  const auto root = test::scratch_dir();
  const Image reference = uniform_image(8, 6, 0.5f);
  Image brighter = reference;
  brighter.at(3, 2, 1) = 0.75f;
  write_failing_render(root / "a-native", "scenes/a.yaml", reference, brighter);
  write_failing_render(root / "b-native", "scenes/b.yaml", reference, uniform_image(8, 6, 0.6f));

  const std::string html = read_file(regenerate_report(root, "make references"));
  for (const char* file : {"reference.png", "rendered.png", "diff.png", "rendered.exr", "figures.json"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(root / "a-native" / file)) << file;
    EXPECT_NE(html.find(std::string("a-native/") + file), std::string::npos) << file;
    EXPECT_NE(html.find(std::string("b-native/") + file), std::string::npos) << file;
  }
  EXPECT_LT(html.find("scenes/a.yaml"), html.find("scenes/b.yaml"));
  EXPECT_NE(html.find("1 of 48"), std::string::npos) << "a's one failing pixel";
  EXPECT_NE(html.find("at (3, 2) channel G"), std::string::npos) << "where a's max error is";
  EXPECT_NE(html.find("make references"), std::string::npos);
}

TEST(RegressionReport, ClearingTheLastFailureLeavesAReportSayingSo) {
  const auto root = test::scratch_dir();
  const Image reference = uniform_image(4, 4, 0.2f);
  write_failing_render(root / "a-embree", "scenes/a.yaml", reference, uniform_image(4, 4, 0.3f));
  regenerate_report(root, "");
  clear_failure(root, "a-embree", "");
  EXPECT_FALSE(std::filesystem::exists(root / "a-embree"));
  EXPECT_NE(read_file(root / "report.html").find("No failing regression tests."), std::string::npos);
}

TEST(RegressionReport, IgnoresAFolderWithoutFiguresAndEscapesText) {
  const auto root = test::scratch_dir();
  std::filesystem::create_directories(root / "half-written");
  const Image reference = uniform_image(4, 4, 0.2f);
  write_failing_render(root / "x-native", "scenes/<x>&.yaml", reference, uniform_image(4, 4, 0.3f));
  const std::string html = read_file(regenerate_report(root, ""));
  EXPECT_EQ(html.find("half-written"), std::string::npos);
  EXPECT_NE(html.find("scenes/&lt;x&gt;&amp;.yaml"), std::string::npos);
  EXPECT_EQ(html.find("<x>"), std::string::npos);
}

TEST(RegressionReport, FiguresMissingFieldsStillGetARow) {
  const auto root = test::scratch_dir();
  std::filesystem::create_directories(root / "old-native");
  std::ofstream(root / "old-native" / "figures.json") << R"({"scene": "scenes/old.yaml"})";
  const std::string html = read_file(regenerate_report(root, ""));
  EXPECT_NE(html.find("scenes/old.yaml"), std::string::npos);
}

TEST(RegressionReport, ImagesOfDifferentSizesGetNoDiff) {
  const auto root = test::scratch_dir();
  const Image reference = uniform_image(4, 4, 0.2f);
  write_failing_render(root / "s-native", "scenes/s.yaml", reference, uniform_image(4, 3, 0.2f));
  EXPECT_FALSE(std::filesystem::exists(root / "s-native" / "diff.png"));
  EXPECT_NE(read_file(regenerate_report(root, "")).find("(none: the images differ in size)"), std::string::npos);
}

}  // namespace html_report_test
}  // namespace rtpro::regression
