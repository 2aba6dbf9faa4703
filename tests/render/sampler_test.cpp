#include "rtpro/render/sampler.h"

#include "rtpro/core/error.h"
#include "rtpro/core/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <set>
#include <span>
#include <vector>

namespace rtpro {
namespace sampler_test {

TEST(StratifiedSampler, OneSamplePerStratum) {
  for (int n : {1, 2, 3, 8}) {
    const StratifiedSampler sampler(n * n, 42);
    for (std::uint64_t pixel : {0ull, 17ull, 123456ull}) {
      std::set<std::pair<int, int>> strata;
      for (int s = 0; s < n * n; ++s) {
        const PixelOffset o = sampler.pixel_offset(pixel, s);
        ASSERT_GE(o.x, 0.0f);
        ASSERT_LT(o.x, 1.0f);
        ASSERT_GE(o.y, 0.0f);
        ASSERT_LT(o.y, 1.0f);
        strata.insert({static_cast<int>(o.x * n), static_cast<int>(o.y * n)});
      }
      EXPECT_EQ(strata.size(), static_cast<std::size_t>(n * n)) << "n=" << n;
    }
  }
}

TEST(StratifiedSampler, IsAPureFunctionOfSeedPixelAndIndex) {
  const StratifiedSampler a(16, 1), b(16, 1), c(16, 2);
  int differing = 0;
  for (int s = 0; s < 16; ++s) {
    EXPECT_EQ(a.pixel_offset(99, s).x, b.pixel_offset(99, s).x);
    EXPECT_EQ(a.pixel_offset(99, s).y, b.pixel_offset(99, s).y);
    differing += a.pixel_offset(99, s).x != c.pixel_offset(99, s).x;
  }
  EXPECT_GT(differing, 12);
  // Neighbouring pixels are jittered independently.
  EXPECT_NE(a.pixel_offset(99, 0).x, a.pixel_offset(100, 0).x);
}

// The offset's definition, written out with the hashes of core/random.h, so that the batch's
// arithmetic (which pixel_offset shares) is checked against something other than itself.
TEST(StratifiedSampler, PixelOffsetIsItsStratumJitteredByTheSamplesHash) {
  for (const int spp : {1, 6, 16, 7}) {
    const StratifiedSampler sampler(spp, 99);
    const StrataGrid grid = sampler.grid();
    for (const std::uint64_t pixel : {0ull, 777ull, ~0ull})
      for (int s = 0; s < spp; ++s) {
        const std::uint64_t bits = hash_combine(hash_combine(99, pixel), static_cast<std::uint64_t>(s));
        const float x =
            (static_cast<float>(s % grid.columns) + to_unit_float(bits)) * (1.0f / static_cast<float>(grid.columns));
        const float y =
            (static_cast<float>(s / grid.columns) + to_unit_float(bits << 24)) * (1.0f / static_cast<float>(grid.rows));
        const PixelOffset o = sampler.pixel_offset(pixel, s);
        EXPECT_EQ(std::bit_cast<std::uint32_t>(o.x), std::bit_cast<std::uint32_t>(x)) << spp << " " << s;
        EXPECT_EQ(std::bit_cast<std::uint32_t>(o.y), std::bit_cast<std::uint32_t>(y)) << spp << " " << s;
      }
  }
}

TEST(StratifiedSampler, OffsetsOfABatchOfPixelsArePixelOffsetBitForBit) {
  // Square, oblong (8x6), prime (7x1) and single-sample grids; keys near the ends of the range, in
  // batches longer and shorter than a run of the batch's hashing; one sample of each pixel, all
  // of them, and a pass's share starting past the first.
  for (const int spp : {1, 7, 16, 48, 64, 100}) {
    for (const std::uint64_t seed : {0ull, 12345ull}) {
      const StratifiedSampler sampler(spp, seed);
      std::vector<std::uint64_t> pixels;
      for (std::uint64_t i = 0; i < 70; ++i) pixels.push_back(i * 0x9e3779b97f4a7c15ull);
      for (const std::uint64_t pixel : {0ull, 1ull, 640ull * 480ull - 1ull, ~0ull}) pixels.push_back(pixel);
      struct Samples {
        int first, count;
      };
      for (const Samples samples :
           {Samples{0, 1}, Samples{spp - 1, 1}, Samples{0, spp}, Samples{spp / 2, spp - spp / 2}})
        for (const std::size_t count : {pixels.size(), std::size_t{1}, std::size_t{64}, std::size_t{65}}) {
          const std::span<const std::uint64_t> batch(pixels.data(), count);
          std::vector<PixelOffset> offsets(batch.size() * static_cast<std::size_t>(samples.count));
          sampler.pixel_offsets(batch, samples.first, samples.count, offsets);
          for (std::size_t i = 0; i < batch.size(); ++i)
            for (int k = 0; k < samples.count; ++k) {
              const PixelOffset one = sampler.pixel_offset(batch[i], samples.first + k);
              const PixelOffset& many =
                  offsets[i * static_cast<std::size_t>(samples.count) + static_cast<std::size_t>(k)];
              ASSERT_EQ(std::bit_cast<std::uint32_t>(many.x), std::bit_cast<std::uint32_t>(one.x))
                  << "spp " << spp << " pixel " << i << " sample " << samples.first + k;
              ASSERT_EQ(std::bit_cast<std::uint32_t>(many.y), std::bit_cast<std::uint32_t>(one.y))
                  << "spp " << spp << " pixel " << i << " sample " << samples.first + k;
            }
        }
    }
  }
}

TEST(StratifiedSampler, RejectsCountsBelowOne) {
  EXPECT_THROW(StratifiedSampler(0, 0), InputError);
  EXPECT_THROW(StratifiedSampler(-4, 0), InputError);
}

TEST(StrataGrid, IsTheMostNearlySquareFactorisation) {
  const std::pair<int, int> expected[] = {{1, 1}, {2, 1}, {3, 1}, {2, 2}, {5, 1}, {3, 2}, {7, 1}, {4, 2}, {3, 3}};
  for (int spp = 1; spp <= 9; ++spp) {
    EXPECT_EQ(strata_grid(spp).columns, expected[spp - 1].first) << spp;
    EXPECT_EQ(strata_grid(spp).rows, expected[spp - 1].second) << spp;
  }
  EXPECT_EQ(strata_grid(48).columns, 8);
  EXPECT_EQ(strata_grid(48).rows, 6);
  EXPECT_EQ(strata_grid(65536).columns, 256);
  for (int spp = 1; spp <= 2000; ++spp) {
    const StrataGrid grid = strata_grid(spp);
    ASSERT_EQ(grid.columns * grid.rows, spp);
    ASSERT_LE(grid.rows, grid.columns);
    for (int rows = grid.rows + 1; rows * rows <= spp; ++rows) ASSERT_NE(spp % rows, 0) << spp;
  }
}

// Any count: every sample in its own cell of the columns×rows grid, for pixel offsets and for
// later dimensions alike.
TEST(StratifiedSampler, NonSquareCountsFillEveryCellOfTheirGrid) {
  for (int spp : {2, 3, 5, 6, 10, 12, 48}) {
    const StratifiedSampler sampler(spp, 11);
    const StrataGrid grid = sampler.grid();
    EXPECT_EQ(sampler.samples_per_pixel(), spp);
    std::set<std::pair<int, int>> pixel_cells, lens_cells;
    for (int s = 0; s < spp; ++s) {
      const PixelOffset o = sampler.pixel_offset(5, s);
      const Sample2D u = sampler.sample_2d(5, s, 2);
      for (float v : {o.x, o.y, u.x, u.y}) {
        ASSERT_GE(v, 0.0f);
        ASSERT_LT(v, 1.0f);
      }
      pixel_cells.insert({static_cast<int>(o.x * grid.columns), static_cast<int>(o.y * grid.rows)});
      lens_cells.insert({static_cast<int>(u.x * grid.columns), static_cast<int>(u.y * grid.rows)});
    }
    EXPECT_EQ(pixel_cells.size(), static_cast<std::size_t>(spp)) << spp;
    EXPECT_EQ(lens_cells.size(), static_cast<std::size_t>(spp)) << spp;
  }
}

TEST(PermutationElement, IsABijectionForEveryCountAndKey) {
  for (std::uint32_t count : {1u, 2u, 3u, 7u, 16u, 17u, 64u, 100u, 255u, 256u, 1000u}) {
    for (std::uint32_t key : {0u, 1u, 0xdeadbeefu, 0x12345678u}) {
      std::set<std::uint32_t> seen;
      for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t p = permutation_element(i, count, key);
        ASSERT_LT(p, count);
        seen.insert(p);
      }
      EXPECT_EQ(seen.size(), count) << "count " << count << " key " << key;
    }
  }
}

TEST(StratifiedSampler, LaterDimensionsAreStratifiedInAnOrderOfTheirOwn) {
  const int n = 8;
  const StratifiedSampler sampler(n * n, 5);
  int same_stratum_as_pixel = 0;
  for (int dimension : {2, 4, 12}) {
    std::set<std::pair<int, int>> strata;
    for (int s = 0; s < n * n; ++s) {
      const Sample2D u = sampler.sample_2d(42, s, dimension);
      ASSERT_GE(u.x, 0.0f);
      ASSERT_LT(u.x, 1.0f);
      ASSERT_GE(u.y, 0.0f);
      ASSERT_LT(u.y, 1.0f);
      const std::pair<int, int> stratum{static_cast<int>(u.x * n), static_cast<int>(u.y * n)};
      strata.insert(stratum);
      const PixelOffset p = sampler.pixel_offset(42, s);
      same_stratum_as_pixel += stratum == std::pair<int, int>{static_cast<int>(p.x * n), static_cast<int>(p.y * n)};
    }
    EXPECT_EQ(strata.size(), static_cast<std::size_t>(n * n)) << "dimension " << dimension;
  }
  // A random permutation keeps about one sample per dimension in the pixel's own stratum.
  EXPECT_LT(same_stratum_as_pixel, 12);
  // Different dimensions and pixels draw different values; the same inputs the same value.
  EXPECT_NE(sampler.sample_2d(42, 3, 2).x, sampler.sample_2d(42, 3, 4).x);
  EXPECT_NE(sampler.sample_2d(42, 3, 2).x, sampler.sample_2d(43, 3, 2).x);
  EXPECT_EQ(sampler.sample_2d(42, 3, 2).x, StratifiedSampler(n * n, 5).sample_2d(42, 3, 2).x);
}

TEST(StratifiedSampler, OneDimensionalValuesFillEveryStratum) {
  const StratifiedSampler sampler(16, 9);
  std::set<int> strata;
  for (int s = 0; s < 16; ++s) {
    const float u = sampler.sample_1d(7, s, 5);
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    strata.insert(static_cast<int>(u * 16));
  }
  EXPECT_EQ(strata.size(), 16u);
}

}  // namespace sampler_test
}  // namespace rtpro
