#pragma once
// Owen-scrambled Sobol points with hash-based scrambling (Burley 2020, "Practical Hash-based Owen
// Scrambling"), the path integrator's sampler. Every dimension pair of a pixel is the first two
// Sobol dimensions, a (0, 2)-sequence: any power-of-two prefix of a pixel's samples is stratified
// in every elementary interval, which the stratified sampler only is for its one grid. Each pixel
// and dimension pair gets its own nested uniform scramble of the points and its own scrambled
// order of the sample indices ("padding" the pairs into a high-dimensional sampler without the
// correlation between pairs that plain Sobol dimensions show).
//
// Like StratifiedSampler, every value is a pure function of (seed, pixel, sample index,
// dimension), with dimensions numbered as in render/sampling/sample_dimensions.h.
#include "rtpro/render/sampler.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace rtpro {

class SobolSampler {
 public:
  explicit SobolSampler(std::uint64_t seed) : seed_(seed) {}

  // The pixel position of this sample (dimensions 0–1).
  PixelOffset pixel_offset(std::uint64_t pixel_key, int sample_index) const {
    return sample_2d(pixel_key, sample_index, 0);
  }
  // The 2D value of dimension pair (dimension, dimension + 1); dimension is even.
  Sample2D sample_2d(std::uint64_t pixel_key, int sample_index, int dimension) const;
  // sample_2d of each key into out[i], bit for bit (out.size() == keys.size()). The hashes of
  // many keys run side by side in vector registers where the CPU has AVX2.
  void sample_2d(std::span<const SampleKey> keys, int dimension, std::span<Sample2D> out) const;
  // A 1D value of `dimension`: an Owen-scrambled van der Corput sequence.
  float sample_1d(std::uint64_t pixel_key, int sample_index, int dimension) const;
  // sample_1d of each key into out[i], bit for bit, as the batch sample_2d.
  void sample_1d(std::span<const SampleKey> keys, int dimension, std::span<float> out) const;

  // A dimension (pair, for T = Sample2D) that a batch draws, and where its values go: key i's at
  // `first` advanced by i · `stride` bytes, so that one batch fills a field of an array of records.
  template <class T>
  struct Draw {
    int dimension;
    T* first;
    std::size_t stride;
  };
  // sample_2d of each key for every pair and sample_1d for every single, bit for bit, into their
  // Draw's elements: one pass over the keys, which hashes each key once for all the draws.
  void sample(std::span<const SampleKey> keys, std::span<const Draw<Sample2D>> pairs,
              std::span<const Draw<float>> singles) const;

 private:
  std::uint64_t seed_;
};

namespace sobol_detail {

// The Laine–Karras permutation of Burley 2020: flips each bit by a hash of the bits below it.
// Applied to a bit-reversed value it is a nested uniform (Owen) scramble.
constexpr std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

std::uint32_t reverse_bits(std::uint32_t x);
std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed);
// The second Sobol dimension of `index` (the first is reverse_bits(index)), and the same value
// bit-reversed, the form the scrambles take it in: superset_sums(index) ==
// reverse_bits(sobol_second_dimension(index)). Bit k of it is the xor of the bits of `index` at the
// positions whose bits are a superset of k's.
std::uint32_t sobol_second_dimension(std::uint32_t index);
std::uint32_t superset_sums(std::uint32_t index);

}  // namespace sobol_detail

}  // namespace rtpro
