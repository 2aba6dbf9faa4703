// The Owen-scrambled Sobol sampler: every power-of-two prefix of a pixel's samples is a (0, m, 2)
// net in each dimension pair (one point in every elementary interval of area 1/N), 1D values are
// stratified the same way, and values are a pure function of (seed, pixel, sample, dimension).
#include "sobol_sampler.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <bit>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

namespace rtpro {
namespace sobol_sampler_test {

TEST(SobolSampler, FirstTwoDimensionsAreTheSobolMatrices) {
  using namespace sobol_detail;
  EXPECT_EQ(reverse_bits(1u), 0x80000000u);
  EXPECT_EQ(reverse_bits(0x12345678u), 0x1e6a2c48u);
  // Sobol's second dimension: 1/2, 3/4, 1/4, 5/8 ... for indices 1, 2, 3, 4.
  EXPECT_EQ(sobol_second_dimension(0), 0u);
  EXPECT_EQ(sobol_second_dimension(1), 0x80000000u);
  EXPECT_EQ(sobol_second_dimension(2), 0xc0000000u);
  EXPECT_EQ(sobol_second_dimension(3), 0x40000000u);
  EXPECT_EQ(sobol_second_dimension(4), 0xa0000000u);
  // Against the definition: the xor of the direction numbers (Pascal's triangle mod 2, one row per
  // index bit) of the bits set in the index. Both maps are linear over GF(2), so agreeing on the
  // 32 unit vectors they agree everywhere; the random indices check that linearity.
  std::uint32_t directions[32];
  directions[0] = 0x80000000u;
  for (int i = 1; i < 32; ++i) directions[i] = directions[i - 1] ^ (directions[i - 1] >> 1);
  const auto by_definition = [&](std::uint32_t index) {
    std::uint32_t value = 0;
    for (int i = 0; i < 32; ++i)
      if (index >> i & 1u) value ^= directions[i];
    return value;
  };
  std::mt19937 rng(3);
  for (int i = 0; i < 1000; ++i) {
    const std::uint32_t index = i < 32 ? 1u << i : static_cast<std::uint32_t>(rng());
    EXPECT_EQ(sobol_second_dimension(index), by_definition(index)) << index;
    EXPECT_EQ(superset_sums(index), reverse_bits(by_definition(index))) << index;
  }
  // The Owen scramble is a bijection on bytes' worth of values (checked on the low 12 bits).
  std::set<std::uint32_t> seen;
  for (std::uint32_t x = 0; x < 4096; ++x) seen.insert(nested_uniform_scramble(x, 0x9e3779b9u) & 0xfffu);
  EXPECT_EQ(seen.size(), 4096u);
}

// Every elementary interval [a/2^i, (a+1)/2^i) × [b/2^j, (b+1)/2^j) with i + j = m holds exactly
// one of the first 2^m points.
void expect_net(const std::vector<Sample2D>& points, int m) {
  const int n = 1 << m;
  for (int i = 0; i <= m; ++i) {
    const int j = m - i;
    std::vector<int> count(static_cast<std::size_t>(n), 0);
    for (int p = 0; p < n; ++p) {
      const int a = static_cast<int>(points[static_cast<std::size_t>(p)].x * static_cast<float>(1 << i));
      const int b = static_cast<int>(points[static_cast<std::size_t>(p)].y * static_cast<float>(1 << j));
      ++count[static_cast<std::size_t>(a * (1 << j) + b)];
    }
    for (int c = 0; c < n; ++c)
      ASSERT_EQ(count[static_cast<std::size_t>(c)], 1) << "2^" << i << " x 2^" << j << " cell " << c;
  }
}

TEST(SobolSampler, EveryPowerOfTwoPrefixIsStratifiedInEveryDimensionPair) {
  const SobolSampler sampler(7);
  for (const std::uint64_t pixel : {0ull, 1ull, 12345ull})
    for (const int dimension : {0, 2, 4, 12, 100}) {
      std::vector<Sample2D> points;
      for (int s = 0; s < 256; ++s) {
        points.push_back(sampler.sample_2d(pixel, s, dimension));
        ASSERT_GE(points.back().x, 0.0f);
        ASSERT_LT(points.back().x, 1.0f);
        ASSERT_GE(points.back().y, 0.0f);
        ASSERT_LT(points.back().y, 1.0f);
      }
      for (int m = 0; m <= 8; ++m) expect_net(points, m);
    }
}

TEST(SobolSampler, OneDimensionalValuesAreStratified) {
  const SobolSampler sampler(3);
  for (const int dimension : {5, 6, 21}) {
    std::vector<int> count(64, 0);
    for (int s = 0; s < 64; ++s) ++count[static_cast<std::size_t>(sampler.sample_1d(42, s, dimension) * 64.0f)];
    for (const int c : count) EXPECT_EQ(c, 1);
  }
}

TEST(SobolSampler, ValuesDependOnlyOnSeedPixelSampleAndDimension) {
  const SobolSampler a(11), b(11), other_seed(12);
  EXPECT_EQ(a.sample_2d(5, 3, 8).x, b.sample_2d(5, 3, 8).x);
  EXPECT_EQ(a.sample_1d(5, 3, 9), b.sample_1d(5, 3, 9));
  // Other pixels, dimensions and seeds are scrambled independently.
  int same = 0;
  for (int s = 0; s < 64; ++s) {
    same += a.sample_2d(5, s, 8).x == a.sample_2d(6, s, 8).x;
    same += a.sample_2d(5, s, 8).x == a.sample_2d(5, s, 10).x;
    same += a.sample_2d(5, s, 8).x == other_seed.sample_2d(5, s, 8).x;
  }
  EXPECT_LT(same, 3);
}

// The batches the path integrator draws a generation's vertex samples with (2D and 1D): every
// value the single draw's, bit for bit, for keys of any pixel and sample index (high bits set
// too) and for runs longer than, equal to and shorter than the batch's internal run.
TEST(SobolSampler, DrawingManyKeysAtOnceIsDrawingEachKey) {
  const SobolSampler sampler(0x5eed);
  std::mt19937_64 rng(9);
  for (const std::size_t count :
       {std::size_t{1}, std::size_t{63}, std::size_t{64}, std::size_t{65}, std::size_t{1000}}) {
    std::vector<SampleKey> keys(count);
    for (SampleKey& key : keys) {
      key.pixel_key = rng() >> (rng() % 64);
      key.sample_index = static_cast<int>(rng() % 4 == 0 ? rng() >> 33 : rng() % 256);
    }
    for (const int dimension : {0, 2, 8, 36, 1000}) {
      std::vector<Sample2D> many(count);
      sampler.sample_2d(keys, dimension, many);
      std::vector<float> many_1d(count);
      sampler.sample_1d(keys, dimension + 1, many_1d);
      for (std::size_t i = 0; i < count; ++i) {
        const Sample2D one = sampler.sample_2d(keys[i].pixel_key, keys[i].sample_index, dimension);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(many[i].x), std::bit_cast<std::uint32_t>(one.x)) << i << " of " << count;
        ASSERT_EQ(std::bit_cast<std::uint32_t>(many[i].y), std::bit_cast<std::uint32_t>(one.y)) << i << " of " << count;
        const float one_1d = sampler.sample_1d(keys[i].pixel_key, keys[i].sample_index, dimension + 1);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(many_1d[i]), std::bit_cast<std::uint32_t>(one_1d))
            << i << " of " << count;
      }
    }
  }
}

// The one-pass batch of several dimensions into fields of records (the path integrator's vertex
// samples): every value the single draw's, bit for bit, and nothing outside its field written.
TEST(SobolSampler, DrawingManyDimensionsIntoRecordsIsDrawingEach) {
  struct Record {
    Sample2D a;
    float single;
    Sample2D b;
    float untouched;
  };
  const SobolSampler sampler(0x5eed);
  std::mt19937_64 rng(11);
  for (const std::size_t count :
       {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{64}, std::size_t{65}, std::size_t{1000}}) {
    std::vector<SampleKey> keys(count);
    for (SampleKey& key : keys) {
      key.pixel_key = rng() >> (rng() % 64);
      key.sample_index = static_cast<int>(rng() % 4 == 0 ? rng() >> 33 : rng() % 256);
    }
    // One record at least, so the draws point at one even for no keys (which must write nothing).
    std::vector<Record> records(std::max<std::size_t>(count, 1), Record{{-1.0f, -1.0f}, -1.0f, {-1.0f, -1.0f}, -1.0f});
    const SobolSampler::Draw<Sample2D> pairs[] = {{36, &records.data()->a, sizeof(Record)},
                                                  {12, &records.data()->b, sizeof(Record)}};
    const SobolSampler::Draw<float> singles[] = {{43, &records.data()->single, sizeof(Record)}};
    sampler.sample(keys, pairs, singles);
    const auto same = [](float a, float b) {
      return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
    };
    for (std::size_t i = 0; i < count; ++i) {
      const SampleKey& key = keys[i];
      const Sample2D a = sampler.sample_2d(key.pixel_key, key.sample_index, 36);
      const Sample2D b = sampler.sample_2d(key.pixel_key, key.sample_index, 12);
      ASSERT_TRUE(same(records[i].a.x, a.x) && same(records[i].a.y, a.y)) << i << " of " << count;
      ASSERT_TRUE(same(records[i].b.x, b.x) && same(records[i].b.y, b.y)) << i << " of " << count;
      ASSERT_TRUE(same(records[i].single, sampler.sample_1d(key.pixel_key, key.sample_index, 43))) << i;
      ASSERT_EQ(records[i].untouched, -1.0f);
    }
    if (count == 0) {
      EXPECT_EQ(records[0].a.x, -1.0f);
    }
  }
}

}  // namespace sobol_sampler_test
}  // namespace rtpro
