#pragma once
// Numerical comparison of a test image against a reference, for regression tests and
// `rtpro compare`. Differences are per channel value, |reference - test|; a pixel warns or fails
// when ANY of its channels differs by more than the threshold.
//
// Non-finite values: a channel that is NaN or infinite in one image and not the same non-finite
// value in the other has an infinite error: the pixel counts as warning and failing and max_error
// becomes infinite. Such channels count as zero error in the mean, RMS and PSNR, which would
// otherwise all be infinite or NaN and say nothing about the rest of the image.
#include "rtpro/image/image.h"

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rtpro {

// Two channel values not finite both: the same infinity, or NaN both (whatever their payloads).
inline bool same_non_finite(float a, float b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

struct CompareThresholds {
  // The defaults follow idiff: anything above float rounding noise fails.
  float fail = 1e-6f;
  float warn = 1e-6f;
  double fail_percent = 0.0;             // how many pixels (percent) may fail and still pass
  std::optional<double> max_mean_error;  // when set, a higher mean error also fails
};

struct ImageComparison {
  // Non-empty when the images cannot be compared (different size or channels); the comparison
  // then fails and no metric below is meaningful.
  std::string incompatibility;

  int width = 0;
  int height = 0;
  std::size_t pixel_count = 0;

  double mean_error = 0.0;  // mean over all channel values
  double rms_error = 0.0;
  double psnr = 0.0;  // dB with a peak of 1.0; +infinity for identical images
  // Relative MSE: the mean over channel values of (test − reference)² / (reference² + 0.01)
  // (Rousselle et al. 2011), how renderers compare noise against a long reference; finite
  // channels only.
  double rel_mse = 0.0;
  // Per channel, the mean of each image's finite values.
  std::vector<double> reference_means, test_means;
  double max_error = 0.0;
  int max_x = 0;
  int max_y = 0;
  std::string max_channel;  // channel name

  std::size_t warn_pixels = 0;           // pixels with a channel over the warn threshold
  std::size_t fail_pixels = 0;           // pixels with a channel over the fail threshold
  std::size_t nan_pixels_reference = 0;  // pixels with a NaN channel
  std::size_t nan_pixels_test = 0;
  std::size_t nonfinite_mismatch_pixels = 0;  // included in warn_pixels and fail_pixels

  bool passed = false;
  std::string verdict;  // why it passed or failed, one line

  double fail_fraction() const { return pixel_count ? double(fail_pixels) / double(pixel_count) : 0.0; }
};

// Same size and channel names (in the same order) are required; otherwise the result carries an
// incompatibility and fails. The data windows are never merged.
ImageComparison compare_images(const Image& reference, const Image& test, const CompareThresholds& thresholds);

}  // namespace rtpro
