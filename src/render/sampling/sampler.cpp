#include "rtpro/render/sampler.h"

#include "rtpro/core/avx2_clones.h"
#include "rtpro/core/error.h"
#include "rtpro/core/random.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace rtpro {

StrataGrid strata_grid(int spp) {
  if (spp <= 0) return {0, 0};
  int rows = static_cast<int>(std::sqrt(static_cast<double>(spp)));
  while (rows * rows > spp) --rows;
  while (spp % rows != 0) --rows;
  return {spp / rows, rows};
}

std::uint32_t permutation_element(std::uint32_t index, std::uint32_t count, std::uint32_t key) {
  if (count <= 1) return 0;
  // The smallest all-ones mask covering count − 1: the hash permutes [0, mask] and walks the
  // cycle until it lands inside [0, count).
  std::uint32_t mask = count - 1;
  mask |= mask >> 1;
  mask |= mask >> 2;
  mask |= mask >> 4;
  mask |= mask >> 8;
  mask |= mask >> 16;
  std::uint32_t i = index;
  do {
    i ^= key;
    i *= 0xe170893du;
    i ^= key >> 16;
    i ^= (i & mask) >> 4;
    i ^= key >> 8;
    i *= 0x0929eb3fu;
    i ^= key >> 23;
    i ^= (i & mask) >> 1;
    i *= 1u | key >> 27;
    i *= 0x6935fa69u;
    i ^= (i & mask) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & mask) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & mask) >> 2;
    i *= 0xc860a3dfu;
    i &= mask;
    i ^= i >> 5;
  } while (i >= count);
  return (i + key) % count;
}

StratifiedSampler::StratifiedSampler(int spp, std::uint64_t seed) : grid_(strata_grid(spp)), seed_(seed) {
  if (spp <= 0) throw InputError("samples per pixel must be at least 1, got " + std::to_string(spp));
  inv_columns_ = 1.0f / static_cast<float>(grid_.columns);
  inv_rows_ = 1.0f / static_cast<float>(grid_.rows);
  sample_mixes_.resize(static_cast<std::size_t>(spp));
  strata_.resize(static_cast<std::size_t>(spp));
  for (int s = 0; s < spp; ++s) {
    sample_mixes_[static_cast<std::size_t>(s)] = mix64(static_cast<std::uint64_t>(s));
    strata_[static_cast<std::size_t>(s)] = {static_cast<float>(s % grid_.columns),
                                            static_cast<float>(s / grid_.columns)};
  }
}

namespace {

constexpr std::size_t kOffsetRun = 64;

// The offset of a sample whose hash is `bits` in `stratum` of the pixel's grid, jittered by the
// hash's top 24 bits (x) and the next 24 (y): to_unit_float's values, the integers converted
// through int32 (exact, as through uint64, and the AVX2 clone has that conversion in vectors).
// (s + jitter) / n stays below 1 because jitter <= 1 − 2⁻²⁴.
inline PixelOffset offset_of(std::uint64_t bits, const Sample2D& stratum, float inv_columns, float inv_rows) {
  const auto jitter_x = static_cast<std::int32_t>(bits >> 40);
  const auto jitter_y = static_cast<std::int32_t>((bits >> 16) & 0xFFFFFFu);
  return {(stratum.x + static_cast<float>(jitter_x) * (1.0f / 16777216.0f)) * inv_columns,
          (stratum.y + static_cast<float>(jitter_y) * (1.0f / 16777216.0f)) * inv_rows};
}

// StratifiedSampler::pixel_offsets for pixels[0, count), count <= kOffsetRun, samples
// [first_sample, first_sample + samples) of each: the arithmetic of sample_bits, a step at a time
// for the whole run, each pixel's own hash once (a key's two mixes of three), each sample's one mix
// across the pixels at one sample a pixel, across the samples at more.
RTPRO_AVX2_CLONES
void pixel_offsets_run(std::uint64_t seed, const std::uint64_t* pixels, std::size_t count, int first_sample,
                       int samples, const std::uint64_t* sample_mixes, const Sample2D* strata, float inv_columns,
                       float inv_rows, PixelOffset* out) {
  std::uint64_t pixel_bits[kOffsetRun];
  for (std::size_t i = 0; i < count; ++i) pixel_bits[i] = mix64(seed ^ mix64(pixels[i]));
  const std::uint64_t* mixes = sample_mixes + first_sample;
  const Sample2D* sample_strata = strata + first_sample;
  if (samples == 1) {
    for (std::size_t i = 0; i < count; ++i) pixel_bits[i] = mix64(pixel_bits[i] ^ mixes[0]);
    for (std::size_t i = 0; i < count; ++i) out[i] = offset_of(pixel_bits[i], sample_strata[0], inv_columns, inv_rows);
    return;
  }
  const auto per_pixel = static_cast<std::size_t>(samples);
  for (std::size_t i = 0; i < count; ++i) {
    PixelOffset* pixel_out = out + i * per_pixel;
    for (std::size_t k = 0; k < per_pixel; ++k)
      pixel_out[k] = offset_of(mix64(pixel_bits[i] ^ mixes[k]), sample_strata[k], inv_columns, inv_rows);
  }
}

}  // namespace

void StratifiedSampler::pixel_offsets(std::span<const std::uint64_t> pixel_keys, int first_sample, int samples,
                                      std::span<PixelOffset> out) const {
  const auto per_pixel = static_cast<std::size_t>(samples);
  for (std::size_t first = 0; first < pixel_keys.size(); first += kOffsetRun)
    pixel_offsets_run(seed_, pixel_keys.data() + first, std::min(kOffsetRun, pixel_keys.size() - first), first_sample,
                      samples, sample_mixes_.data(), strata_.data(), inv_columns_, inv_rows_,
                      out.data() + first * per_pixel);
}

std::uint64_t StratifiedSampler::sample_bits(std::uint64_t pixel_key, int sample_index) const {
  return hash_combine(hash_combine(seed_, pixel_key), static_cast<std::uint64_t>(sample_index));
}

PixelOffset StratifiedSampler::pixel_offset(std::uint64_t pixel_key, int sample_index) const {
  return offset_of(sample_bits(pixel_key, sample_index), strata_[static_cast<std::size_t>(sample_index)], inv_columns_,
                   inv_rows_);
}

StratifiedSampler::PermutedSample StratifiedSampler::permuted(std::uint64_t pixel_key, int sample_index,
                                                              int dimension) const {
  const std::uint64_t pixel_dimension = hash_combine(hash_combine(seed_, pixel_key), 0x5eed0000ull + dimension);
  const auto count = static_cast<std::uint32_t>(grid_.columns * grid_.rows);
  return {pixel_dimension, count,
          permutation_element(static_cast<std::uint32_t>(sample_index), count,
                              static_cast<std::uint32_t>(pixel_dimension))};
}

Sample2D StratifiedSampler::sample_2d(std::uint64_t pixel_key, int sample_index, int dimension) const {
  const auto [pixel_dimension, count, stratum] = permuted(pixel_key, sample_index, dimension);
  const std::uint64_t bits = hash_combine(pixel_dimension, static_cast<std::uint64_t>(sample_index));
  const float jitter_x = to_unit_float(bits);
  const float jitter_y = to_unit_float(bits << 24);
  const auto sx = static_cast<int>(stratum % static_cast<std::uint32_t>(grid_.columns));
  const auto sy = static_cast<int>(stratum / static_cast<std::uint32_t>(grid_.columns));
  return {(static_cast<float>(sx) + jitter_x) * inv_columns_, (static_cast<float>(sy) + jitter_y) * inv_rows_};
}

float StratifiedSampler::sample_1d(std::uint64_t pixel_key, int sample_index, int dimension) const {
  const auto [pixel_dimension, count, stratum] = permuted(pixel_key, sample_index, dimension);
  const float jitter = to_unit_float(hash_combine(pixel_dimension, static_cast<std::uint64_t>(sample_index)));
  // (s + jitter) / count < 1: jitter <= 1 − 2⁻²⁴ and the float product rounds at most to 1 − 2⁻²⁴.
  const float value = (static_cast<float>(stratum) + jitter) / static_cast<float>(count);
  return value < 1.0f ? value : 0x1.fffffep-1f;
}

Sample2D StratifiedSampler::light_sample(std::uint64_t pixel_key, int sample_index, int bounce, int light, int index,
                                         int per_axis) const {
  std::uint64_t bits =
      hash_combine(sample_bits(pixel_key, sample_index), 0x11947000ull + static_cast<std::uint64_t>(bounce));
  bits = hash_combine(hash_combine(bits, static_cast<std::uint64_t>(light)), static_cast<std::uint64_t>(index));
  const float inv = 1.0f / static_cast<float>(per_axis);
  const float x = (static_cast<float>(index % per_axis) + to_unit_float(bits)) * inv;
  const float y = (static_cast<float>(index / per_axis) + to_unit_float(bits << 24)) * inv;
  return {x < 1.0f ? x : 0x1.fffffep-1f, y < 1.0f ? y : 0x1.fffffep-1f};
}

}  // namespace rtpro
