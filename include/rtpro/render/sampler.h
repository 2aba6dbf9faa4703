#pragma once
// The one source of randomness in rendering. Every value is a pure function of
// (seed, pixel, sample index, dimension), so images never depend on threads, tiles, regions,
// ranks or resumes. Dimensions come in 2D pairs (render/sampling/sample_dimensions.h says who uses which).
//
// Stratified: the spp samples of a pixel fall one per stratum of a columns×rows grid over the
// pixel (strata_grid: n×n for a square count, else the most nearly square factorisation, 8×6 for
// 48, down to 7×1 for a prime), in sample order (sample s takes stratum (s mod columns,
// s div columns)). Every later dimension pair is stratified over the same grid, but visits its strata in an order of its own — a pseudo-random permutation
// per pixel and dimension — so that, e.g., the lens position is not correlated with the position
// in the pixel (pbrt's padded stratified sampling).
#include "rtpro/core/random.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

struct Sample2D {
  float x, y;  // each in [0, 1)
};

// One camera sample: the pixel and the sample's index in it.
struct SampleKey {
  std::uint64_t pixel_key;  // y · width + x in the full image
  int sample_index;
};
using PixelOffset = Sample2D;

// The strata of spp samples: columns × rows == spp, rows the largest divisor of spp that is at
// most √spp (so a square count keeps its n×n grid). {0, 0} for spp <= 0.
struct StrataGrid {
  int columns, rows;
};
StrataGrid strata_grid(int spp);

class StratifiedSampler {
 public:
  // spp >= 1.
  StratifiedSampler(int spp, std::uint64_t seed);

  int samples_per_pixel() const { return grid_.columns * grid_.rows; }
  StrataGrid grid() const { return grid_; }

  // `pixel_key` identifies the pixel in the full image (y·width + x); sample_index is in
  // [0, samples_per_pixel()). Dimensions 0–1: stratum (s mod columns, s div columns) jittered by
  // the top 24 bits of hash_combine(hash_combine(seed, pixel_key), s) (x) and the next 24 (y).
  PixelOffset pixel_offset(std::uint64_t pixel_key, int sample_index) const;

  // pixel_offset(pixel_keys[i], first_sample + k) into out[i · samples + k], for k in [0, samples)
  // (out.size() == pixel_keys.size() · samples; the samples within [0, samples_per_pixel())), bit
  // for bit. Worked in runs of pixels, each step for the whole run before the next, so that the
  // AVX2 clone hashes four pixels or samples at a time (one at a time, a 1-spp frame's three mixes
  // a sample were a tenth of its instructions).
  void pixel_offsets(std::span<const std::uint64_t> pixel_keys, int first_sample, int samples,
                     std::span<PixelOffset> out) const;

  // The 2D value of dimension pair (dimension, dimension + 1) for this sample; dimension is even
  // and at least 2.
  Sample2D sample_2d(std::uint64_t pixel_key, int sample_index, int dimension) const;
  // sample_2d of each key into out[i] (out.size() == keys.size()).
  void sample_2d(std::span<const SampleKey> keys, int dimension, std::span<Sample2D> out) const {
    for (std::size_t i = 0; i < keys.size(); ++i)
      out[i] = sample_2d(keys[i].pixel_key, keys[i].sample_index, dimension);
  }

  // A 1D value of `dimension`, stratified over spp strata in a permuted order.
  float sample_1d(std::uint64_t pixel_key, int sample_index, int dimension) const;
  // sample_1d of each key into out[i] (out.size() == keys.size()).
  void sample_1d(std::span<const SampleKey> keys, int dimension, std::span<float> out) const {
    for (std::size_t i = 0; i < keys.size(); ++i)
      out[i] = sample_1d(keys[i].pixel_key, keys[i].sample_index, dimension);
  }

  // Point `index` of the per_axis × per_axis stratified points a shading point spreads over an
  // area light (number `light` in the scene) at the bounce-th surface of this camera sample:
  // stratum (index mod per_axis, index div per_axis), jittered by a hash of all of them and the
  // seed. Glass branches of one sample that reach their bounce-th surface share the values.
  Sample2D light_sample(std::uint64_t pixel_key, int sample_index, int bounce, int light, int index,
                        int per_axis) const;

 private:
  // A later dimension's hash for this pixel, the stratum count, and the stratum this sample takes.
  struct PermutedSample {
    std::uint64_t pixel_dimension;
    std::uint32_t count;
    std::uint32_t stratum;
  };
  PermutedSample permuted(std::uint64_t pixel_key, int sample_index, int dimension) const;
  std::uint64_t sample_bits(std::uint64_t pixel_key, int sample_index) const;

  StrataGrid grid_;
  float inv_columns_, inv_rows_;
  std::uint64_t seed_;
  // mix64(s) of each sample index s: hash_combine(bits, s) is mix64(bits ^ sample_mixes_[s]), one
  // mix of a key's three fewer to work out.
  std::vector<std::uint64_t> sample_mixes_;
  // Sample s's stratum (s mod columns, s div columns), as floats: no division per key.
  std::vector<Sample2D> strata_;
};

// Element `index` of a pseudo-random permutation of [0, count) chosen by `key` (Kensler's
// hash-based cycle walking): a bijection for every key, computed without storing the permutation.
std::uint32_t permutation_element(std::uint32_t index, std::uint32_t count, std::uint32_t key);

}  // namespace rtpro
