#include "rtpro/image/image_compare.h"

#include "test_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rtpro {
namespace image_compare_test {

using test::gradient_image;

TEST(ImageCompare, IdenticalImagesHaveNoErrorAndInfinitePsnr) {
  const Image image = gradient_image(8, 5);
  const ImageComparison result = compare_images(image, image, {});
  EXPECT_TRUE(result.incompatibility.empty());
  EXPECT_EQ(result.pixel_count, 40u);
  EXPECT_EQ(result.mean_error, 0.0);
  EXPECT_EQ(result.rms_error, 0.0);
  EXPECT_EQ(result.max_error, 0.0);
  EXPECT_TRUE(std::isinf(result.psnr) && result.psnr > 0);
  EXPECT_EQ(result.fail_pixels, 0u);
  EXPECT_EQ(result.warn_pixels, 0u);
  EXPECT_TRUE(result.passed);
}

TEST(ImageCompare, OnePixelOffIsFoundAndCounted) {
  const Image reference = gradient_image(8, 5);
  Image test = reference;
  test.at(6, 3, 1) += 0.5f;
  test.at(2, 1, 2) += 1e-7f;  // below the default thresholds
  const ImageComparison result = compare_images(reference, test, {});
  EXPECT_NEAR(result.max_error, 0.5, 1e-6);
  EXPECT_EQ(result.max_x, 6);
  EXPECT_EQ(result.max_y, 3);
  EXPECT_EQ(result.max_channel, "G");
  EXPECT_EQ(result.fail_pixels, 1u);
  EXPECT_EQ(result.warn_pixels, 1u);
  EXPECT_NEAR(result.mean_error, 0.5 / 120.0, 1e-6);
  EXPECT_FALSE(result.passed);
  EXPECT_NE(result.verdict.find("1 pixels"), std::string::npos) << result.verdict;
}

TEST(ImageCompare, FailPercentAllowsSomeFailingPixels) {
  const Image reference = gradient_image(10, 10);
  Image test = reference;
  test.at(0, 0, 0) += 0.5f;
  test.at(9, 9, 2) += 0.5f;
  CompareThresholds thresholds;
  thresholds.fail_percent = 2.0;
  EXPECT_TRUE(compare_images(reference, test, thresholds).passed);
  thresholds.fail_percent = 1.5;
  EXPECT_FALSE(compare_images(reference, test, thresholds).passed);
}

TEST(ImageCompare, WarningsAloneDoNotFail) {
  const Image reference = gradient_image(4, 4);
  Image test = reference;
  test.at(1, 1, 0) += 0.05f;
  CompareThresholds thresholds;
  thresholds.warn = 0.01f;
  thresholds.fail = 0.1f;
  const ImageComparison result = compare_images(reference, test, thresholds);
  EXPECT_EQ(result.warn_pixels, 1u);
  EXPECT_EQ(result.fail_pixels, 0u);
  EXPECT_TRUE(result.passed);
  EXPECT_NE(result.verdict.find("warn"), std::string::npos) << result.verdict;
}

TEST(ImageCompare, UniformOffsetGivesEqualMeanAndRms) {
  const Image reference = gradient_image(6, 6);
  Image test = reference;
  for (float& value : test.data) value += 0.25f;
  CompareThresholds thresholds;
  thresholds.fail = 0.3f;
  const ImageComparison result = compare_images(reference, test, thresholds);
  EXPECT_NEAR(result.mean_error, 0.25, 1e-6);
  EXPECT_NEAR(result.rms_error, 0.25, 1e-6);
  EXPECT_NEAR(result.psnr, 20.0 * std::log10(1.0 / 0.25), 1e-4);
  EXPECT_EQ(result.fail_pixels, 0u);
  EXPECT_TRUE(result.passed);
  thresholds.max_mean_error = 0.2;
  EXPECT_FALSE(compare_images(reference, test, thresholds).passed);
}

// relMSE weighs an error by the reference's value: the same absolute error counts 100 times less
// on a value of 1 than on a black one (against the 0.01 that keeps black finite).
TEST(ImageCompare, RelativeMseAndMeansPerChannel) {
  Image reference(2, 1), test(2, 1);
  reference.data = {0.0f, 1.0f, 2.0f, 0.0f, 1.0f, 4.0f};
  test.data = {0.1f, 1.1f, 2.0f, 0.0f, 1.0f, 4.0f};
  const ImageComparison result = compare_images(reference, test, {});
  const double expected = (0.01 / 0.01 + 0.01 / 1.01) / 6.0;
  EXPECT_NEAR(result.rel_mse, expected, 1e-6);
  ASSERT_EQ(result.reference_means.size(), 3u);
  EXPECT_NEAR(result.reference_means[2], 3.0, 1e-12);
  EXPECT_NEAR(result.test_means[0], 0.05, 1e-7);
  EXPECT_NEAR(result.test_means[1], 1.05, 1e-7);
  EXPECT_EQ(compare_images(reference, reference, {}).rel_mse, 0.0);
}

TEST(ImageCompare, DifferentSizesAreAFailureNotAUnion) {
  const Image reference = gradient_image(8, 5);
  Image test = gradient_image(8, 6);
  const ImageComparison result = compare_images(reference, test, {});
  EXPECT_FALSE(result.passed);
  EXPECT_NE(result.incompatibility.find("8x5"), std::string::npos) << result.incompatibility;
  EXPECT_NE(result.incompatibility.find("8x6"), std::string::npos) << result.incompatibility;
}

TEST(ImageCompare, DifferentChannelsAreAFailure) {
  const Image reference(4, 4, {"R", "G", "B"});
  const Image test(4, 4, {"R", "G", "B", "A"});
  const ImageComparison result = compare_images(reference, test, {});
  EXPECT_FALSE(result.passed);
  EXPECT_NE(result.incompatibility.find("R,G,B,A"), std::string::npos) << result.incompatibility;
}

TEST(ImageCompare, NanInOneImageIsAFailingPixelWithInfiniteError) {
  const Image reference = gradient_image(5, 5);
  Image test = reference;
  test.at(2, 4, 0) = NAN;
  const ImageComparison result = compare_images(reference, test, {});
  EXPECT_EQ(result.nan_pixels_reference, 0u);
  EXPECT_EQ(result.nan_pixels_test, 1u);
  EXPECT_EQ(result.nonfinite_mismatch_pixels, 1u);
  EXPECT_EQ(result.fail_pixels, 1u);
  EXPECT_EQ(result.warn_pixels, 1u);
  EXPECT_TRUE(std::isinf(result.max_error));
  EXPECT_EQ(result.max_x, 2);
  EXPECT_EQ(result.max_y, 4);
  EXPECT_EQ(result.mean_error, 0.0) << "the NaN channel is left out of the mean";
  EXPECT_FALSE(result.passed);
}

TEST(ImageCompare, NanPixelThatAlsoDiffersIsCountedOnce) {
  const Image reference = gradient_image(5, 5);
  Image test = reference;
  test.at(1, 1, 0) = INFINITY;
  test.at(1, 1, 2) += 0.5f;
  const ImageComparison result = compare_images(reference, test, {});
  EXPECT_EQ(result.fail_pixels, 1u);
  EXPECT_EQ(result.nonfinite_mismatch_pixels, 1u);
  EXPECT_EQ(result.nan_pixels_test, 0u);
}

TEST(ImageCompare, NanAtTheSamePlaceInBothImagesMatches) {
  Image reference = gradient_image(5, 5);
  reference.at(3, 0, 1) = NAN;
  const ImageComparison result = compare_images(reference, reference, {});
  EXPECT_EQ(result.nan_pixels_reference, 1u);
  EXPECT_EQ(result.nan_pixels_test, 1u);
  EXPECT_EQ(result.nonfinite_mismatch_pixels, 0u);
  EXPECT_EQ(result.fail_pixels, 0u);
  EXPECT_TRUE(result.passed);
}

}  // namespace image_compare_test
}  // namespace rtpro
