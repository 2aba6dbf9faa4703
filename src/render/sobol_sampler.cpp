#include "rtpro/render/sobol_sampler.h"

#include "rtpro/core/random.h"

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

// The generator matrix applied a byte at a time: table[b][v] is the xor of the directions of the
// bits set in v, for byte b of the index. Four lookups instead of up to 32 conditional xors (the
// scrambled indices have high bits set).
using ByteTables = std::array<std::array<std::uint32_t, 256>, 4>;
constexpr ByteTables second_dimension_byte_tables() {
  const std::array<std::uint32_t, 32> directions = second_dimension_directions();
  ByteTables tables{};
  for (int byte = 0; byte < 4; ++byte)
    for (int value = 0; value < 256; ++value) {
      std::uint32_t x = 0;
      for (int bit = 0; bit < 8; ++bit)
        if (value >> bit & 1) x ^= directions[static_cast<std::size_t>(byte * 8 + bit)];
      tables[static_cast<std::size_t>(byte)][static_cast<std::size_t>(value)] = x;
    }
  return tables;
}
constexpr ByteTables kSecondDimension = second_dimension_byte_tables();

}  // namespace

std::uint32_t sobol_second_dimension(std::uint32_t index) {
  return kSecondDimension[0][index & 0xffu] ^ kSecondDimension[1][index >> 8 & 0xffu] ^
         kSecondDimension[2][index >> 16 & 0xffu] ^ kSecondDimension[3][index >> 24];
}

}  // namespace sobol_detail

namespace {

constexpr float to_unit(std::uint32_t bits) {
  return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f);  // the top 24 bits: exact, below 1
}

// Per pixel and dimension: the scramble of the sample order and of each coordinate.
struct Scrambles {
  std::uint32_t order, x, y;
};

Scrambles scrambles(std::uint64_t seed, std::uint64_t pixel_key, int dimension) {
  const std::uint64_t h = hash_combine(hash_combine(seed, pixel_key), static_cast<std::uint64_t>(dimension));
  const std::uint64_t h2 = mix64(h);
  return {static_cast<std::uint32_t>(h), static_cast<std::uint32_t>(h >> 32), static_cast<std::uint32_t>(h2)};
}

}  // namespace

Sample2D SobolSampler::sample_2d(std::uint64_t pixel_key, int sample_index, int dimension) const {
  using namespace sobol_detail;
  const Scrambles s = scrambles(seed_, pixel_key, dimension);
  const std::uint32_t index = nested_uniform_scramble(static_cast<std::uint32_t>(sample_index), s.order);
  return {to_unit(nested_uniform_scramble(reverse_bits(index), s.x)),
          to_unit(nested_uniform_scramble(sobol_second_dimension(index), s.y))};
}

float SobolSampler::sample_1d(std::uint64_t pixel_key, int sample_index, int dimension) const {
  using namespace sobol_detail;
  const Scrambles s = scrambles(seed_, pixel_key, dimension);
  const std::uint32_t index = nested_uniform_scramble(static_cast<std::uint32_t>(sample_index), s.order);
  return to_unit(nested_uniform_scramble(reverse_bits(index), s.x));
}

}  // namespace rtpro
