#include "denoise_buffers.h"

#include "rtpro/core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rtpro {

namespace {

std::optional<int> channel_index(const Image& image, std::string_view name) {
  const auto found = std::find(image.channels.begin(), image.channels.end(), name);
  if (found == image.channels.end()) return std::nullopt;
  return static_cast<int>(found - image.channels.begin());
}

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return text;
}

// The channels of a three-channel layer, or nothing when none of them is present. A layer present
// in part is an input error: a half-written file, or a name mistyped by whatever wrote it.
std::optional<std::array<int, 3>> find_layer(const Image& image, const ChannelNames3& names) {
  std::array<int, 3> indices{};
  std::vector<std::string> present, missing;
  for (int c = 0; c < 3; ++c) {
    const std::optional<int> index = channel_index(image, names[c]);
    (index ? present : missing).emplace_back(names[c]);
    indices[c] = index.value_or(-1);
  }
  if (present.empty()) return std::nullopt;
  if (!missing.empty())
    throw InputError("the image has " + listed(present) + " but not " + listed(missing) +
                     ": the denoiser needs all three or none");
  return indices;
}

float finite_or_zero(float value) { return std::isfinite(value) ? value : 0.0f; }

// Runs row(y) for every row of the image, in parallel: each call writes its own row only.
template <typename Row>
void for_each_row(int height, const Row& row) {
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 8), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) row(y);
  });
}

// Runs row(y) for every row of the planes' padded area (-pad <= y < height + pad), in parallel.
template <typename Row>
void for_each_padded_row(int height, int pad, const Row& row) {
  for_each_row(height + 2 * pad, [&](int y) { row(y - pad); });
}

PaddedPlane plane_of(const Image& image, int channel, int pad) {
  PaddedPlane plane(image.width, image.height, pad);
  for_each_row(image.height, [&](int y) {
    for (int x = 0; x < image.width; ++x) plane.at(x, y) = finite_or_zero(image.at(x, y, channel));
  });
  plane.extend_edges();
  return plane;
}

PaddedRgb rgb_of(const Image& image, const std::array<int, 3>& channels, int pad) {
  return {plane_of(image, channels[0], pad), plane_of(image, channels[1], pad), plane_of(image, channels[2], pad)};
}

// Noise estimates are taken over 5×5 pixels: one pixel's own has one or two degrees of freedom,
// far too noisy to scale distances with.
constexpr int kNoiseRadius = 2;

// The mean of `plane` over the (2·radius+1)² window around each pixel, counting only pixels
// inside the image, into a new plane with the given padding (edges extended).
PaddedPlane box_mean(const PaddedPlane& plane, int radius, int pad) {
  const int width = plane.width(), height = plane.height();
  PaddedPlane across(width, height, 0), result(width, height, pad);
  for_each_row(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const int x0 = std::max(0, x - radius), x1 = std::min(width - 1, x + radius);
      float sum = 0.0f;
      for (int i = x0; i <= x1; ++i) sum += plane.at(i, y);
      across.at(x, y) = sum / static_cast<float>(x1 - x0 + 1);
    }
  });
  for_each_row(height, [&](int y) {
    const int y0 = std::max(0, y - radius), y1 = std::min(height - 1, y + radius);
    for (int x = 0; x < width; ++x) {
      float sum = 0.0f;
      for (int i = y0; i <= y1; ++i) sum += across.at(x, i);
      result.at(x, y) = sum / static_cast<float>(y1 - y0 + 1);
    }
  });
  result.extend_edges();
  return result;
}

// The median of `plane` over the (2·radius+1)² window around each pixel (inside the image).
PaddedPlane window_median(const PaddedPlane& plane, int radius) {
  const int width = plane.width(), height = plane.height();
  PaddedPlane result(width, height, 0);
  for_each_row(height, [&](int y) {
    std::vector<float> window;
    for (int x = 0; x < width; ++x) {
      window.clear();
      for (int j = std::max(0, y - radius); j <= std::min(height - 1, y + radius); ++j)
        for (int i = std::max(0, x - radius); i <= std::min(width - 1, x + radius); ++i)
          window.push_back(plane.at(i, j));
      const auto middle = window.begin() + static_cast<std::ptrdiff_t>(window.size() / 2);
      std::nth_element(window.begin(), middle, window.end());
      result.at(x, y) = *middle;
    }
  });
  return result;
}

// The variance of a pixel's difference from the median of its eight neighbours, in units of the
// pixels' own noise variance.
constexpr float kResidualVariance = 1.2f;

// The noise of one channel, from each pixel's difference to the median of its eight neighbours:
// for independent noise of variance σ² that difference has a variance of about 1.2·σ² (the median
// of eight has 0.2·σ²). Edges and texture the features do not explain count as noise too.
struct NoiseResidual {
  PaddedPlane squared;  // the difference², over 1.2: an estimate of σ² with one degree of freedom
  PaddedPlane level;    // the median of the eight neighbours
};

NoiseResidual residual_from_neighbours(const PaddedPlane& colour) {
  const int width = colour.width(), height = colour.height();
  NoiseResidual r{PaddedPlane(width, height, 0), PaddedPlane(width, height, 0)};
  for_each_row(height, [&](int y) {
    std::array<float, 8> neighbours;
    for (int x = 0; x < width; ++x) {
      int n = 0;
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i)
          if (i != 0 || j != 0)
            neighbours[n++] = colour.at(std::clamp(x + i, 0, width - 1), std::clamp(y + j, 0, height - 1));
      std::nth_element(neighbours.begin(), neighbours.begin() + 4, neighbours.end());
      const float d = colour.at(x, y) - neighbours[4];
      r.squared.at(x, y) = d * d / kResidualVariance;
      r.level.at(x, y) = neighbours[4];
    }
  });
  return r;
}

// The variance of each pixel's mean colour as the renderer measured it: its variance layer, or
// (A−B)²/4 from its half-buffers (A and B independent and alike: E[(A−B)²] = 4·Var(mean)).
// Nothing when there are neither, or when they are zero in every pixel.
using MeasuredVariance = std::array<PaddedPlane, 3>;

std::optional<MeasuredVariance> measured_variance(const Image& image, bool& from_variance_layer) {
  const auto half_a = find_layer(image, kHalfAChannels);
  const auto half_b = find_layer(image, kHalfBChannels);
  if (half_a.has_value() != half_b.has_value())
    throw InputError(std::string("the image has the half-buffer ") + (half_a ? "half_a" : "half_b") + " but not " +
                     (half_a ? "half_b" : "half_a") + ": both or neither");
  const auto variance = find_layer(image, kVarianceChannels);
  from_variance_layer = variance.has_value();
  if (!variance && !half_a) return std::nullopt;
  MeasuredVariance measured;
  std::vector<char> row_has_noise(static_cast<std::size_t>(image.height), 0);
  for (int c = 0; c < 3; ++c) {
    measured[c] = PaddedPlane(image.width, image.height, 0);
    for_each_row(image.height, [&](int y) {
      for (int x = 0; x < image.width; ++x) {
        float v;
        if (variance) {
          v = finite_or_zero(image.at(x, y, (*variance)[c]));
        } else {
          const float d = finite_or_zero(image.at(x, y, (*half_a)[c])) - finite_or_zero(image.at(x, y, (*half_b)[c]));
          v = 0.25f * d * d;
        }
        measured[c].at(x, y) = std::isfinite(v) && v > 0.0f ? v : 0.0f;
        if (measured[c].at(x, y) > 0.0f) row_has_noise[static_cast<std::size_t>(y)] = 1;
      }
    });
  }
  // A film of one sample per pixel writes that sample as both halves, and a variance of zero: no
  // measure at all, not a noise-free render.
  if (std::find(row_has_noise.begin(), row_has_noise.end(), 1) == row_has_noise.end()) return std::nullopt;
  return measured;
}

// How far the neighbourhood's estimate may exceed the renderer's measure before it is taken for
// detail: measured on heavy-tailed renders, the neighbourhood's estimate works better wherever
// noise is present (a factor of 2 cost relMSE, 8 did not); where the samples agree it is detail.
constexpr float kMeasuredNoiseHeadroom = 8.0f;

// The median of a χ² variable with one degree of freedom over its mean: scales a median of
// squared residuals to a variance.
constexpr float kChiSquaredMedian = 0.455f;
// Part of a pixel's expected squared difference, as a fraction of the level²: even in noise-free
// surroundings, with the default threshold of 32, a pixel must stand √2 times the level above it
// (2.4 times as bright, in every channel) to be taken for a firefly.
constexpr float kFireflyLevelFloor = 1.0f / 16.0f;

// How far each pixel is a firefly beyond `threshold`: u = the mean over channels of residual² over
// its expected value. The expectation is robust (the median over 5×5 pixels, so a firefly does
// not excuse itself) plus level²/16 (so a small highlight in clean surroundings is not taken for
// one). Pure noise gives u ~ χ²₃/3 (mean 1); a firefly, hundreds. With the sample variance of
// each pixel's mean (`sample_variance`), a pixel whose samples agree is a detail however bright:
// one bright sample among n lifts the mean by F/n and its variance to about (F/n)², while a detail
// every sample sees has none. (Half-buffers cannot tell: two bright samples, one in each half,
// look like agreement.)
PaddedPlane firefly_distance_of(const std::array<NoiseResidual, 3>& residuals, const MeasuredVariance* sample_variance,
                                float threshold, int pad, std::size_t& fireflies) {
  const int width = residuals[0].squared.width(), height = residuals[0].squared.height();
  std::array<PaddedPlane, 3> expected;
  for (int c = 0; c < 3; ++c) expected[c] = window_median(residuals[c].squared, kNoiseRadius);
  PaddedPlane distance(width, height, pad);
  std::vector<int> row_count(static_cast<std::size_t>(height), 0);
  for_each_row(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      float u = 0.0f;
      for (int c = 0; c < 3; ++c) {
        const float level = residuals[c].level.at(x, y);
        u += residuals[c].squared.at(x, y) /
             (expected[c].at(x, y) / kChiSquaredMedian + kFireflyLevelFloor * level * level + 1e-12f);
      }
      u /= 3.0f;
      if (u > threshold && sample_variance) {
        float own = 0.0f, deviation = 0.0f;
        for (int c = 0; c < 3; ++c) {
          own += (*sample_variance)[c].at(x, y);
          deviation += residuals[c].squared.at(x, y) * kResidualVariance;
        }
        if (own < 0.25f * deviation) continue;
      }
      if (u > threshold) {
        distance.at(x, y) = std::min(u - threshold, 80.0f);
        ++row_count[static_cast<std::size_t>(y)];
      }
    }
  });
  distance.extend_edges();
  for (int count : row_count) fireflies += static_cast<std::size_t>(count);
  return distance;
}

// Inverse depth, 0 where the camera ray hit nothing (depth 0), scaled so its mean over the hits
// is 1: a plane's inverse depth is affine in screen space, and the background is infinitely far.
PaddedPlane inverse_depth(const Image& image, int channel, int pad) {
  PaddedPlane plane(image.width, image.height, pad);
  double sum = 0.0;
  std::size_t hits = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float z = image.at(x, y, channel);
      const float w = std::isfinite(z) && z > 0.0f ? 1.0f / z : 0.0f;
      plane.at(x, y) = std::isfinite(w) ? w : 0.0f;
      if (plane.at(x, y) > 0.0f) {
        sum += plane.at(x, y);
        ++hits;
      }
    }
  if (hits > 0) {
    const float scale = static_cast<float>(static_cast<double>(hits) / sum);
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) plane.at(x, y) *= scale;
  }
  plane.extend_edges();
  return plane;
}

// The smaller of the two one-sided differences along x (dx = 1) or y: a plane's slope, but not
// the jump at its silhouette.
PaddedPlane one_sided_slope(const PaddedPlane& plane, int dx, int dy, int pad) {
  const int width = plane.width(), height = plane.height();
  PaddedPlane slope(width, height, pad);
  for_each_row(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const float centre = plane.at(x, y);
      const bool has_before = x - dx >= 0 && y - dy >= 0;
      const bool has_after = x + dx < width && y + dy < height;
      const float before = has_before ? std::abs(centre - plane.at(x - dx, y - dy)) : INFINITY;
      const float after = has_after ? std::abs(plane.at(x + dx, y + dy) - centre) : INFINITY;
      const float s = std::min(before, after);
      slope.at(x, y) = std::isfinite(s) ? s : 0.0f;
    }
  });
  slope.extend_edges();
  return slope;
}

void check_size(const Image& image) {
  if (image.width <= 0 || image.height <= 0) throw InputError("the image has no pixels");
  const std::size_t expected =
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * image.channels.size();
  if (image.data.size() != expected)
    throw InputError("the image's pixel data holds " + std::to_string(image.data.size()) + " values, not the " +
                     std::to_string(expected) + " of " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " pixels of " + std::to_string(image.channels.size()) +
                     " channels");
}

}  // namespace

DenoiseBuffers gather_denoise_buffers(const Image& image, const DenoiseSettings& settings, int pad) {
  check_size(image);
  const std::optional<std::array<int, 3>> colour = find_layer(image, kColourChannels);
  if (!colour) throw InputError("the image has no R, G, B colour channels to denoise");
  const auto noisy = find_layer(image, kNoisyChannels);
  const auto albedo = find_layer(image, kAlbedoChannels);
  const auto normal = find_layer(image, kNormalChannels);
  const std::optional<int> depth = channel_index(image, kDepthChannel);

  DenoiseBuffers buffers;
  buffers.width = image.width;
  buffers.height = image.height;
  buffers.colour = rgb_of(image, noisy.value_or(*colour), pad);

  // The noise: from the neighbourhood, capped by what the renderer measured when it did.
  bool from_variance_layer = false;
  const std::optional<MeasuredVariance> measured = measured_variance(image, from_variance_layer);
  std::array<NoiseResidual, 3> residuals;
  for (int c = 0; c < 3; ++c) {
    residuals[c] = residual_from_neighbours(buffers.colour[c]);
    buffers.variance[c] = box_mean(residuals[c].squared, kNoiseRadius, pad);
    if (measured) {
      const PaddedPlane cap = box_mean((*measured)[c], kNoiseRadius, pad);
      for_each_padded_row(image.height, pad, [&](int y) {
        for (int x = -pad; x < image.width + pad; ++x)
          buffers.variance[c].at(x, y) = std::min(buffers.variance[c].at(x, y), kMeasuredNoiseHeadroom * cap.at(x, y));
      });
    }
  }
  buffers.report.used_measured_noise = measured.has_value();
  if (settings.firefly_threshold > 0.0f)
    buffers.firefly_distance = firefly_distance_of(residuals, measured && from_variance_layer ? &*measured : nullptr,
                                                   settings.firefly_threshold, pad, buffers.report.firefly_pixels);

  auto add_features = [&](const std::array<int, 3>& channels) {
    const int first = static_cast<int>(buffers.features.size());
    for (int c = 0; c < 3; ++c) buffers.features.push_back(plane_of(image, channels[c], pad));
    return first;
  };
  if (albedo) {
    buffers.albedo_first = add_features(*albedo);
    buffers.report.features.emplace_back("albedo");
  }
  if (normal) {
    buffers.normal_first = add_features(*normal);
    buffers.report.features.emplace_back("normal");
  }
  if (depth) {
    buffers.depth = static_cast<int>(buffers.features.size());
    buffers.features.push_back(inverse_depth(image, *depth, pad));
    buffers.depth_slope_x = one_sided_slope(buffers.features.back(), 1, 0, pad);
    buffers.depth_slope_y = one_sided_slope(buffers.features.back(), 0, 1, pad);
    buffers.report.features.emplace_back("depth");
  }

  // Divided by the albedo, the colour is the light arriving: smooth across a texture's edges,
  // where the colour itself is not. The variance scales with the square.
  if (buffers.albedo_first >= 0)
    for (int c = 0; c < 3; ++c)
      for_each_padded_row(image.height, pad, [&](int y) {
        for (int x = -pad; x < image.width + pad; ++x) {
          const float inverse = 1.0f / demodulation_factor(buffers, x, y, c);
          buffers.colour[c].at(x, y) *= inverse;
          buffers.variance[c].at(x, y) *= inverse * inverse;
        }
      });
  return buffers;
}

float demodulation_factor(const DenoiseBuffers& buffers, int x, int y, int channel) {
  if (buffers.albedo_first < 0) return 1.0f;
  return std::max(buffers.features[buffers.albedo_first + channel].at(x, y), 0.0f) + kDemodulationFloor;
}

}  // namespace rtpro
