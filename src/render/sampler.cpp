#include "rtpro/render/sampler.h"

#include "rtpro/core/error.h"
#include "rtpro/core/random.h"

#include <cmath>
#include <string>

namespace rtpro {

int perfect_square_root(int spp) {
  if (spp <= 0) return 0;
  const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(spp))));
  return n * n == spp ? n : 0;
}

StratifiedSampler::StratifiedSampler(int spp, std::uint64_t seed) : strata_(perfect_square_root(spp)), seed_(seed) {
  if (strata_ == 0) throw InputError("samples per pixel must be a perfect square n×n, got " + std::to_string(spp));
  inv_strata_ = 1.0f / static_cast<float>(strata_);
}

PixelOffset StratifiedSampler::sample(std::uint64_t pixel_key, int sample_index) const {
  const std::uint64_t bits = hash_combine(hash_combine(seed_, pixel_key), static_cast<std::uint64_t>(sample_index));
  const float jitter_x = to_unit_float(bits);
  const float jitter_y = to_unit_float(bits << 24);
  const int sx = sample_index % strata_;
  const int sy = sample_index / strata_;
  // (s + jitter) / n stays below 1 because jitter <= 1 − 2⁻²⁴.
  return {(static_cast<float>(sx) + jitter_x) * inv_strata_, (static_cast<float>(sy) + jitter_y) * inv_strata_};
}

}  // namespace rtpro
