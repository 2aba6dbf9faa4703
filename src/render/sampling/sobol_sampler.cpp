#include "sobol_sampler.h"

#include "rtpro/core/avx2_clones.h"
#include "rtpro/core/random.h"

#include <algorithm>
#include <cstddef>

namespace rtpro {

namespace sobol_detail {

std::uint32_t reverse_bits(std::uint32_t x) {
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
  return x;
}

std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

// Sobol's second dimension has the rows of Pascal's triangle mod 2 as direction numbers: index bit
// i sets bit 31 − k of the value for every k with C(i, k) odd, i.e. (Lucas) every k whose bits are
// a subset of i's. Read reversed, bit k of the value is thus the xor of the index bits at the
// supersets of k, summed here one bit of the position at a time: five shift-and-xor steps, which
// vectorise where table lookups would need a load per byte and lane.
std::uint32_t superset_sums(std::uint32_t index) {
  std::uint32_t x = index;
  x ^= (x >> 1) & 0x55555555u;
  x ^= (x >> 2) & 0x33333333u;
  x ^= (x >> 4) & 0x0f0f0f0fu;
  x ^= (x >> 8) & 0x00ff00ffu;
  x ^= x >> 16;
  return x;
}

std::uint32_t sobol_second_dimension(std::uint32_t index) { return reverse_bits(superset_sums(index)); }

}  // namespace sobol_detail

namespace {

constexpr float to_unit(std::uint32_t bits) {
  return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f);  // the top 24 bits: exact, below 1
}

// Per pixel and dimension: the scramble of the sample order and of each coordinate, from one
// SplitMix finalisation of the seed, the pixel and the dimension, each multiplied by a constant of
// its own and xor-ed together. The pixel's and the dimension's parts are separate so that a batch
// works a key's part out once for all the dimensions it draws.
struct Scrambles {
  std::uint32_t order, x, y;
};

std::uint64_t pixel_hash(std::uint64_t seed, std::uint64_t pixel_key) {
  return seed ^ (pixel_key * 0x9e3779b97f4a7c15ULL);
}

std::uint64_t dimension_hash(int dimension) { return static_cast<std::uint64_t>(dimension) * 0xd1b54a32d192ed03ULL; }

Scrambles scrambles(std::uint64_t pixel_hash, std::uint64_t dimension_hash) {
  const std::uint64_t h = mix64(pixel_hash ^ dimension_hash);
  const std::uint64_t h2 = (h ^ (h >> 29)) * 0xbf58476d1ce4e5b9ULL;
  return {static_cast<std::uint32_t>(h), static_cast<std::uint32_t>(h >> 32), static_cast<std::uint32_t>(h2 >> 32)};
}

// With nus(v, s) = reverse(LK(reverse(v), s)) the nested uniform scramble, a sample is
//   index = nus(sample, order),  x = nus(reverse(index), sx),  y = nus(sobol2(index), sy),
// computed here with the reverses that cancel left out: index = reverse(LK(reverse(sample), order)),
// x = reverse(LK(index, sx)), and as reverse(sobol2(index)) is the superset sums of index,
// y = reverse(LK(superset_sums(index), sy)). A 1D value is the x of its dimension's scrambles.
std::uint32_t scrambled_index(std::uint32_t reversed_sample, std::uint32_t order) {
  using namespace sobol_detail;
  return reverse_bits(laine_karras_permutation(reversed_sample, order));
}

float scrambled_x(std::uint32_t index, std::uint32_t scramble) {
  using namespace sobol_detail;
  return to_unit(reverse_bits(laine_karras_permutation(index, scramble)));
}

float scrambled_y(std::uint32_t index, std::uint32_t scramble) {
  using namespace sobol_detail;
  return to_unit(reverse_bits(laine_karras_permutation(superset_sums(index), scramble)));
}

std::uint32_t reversed_sample(int sample_index) {
  return sobol_detail::reverse_bits(static_cast<std::uint32_t>(sample_index));
}

}  // namespace

Sample2D SobolSampler::sample_2d(std::uint64_t pixel_key, int sample_index, int dimension) const {
  const Scrambles s = scrambles(pixel_hash(seed_, pixel_key), dimension_hash(dimension));
  const std::uint32_t index = scrambled_index(reversed_sample(sample_index), s.order);
  return {scrambled_x(index, s.x), scrambled_y(index, s.y)};
}

float SobolSampler::sample_1d(std::uint64_t pixel_key, int sample_index, int dimension) const {
  const Scrambles s = scrambles(pixel_hash(seed_, pixel_key), dimension_hash(dimension));
  return scrambled_x(scrambled_index(reversed_sample(sample_index), s.order), s.x);
}

namespace {

// SobolSampler::sample over a run of keys, keys[first, first + count). Written as plain loops over
// arrays, each step for every key before the next step, so that the AVX2 clone vectorises the
// hashes, four keys at a time in 64 bits and eight in 32; integer operations give the same bits in
// any encoding, and to_unit's conversion is exact, so both clones compute sample_2d's and
// sample_1d's values. The keys' own hashes are worked out once for all the draws.
constexpr std::size_t kRun = 64;

template <class T>
T& element(const SobolSampler::Draw<T>& draw, std::size_t i) {
  return *reinterpret_cast<T*>(reinterpret_cast<std::byte*>(draw.first) + i * draw.stride);
}

RTPRO_AVX2_CLONES
void sample_run(std::uint64_t seed, std::span<const SampleKey> keys, std::size_t first, std::size_t count,
                std::span<const SobolSampler::Draw<Sample2D>> pairs,
                std::span<const SobolSampler::Draw<float>> singles) {
  std::uint64_t pixel[kRun];
  std::uint32_t reversed[kRun];
  for (std::size_t i = 0; i < count; ++i) {
    pixel[i] = pixel_hash(seed, keys[first + i].pixel_key);
    reversed[i] = reversed_sample(keys[first + i].sample_index);
  }
  std::uint32_t order[kRun], sx[kRun], sy[kRun];
  for (const SobolSampler::Draw<Sample2D>& pair : pairs) {
    const std::uint64_t dimension = dimension_hash(pair.dimension);
    for (std::size_t i = 0; i < count; ++i) {
      const Scrambles s = scrambles(pixel[i], dimension);
      order[i] = s.order;
      sx[i] = s.x;
      sy[i] = s.y;
    }
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint32_t index = scrambled_index(reversed[i], order[i]);
      element(pair, first + i) = {scrambled_x(index, sx[i]), scrambled_y(index, sy[i])};
    }
  }
  for (const SobolSampler::Draw<float>& single : singles) {
    const std::uint64_t dimension = dimension_hash(single.dimension);
    for (std::size_t i = 0; i < count; ++i) {
      const Scrambles s = scrambles(pixel[i], dimension);
      order[i] = s.order;
      sx[i] = s.x;
    }
    for (std::size_t i = 0; i < count; ++i)
      element(single, first + i) = scrambled_x(scrambled_index(reversed[i], order[i]), sx[i]);
  }
}

}  // namespace

void SobolSampler::sample(std::span<const SampleKey> keys, std::span<const Draw<Sample2D>> pairs,
                          std::span<const Draw<float>> singles) const {
  for (std::size_t first = 0; first < keys.size(); first += kRun)
    sample_run(seed_, keys, first, std::min(kRun, keys.size() - first), pairs, singles);
}

void SobolSampler::sample_2d(std::span<const SampleKey> keys, int dimension, std::span<Sample2D> out) const {
  const Draw<Sample2D> pair{dimension, out.data(), sizeof(Sample2D)};
  sample(keys, {&pair, 1}, {});
}

void SobolSampler::sample_1d(std::span<const SampleKey> keys, int dimension, std::span<float> out) const {
  const Draw<float> single{dimension, out.data(), sizeof(float)};
  sample(keys, {}, {&single, 1});
}

}  // namespace rtpro
