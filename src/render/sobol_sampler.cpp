#include "rtpro/render/sobol_sampler.h"

#include "rtpro/core/avx2_clones.h"
#include "rtpro/core/random.h"

#include <algorithm>

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
// supersets of k, summed here one bit of the position at a time in five shift-and-xor steps, which
// vectorise (the byte tables they replaced needed four loads a value).
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
// SplitMix finalisation of the three inputs.
struct Scrambles {
  std::uint32_t order, x, y;
};

Scrambles scrambles(std::uint64_t seed, std::uint64_t pixel_key, int dimension) {
  const std::uint64_t h = mix64(seed ^ (pixel_key * 0x9e3779b97f4a7c15ULL) ^
                                (static_cast<std::uint64_t>(dimension) * 0xd1b54a32d192ed03ULL));
  const std::uint64_t h2 = (h ^ (h >> 29)) * 0xbf58476d1ce4e5b9ULL;
  return {static_cast<std::uint32_t>(h), static_cast<std::uint32_t>(h >> 32), static_cast<std::uint32_t>(h2 >> 32)};
}

}  // namespace

// With nus(v, s) = reverse(LK(reverse(v), s)) the nested uniform scramble, a sample is
//   index = nus(sample, order),  x = nus(reverse(index), sx),  y = nus(sobol2(index), sy),
// computed here with the reverses that cancel left out: r = LK(reverse(sample), order) is
// reverse(index), x = reverse(LK(index, sx)), and as reverse(sobol2(index)) is the superset sums
// of index, y = reverse(LK(superset_sums(index), sy)).
Sample2D SobolSampler::sample_2d(std::uint64_t pixel_key, int sample_index, int dimension) const {
  using namespace sobol_detail;
  const Scrambles s = scrambles(seed_, pixel_key, dimension);
  const std::uint32_t r = laine_karras_permutation(reverse_bits(static_cast<std::uint32_t>(sample_index)), s.order);
  const std::uint32_t index = reverse_bits(r);
  return {to_unit(reverse_bits(laine_karras_permutation(index, s.x))),
          to_unit(reverse_bits(laine_karras_permutation(superset_sums(index), s.y)))};
}

namespace {

// SobolSampler::sample_2d over a run of keys. Written as plain loops over arrays, each step for
// every key before the next step, so that the AVX2 clone vectorises the 32-bit hashes eight keys
// at a time; integer operations give the same bits in any encoding, and to_unit's conversion is
// exact, so both clones compute sample_2d's values.
constexpr std::size_t kRun = 64;

RTPRO_AVX2_CLONES
void sample_2d_run(std::uint64_t seed, const SampleKey* keys, std::size_t count, int dimension, Sample2D* out) {
  using namespace sobol_detail;
  std::uint32_t order[kRun], sx[kRun], sy[kRun], index[kRun];
  for (std::size_t i = 0; i < count; ++i) {
    const Scrambles s = scrambles(seed, keys[i].pixel_key, dimension);
    order[i] = s.order;
    sx[i] = s.x;
    sy[i] = s.y;
  }
  for (std::size_t i = 0; i < count; ++i)
    index[i] = reverse_bits(
        laine_karras_permutation(reverse_bits(static_cast<std::uint32_t>(keys[i].sample_index)), order[i]));
  for (std::size_t i = 0; i < count; ++i) {
    out[i].x = to_unit(reverse_bits(laine_karras_permutation(index[i], sx[i])));
    out[i].y = to_unit(reverse_bits(laine_karras_permutation(superset_sums(index[i]), sy[i])));
  }
}

RTPRO_AVX2_CLONES
void sample_1d_run(std::uint64_t seed, const SampleKey* keys, std::size_t count, int dimension, float* out) {
  using namespace sobol_detail;
  std::uint32_t order[kRun], sx[kRun];
  for (std::size_t i = 0; i < count; ++i) {
    const Scrambles s = scrambles(seed, keys[i].pixel_key, dimension);
    order[i] = s.order;
    sx[i] = s.x;
  }
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t r =
        laine_karras_permutation(reverse_bits(static_cast<std::uint32_t>(keys[i].sample_index)), order[i]);
    out[i] = to_unit(reverse_bits(laine_karras_permutation(reverse_bits(r), sx[i])));
  }
}

}  // namespace

void SobolSampler::sample_1d(std::span<const SampleKey> keys, int dimension, std::span<float> out) const {
  for (std::size_t start = 0; start < keys.size(); start += kRun)
    sample_1d_run(seed_, keys.data() + start, std::min(kRun, keys.size() - start), dimension, out.data() + start);
}

void SobolSampler::sample_2d(std::span<const SampleKey> keys, int dimension, std::span<Sample2D> out) const {
  for (std::size_t start = 0; start < keys.size(); start += kRun)
    sample_2d_run(seed_, keys.data() + start, std::min(kRun, keys.size() - start), dimension, out.data() + start);
}

float SobolSampler::sample_1d(std::uint64_t pixel_key, int sample_index, int dimension) const {
  using namespace sobol_detail;
  const Scrambles s = scrambles(seed_, pixel_key, dimension);
  const std::uint32_t r = laine_karras_permutation(reverse_bits(static_cast<std::uint32_t>(sample_index)), s.order);
  return to_unit(reverse_bits(laine_karras_permutation(reverse_bits(r), s.x)));
}

}  // namespace rtpro
