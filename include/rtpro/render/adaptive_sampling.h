#pragma once
// Adaptive sampling: between passes, which pixels take more samples. A pixel goes on while it has
// fewer than `min_samples` or its error is at least `threshold`; the pixels around one that goes on
// go on too (a 3×3 dilation), so a noisy region's edge is not left behind. Two errors:
// - cycles, Cycles' (after Dammertz et al. 2010, "A hierarchical automatic stopping condition for
//   Monte Carlo global illumination", section 2.1): the difference between the mean of all its
//   samples and the mean of its even-numbered half, over the square root of its brightness,
//     error = Σ_rgb |I − A| / (0.0001 + √(Σ_rgb I)),
//   with I the mean of all samples and A of the even ones. Every pixel stops at about the same
//   error, as Cycles' users know it.
// - relmse: how much one more sample would lower the pixel's relative mean squared error (the
//   measure of benchmarks, with the pixel's own mean in place of the reference):
//     error = √(r / n),  r = ⅓ Σ_rgb (s² / n) / (I² + 0.01),
//   with s² the sample variance and n the samples. Stopping every pixel at one marginal gain gives
//   each pixel samples in proportion to s / √(I² + 0.01), the allocation with the lowest relMSE
//   for the samples spent; equal errors (Cycles') leave the relMSE of the whole image about where
//   uniform sampling has it.
#include "rtpro/render/film.h"
#include "rtpro/render/progressive_film.h"

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace rtpro {

enum class NoiseMetric { kCycles, kRelMse };

// "cycles" or "relmse"; throws InputError naming both.
NoiseMetric parse_noise_metric(std::string_view name);
const char* noise_metric_name(NoiseMetric metric);

struct AdaptiveSampling {
  float threshold = 0.0f;  // 0: every pixel takes every sample
  int min_samples = 0;     // resolved: at least 1
  NoiseMetric metric = NoiseMetric::kCycles;
};

// The samples a pixel takes before its error counts: `min_samples`, or when 0, 16 or ⌈√(1/threshold)⌉
// if more (the even half must be a usable estimate); never above spp.
int resolved_min_samples(int min_samples, float threshold, int spp);

// The pixel's error; infinite below two samples. Reads the even half (cycles) or the squares (relmse).
float pixel_error(const PixelAccumulator& acc, NoiseMetric metric);

// One flag per pixel of the film's region (row-major): 1 when the pixel takes the next pass.
// Returns how many do.
std::size_t active_pixels(const ProgressiveFilm& film, const AdaptiveSampling& settings,
                          std::vector<std::uint8_t>& mask);

}  // namespace rtpro
