#include "rtpro/render/sampler.h"

#include "rtpro/core/error.h"

#include <gtest/gtest.h>

#include <set>

namespace rtpro {
namespace {

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

TEST(StratifiedSampler, RejectsSampleCountsThatAreNotSquares) {
  EXPECT_THROW(StratifiedSampler(10, 0), InputError);
  EXPECT_THROW(StratifiedSampler(0, 0), InputError);
  EXPECT_EQ(perfect_square_root(64), 8);
  EXPECT_EQ(perfect_square_root(63), 0);
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

}  // namespace
}  // namespace rtpro
