#pragma once
// Stratified (jittered n×n) pixel sampling. Every offset is a pure function of
// (seed, pixel, sample index), so images never depend on threads, tiles or regions.
#include <cstdint>

namespace rtpro {

struct PixelOffset {
  float x, y;  // in [0, 1) within the pixel
};

class StratifiedSampler {
 public:
  // spp must be a perfect square n×n.
  StratifiedSampler(int spp, std::uint64_t seed);

  int samples_per_pixel() const { return strata_ * strata_; }
  int strata_per_axis() const { return strata_; }
  // `pixel_key` identifies the pixel in the full image (y·width + x).
  PixelOffset sample(std::uint64_t pixel_key, int sample_index) const;

 private:
  int strata_;
  float inv_strata_;
  std::uint64_t seed_;
};

// n when spp == n·n, else 0.
int perfect_square_root(int spp);

}  // namespace rtpro
