#include "rtpro/render/sobol_sampler.h"

#include "rtpro/core/avx2_clones.h"
#include "rtpro/core/random.h"

#include <algorithm>

#include <array>

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

namespace {

// Direction numbers of the second Sobol dimension: the rows of Pascal's triangle mod 2 from the
// top bit down, each row the one before xor itself shifted by one.
constexpr std::array<std::uint32_t, 32> second_dimension_directions() {
  std::array<std::uint32_t, 32> v{};
  v[0] = 0x80000000u;
  for (int i = 1; i < 32; ++i) v[i] = v[i - 1] ^ (v[i - 1] >> 1);
  return v;
}

// A linear map over GF(2) applied a byte at a time: table[b][v] is the xor of the images of the
// bits set in v, for byte b of the input. Four lookups instead of up to 32 conditional xors (the
// scrambled indices have high bits set).
using ByteTables = std::array<std::array<std::uint32_t, 256>, 4>;
using BitImages = std::array<std::uint32_t, 32>;  // the image of each input bit
constexpr ByteTables byte_tables(const BitImages& image_of_bit) {
  ByteTables tables{};
  for (std::size_t byte = 0; byte < 4; ++byte)
    for (std::size_t value = 1; value < 256; ++value) {
      // The value without its lowest set bit is already in the table.
      const std::size_t lowest = static_cast<std::size_t>(__builtin_ctz(static_cast<unsigned>(value)));
      tables[byte][value] = tables[byte][value & (value - 1)] ^ image_of_bit[byte * 8 + lowest];
    }
  return tables;
}

constexpr std::uint32_t apply(const ByteTables& t, std::uint32_t x) {
  return t[0][x & 0xffu] ^ t[1][x >> 8 & 0xffu] ^ t[2][x >> 16 & 0xffu] ^ t[3][x >> 24];
}

constexpr std::uint32_t reversed(std::uint32_t x) {
  std::uint32_t r = 0;
  for (int i = 0; i < 32; ++i) r |= (x >> i & 1u) << (31 - i);
  return r;
}

// The second dimension read and written bit-reversed: reverse ∘ sobol ∘ reverse, the form the
// scrambles below take it in. Bit b of the input is bit 31 − b of the index.
constexpr BitImages reversed_directions() {
  const BitImages directions = second_dimension_directions();
  BitImages images{};
  for (std::size_t bit = 0; bit < 32; ++bit) images[bit] = reversed(directions[31 - bit]);
  return images;
}

constexpr ByteTables kSecondDimension = byte_tables(second_dimension_directions());
constexpr ByteTables kSecondDimensionReversed = byte_tables(reversed_directions());

}  // namespace

std::uint32_t sobol_second_dimension(std::uint32_t index) { return apply(kSecondDimension, index); }

std::uint32_t reversed_sobol_second_dimension(std::uint32_t reversed_index) {
  return apply(kSecondDimensionReversed, reversed_index);
}

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
// reverse(index), x = reverse(LK(index, sx)), y = reverse(LK(reverse(sobol2(reverse(r))), sy)).
Sample2D SobolSampler::sample_2d(std::uint64_t pixel_key, int sample_index, int dimension) const {
  using namespace sobol_detail;
  const Scrambles s = scrambles(seed_, pixel_key, dimension);
  const std::uint32_t r = laine_karras_permutation(reverse_bits(static_cast<std::uint32_t>(sample_index)), s.order);
  const std::uint32_t index = reverse_bits(r);
  return {to_unit(reverse_bits(laine_karras_permutation(index, s.x))),
          to_unit(reverse_bits(laine_karras_permutation(reversed_sobol_second_dimension(r), s.y)))};
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
  std::uint32_t order[kRun], sx[kRun], sy[kRun], r[kRun], second[kRun];
  for (std::size_t i = 0; i < count; ++i) {
    const Scrambles s = scrambles(seed, keys[i].pixel_key, dimension);
    order[i] = s.order;
    sx[i] = s.x;
    sy[i] = s.y;
  }
  for (std::size_t i = 0; i < count; ++i)
    r[i] = laine_karras_permutation(reverse_bits(static_cast<std::uint32_t>(keys[i].sample_index)), order[i]);
  for (std::size_t i = 0; i < count; ++i) second[i] = reversed_sobol_second_dimension(r[i]);
  for (std::size_t i = 0; i < count; ++i) {
    out[i].x = to_unit(reverse_bits(laine_karras_permutation(reverse_bits(r[i]), sx[i])));
    out[i].y = to_unit(reverse_bits(laine_karras_permutation(second[i], sy[i])));
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
