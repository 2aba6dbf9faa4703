#include "rtpro/image/image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rtpro {

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ",") + name;
  return text;
}

std::string incompatibility_between(const Image& reference, const Image& test) {
  std::ostringstream text;
  if (reference.width != test.width || reference.height != test.height)
    text << "the images differ in size: reference " << reference.width << "x" << reference.height << ", test "
         << test.width << "x" << test.height;
  else if (reference.channels != test.channels)
    text << "the images differ in channels: reference " << joined(reference.channels) << ", test "
         << joined(test.channels);
  return text.str();
}

// A read-only view for OpenImageIO 2.4, which has no const wrapping constructor; compare() only
// reads the pixels.
OIIO::ImageBuf wrap(const Image& image) {
  OIIO::ImageSpec spec(image.width, image.height, image.channel_count(), OIIO::TypeDesc::FLOAT);
  spec.channelnames = image.channels;
  return OIIO::ImageBuf(spec, const_cast<float*>(image.data.data()));
}

// What ImageBufAlgo::compare leaves out: it reports an infinite max error where only one image is
// NaN or infinite, but neither counts that pixel as failing nor counts NaNs. `comparison` holds
// its results; this adds the non-finite pixels it skipped.
void count_non_finite(const Image& reference, const Image& test, const CompareThresholds& thresholds,
                      ImageComparison& comparison) {
  const std::size_t stride = reference.channels.size();
  for (std::size_t pixel = 0; pixel < comparison.pixel_count; ++pixel) {
    bool nan_in_reference = false, nan_in_test = false, mismatch = false;
    float finite_error = 0.0f;  // what compare() already judged this pixel by
    for (std::size_t c = 0; c < stride; ++c) {
      const float a = reference.data[pixel * stride + c];
      const float b = test.data[pixel * stride + c];
      nan_in_reference |= std::isnan(a);
      nan_in_test |= std::isnan(b);
      if (std::isfinite(a) && std::isfinite(b)) finite_error = std::max(finite_error, std::abs(a - b));
      else mismatch |= !same_non_finite(a, b);
    }
    comparison.nan_pixels_reference += nan_in_reference;
    comparison.nan_pixels_test += nan_in_test;
    if (!mismatch) continue;
    ++comparison.nonfinite_mismatch_pixels;
    comparison.fail_pixels += !(finite_error > thresholds.fail);
    comparison.warn_pixels += !(finite_error > thresholds.warn);
  }
}

// Relative MSE and the per-channel means, in doubles over every finite channel value.
void add_noise_figures(const Image& reference, const Image& test, ImageComparison& comparison) {
  constexpr double kEpsilon = 0.01;
  const std::size_t stride = reference.channels.size();
  std::vector<double> reference_sum(stride, 0.0), test_sum(stride, 0.0);
  std::vector<std::size_t> reference_count(stride, 0), test_count(stride, 0);
  double rel_sum = 0.0;
  std::size_t rel_count = 0;
  for (std::size_t i = 0; i < reference.data.size(); ++i) {
    const std::size_t c = i % stride;
    const double a = reference.data[i], b = test.data[i];
    if (std::isfinite(a)) {
      reference_sum[c] += a;
      ++reference_count[c];
    }
    if (std::isfinite(b)) {
      test_sum[c] += b;
      ++test_count[c];
    }
    if (std::isfinite(a) && std::isfinite(b)) {
      rel_sum += (b - a) * (b - a) / (a * a + kEpsilon);
      ++rel_count;
    }
  }
  comparison.rel_mse = rel_count ? rel_sum / double(rel_count) : 0.0;
  for (std::size_t c = 0; c < stride; ++c) {
    comparison.reference_means.push_back(reference_count[c] ? reference_sum[c] / double(reference_count[c]) : 0.0);
    comparison.test_means.push_back(test_count[c] ? test_sum[c] / double(test_count[c]) : 0.0);
  }
}

void judge(const CompareThresholds& thresholds, ImageComparison& comparison) {
  std::ostringstream verdict;
  const double allowed_failures = thresholds.fail_percent / 100.0 * double(comparison.pixel_count);
  if (double(comparison.fail_pixels) > allowed_failures) {
    verdict << comparison.fail_pixels << " pixels (" << 100.0 * comparison.fail_fraction() << "%) differ by more than "
            << thresholds.fail << " (allowed: " << thresholds.fail_percent << "%)";
  } else if (thresholds.max_mean_error && !(comparison.mean_error <= *thresholds.max_mean_error)) {
    verdict << "the mean error " << comparison.mean_error << " exceeds " << *thresholds.max_mean_error;
  } else {
    comparison.passed = true;
    verdict << "within tolerance";
    if (comparison.fail_pixels > 0) verdict << ", " << comparison.fail_pixels << " pixels over the fail threshold";
    if (comparison.warn_pixels > 0) verdict << ", " << comparison.warn_pixels << " pixels over the warn threshold";
  }
  comparison.verdict = verdict.str();
}

}  // namespace

ImageComparison compare_images(const Image& reference, const Image& test, const CompareThresholds& thresholds) {
  ImageComparison comparison;
  comparison.incompatibility = incompatibility_between(reference, test);
  if (!comparison.incompatibility.empty()) {
    comparison.verdict = comparison.incompatibility;
    return comparison;
  }
  comparison.width = reference.width;
  comparison.height = reference.height;
  comparison.pixel_count = static_cast<std::size_t>(reference.width) * reference.height;
  if (comparison.pixel_count == 0 || reference.channels.empty()) {
    comparison.passed = true;
    comparison.psnr = INFINITY;
    comparison.verdict = "both images are empty";
    return comparison;
  }

  const auto results = OIIO::ImageBufAlgo::compare(wrap(reference), wrap(test), thresholds.fail, thresholds.warn);
  comparison.mean_error = results.meanerror;
  comparison.rms_error = results.rms_error;
  // Not results.PSNR: OpenImageIO 2.4 takes the largest pixel value (at least 1) as the peak, so
  // its PSNR depends on image content; rtpro's peak is 1.0.
  comparison.psnr = results.rms_error > 0.0 ? 20.0 * std::log10(1.0 / results.rms_error) : INFINITY;
  comparison.max_error = results.maxerror;
  comparison.max_x = results.maxx;
  comparison.max_y = results.maxy;
  comparison.max_channel = reference.channels[std::clamp(results.maxc, 0, reference.channel_count() - 1)];
  comparison.warn_pixels = results.nwarn;
  comparison.fail_pixels = results.nfail;
  count_non_finite(reference, test, thresholds, comparison);
  add_noise_figures(reference, test, comparison);
  judge(thresholds, comparison);
  return comparison;
}

}  // namespace rtpro
