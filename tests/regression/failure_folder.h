#pragma once
// What a failing regression test leaves in the build tree, one folder per scene and backend:
// reference.png, rendered.png and diff.png to look at, rendered.exr to inspect or adopt, and
// figures.json with the numbers. figures.json is written last and atomically: a folder without it
// is incomplete and the report ignores it.
#include "rtpro/image/atomic_file_replacement.h"
#include "rtpro/image/diff_image.h"
#include "rtpro/image/image_compare.h"
#include "rtpro/image/image_io.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace rtpro::regression {

// Infinity and NaN have no JSON spelling; null stands for "not finite".
inline nlohmann::json finite_or_null(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

inline nlohmann::json comparison_figures(const ImageComparison& comparison, const CompareThresholds& thresholds) {
  nlohmann::json figures;
  figures["verdict"] = comparison.verdict;
  figures["incompatibility"] = comparison.incompatibility;
  figures["pixels"] = comparison.pixel_count;
  figures["fail_pixels"] = comparison.fail_pixels;
  figures["fail_percent"] = 100.0 * comparison.fail_fraction();
  figures["nonfinite_mismatch_pixels"] = comparison.nonfinite_mismatch_pixels;
  figures["mean_error"] = comparison.mean_error;
  figures["rms_error"] = comparison.rms_error;
  figures["psnr"] = finite_or_null(comparison.psnr);
  figures["max_error"] = finite_or_null(comparison.max_error);
  figures["max_error_at"] = {{"x", comparison.max_x}, {"y", comparison.max_y}, {"channel", comparison.max_channel}};
  figures["thresholds"] = {{"fail", thresholds.fail},
                           {"fail_percent", thresholds.fail_percent},
                           {"max_mean_error", thresholds.max_mean_error ? nlohmann::json(*thresholds.max_mean_error)
                                                                        : nlohmann::json(nullptr)}};
  return figures;
}

// Through rtpro's one atomic writer: readers see the old file or the whole new one.
inline void write_text_atomically(const std::filesystem::path& file, const std::string& text) {
  write_file_atomically(file, text);
}

// What white stands for in diff.png: the 99th percentile of the per-pixel error (the largest
// channel difference), so that a handful of edge pixels cannot turn a change of the whole image
// black; the largest difference when fewer than 1% of the pixels differ at all.
inline float diff_full_scale(const Image& reference, const Image& rendered) {
  std::vector<float> errors(static_cast<std::size_t>(reference.width) * reference.height, 0.0f);
  const std::size_t channels = reference.channels.size();
  for (std::size_t pixel = 0; pixel < errors.size(); ++pixel)
    for (std::size_t c = 0; c < channels; ++c) {
      const float error = std::abs(reference.data[pixel * channels + c] - rendered.data[pixel * channels + c]);
      if (std::isfinite(error)) errors[pixel] = std::max(errors[pixel], error);
    }
  const auto percentile = errors.begin() + static_cast<std::ptrdiff_t>(errors.size() * 99 / 100);
  std::nth_element(errors.begin(), percentile, errors.end());
  return percentile == errors.end() ? 0.0f : *percentile;  // 0: write_diff_image takes the largest
}

// `figures` gets the image names and the diff's full scale added.
inline void write_failure_folder(const std::filesystem::path& folder, const Image& reference, const Image& rendered,
                                 nlohmann::json figures) {
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const ImageWriteOptions display_options;
  write_image(folder / "reference.png", reference, display_options);
  write_image(folder / "rendered.png", rendered, display_options);
  write_image(folder / "rendered.exr", rendered, display_options);
  figures["images"] = {{"reference", "reference.png"}, {"rendered", "rendered.png"}, {"rendered_exr", "rendered.exr"}};
  const bool comparable = reference.width == rendered.width && reference.height == rendered.height &&
                          reference.channel_count() == rendered.channel_count();
  if (comparable) {
    const float full_scale = diff_full_scale(reference, rendered);
    write_diff_image(folder / "diff.png", reference, rendered, full_scale);
    figures["images"]["diff"] = "diff.png";
    figures["diff_full_scale"] = full_scale > 0.0f ? nlohmann::json(full_scale) : figures["max_error"];
  }
  write_text_atomically(folder / "figures.json", figures.dump(2) + "\n");
}

}  // namespace rtpro::regression
