#include "rtpro/render/adaptive_sampling.h"

#include "rtpro/core/error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace rtpro {

int resolved_min_samples(int min_samples, float threshold, int spp) {
  int samples = min_samples;
  if (samples <= 0) {
    // Enough for the even half to be a usable estimate; more for stricter thresholds.
    samples = 16;
    // Capped at the spp before the conversion: a tiny threshold's root is beyond any int.
    if (threshold > 0.0f)
      samples = std::max(samples, static_cast<int>(std::min(std::ceil(std::sqrt(1.0f / threshold)),
                                                            static_cast<float>(std::max(spp, 1)))));
  }
  return std::clamp(samples, 1, std::max(spp, 1));
}

NoiseMetric parse_noise_metric(std::string_view name) {
  if (name == "cycles") return NoiseMetric::kCycles;
  if (name == "relmse") return NoiseMetric::kRelMse;
  throw InputError("unknown noise metric '" + std::string(name) + "': expected cycles or relmse");
}

const char* noise_metric_name(NoiseMetric metric) {
  switch (metric) {
    case NoiseMetric::kCycles: return "cycles";
    case NoiseMetric::kRelMse: return "relmse";
  }
  return "?";
}

namespace {

float cycles_error(const PixelAccumulator& acc) {
  const int even = (acc.samples + 1) / 2;
  const Color mean = acc.radiance / static_cast<float>(acc.samples);
  const Color even_mean = acc.even_radiance / static_cast<float>(even);
  const float difference =
      std::abs(mean.x - even_mean.x) + std::abs(mean.y - even_mean.y) + std::abs(mean.z - even_mean.z);
  const float brightness = std::max(0.0f, mean.x + mean.y + mean.z);
  return difference / (0.0001f + std::sqrt(brightness));
}

float relmse_error(const PixelAccumulator& acc) {
  const float n = static_cast<float>(acc.samples);
  float relmse = 0.0f;
  for (int c = 0; c < 3; ++c) {
    const float mean = acc.radiance[c] / n;
    const float sample_variance = std::max(0.0f, (acc.radiance_squared[c] - acc.radiance[c] * mean) / (n - 1.0f));
    relmse += sample_variance / n / (mean * mean + 0.01f);
  }
  return std::sqrt(relmse / 3.0f / n);
}

}  // namespace

float pixel_error(const PixelAccumulator& acc, NoiseMetric metric) {
  if (acc.samples < 2) return INFINITY;
  switch (metric) {
    case NoiseMetric::kCycles: return cycles_error(acc);
    case NoiseMetric::kRelMse: return relmse_error(acc);
  }
  return INFINITY;
}

std::size_t active_pixels(const ProgressiveFilm& film, const AdaptiveSampling& settings,
                          std::vector<std::uint8_t>& mask) {
  const PixelRegion& region = film.grid().region();
  const int width = region.width(), height = region.height();
  std::vector<std::uint8_t> unconverged(region.pixel_count());
  tbb::parallel_for(0, height, [&](int row) {
    for (int column = 0; column < width; ++column) {
      const PixelAccumulator& acc = film.pixel(region.x0 + column, region.y0 + row);
      const bool goes_on =
          acc.samples < settings.min_samples || !(pixel_error(acc, settings.metric) < settings.threshold);
      unconverged[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column)] =
          goes_on ? 1 : 0;
    }
  });
  mask.assign(region.pixel_count(), 0);
  std::vector<std::size_t> row_counts(static_cast<std::size_t>(height), 0);
  tbb::parallel_for(0, height, [&](int row) {
    std::size_t count = 0;
    for (int column = 0; column < width; ++column) {
      bool goes_on = false;
      for (int y = std::max(row - 1, 0); y <= std::min(row + 1, height - 1) && !goes_on; ++y)
        for (int x = std::max(column - 1, 0); x <= std::min(column + 1, width - 1) && !goes_on; ++x)
          goes_on = unconverged[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                static_cast<std::size_t>(x)] != 0;
      mask[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column)] =
          goes_on;
      count += goes_on ? 1 : 0;
    }
    row_counts[static_cast<std::size_t>(row)] = count;
  });
  std::size_t total = 0;
  for (std::size_t count : row_counts) total += count;
  return total;
}

}  // namespace rtpro
