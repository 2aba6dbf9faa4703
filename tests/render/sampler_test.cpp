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
        const PixelOffset o = sampler.sample(pixel, s);
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
    EXPECT_EQ(a.sample(99, s).x, b.sample(99, s).x);
    EXPECT_EQ(a.sample(99, s).y, b.sample(99, s).y);
    differing += a.sample(99, s).x != c.sample(99, s).x;
  }
  EXPECT_GT(differing, 12);
  // Neighbouring pixels are jittered independently.
  EXPECT_NE(a.sample(99, 0).x, a.sample(100, 0).x);
}

TEST(StratifiedSampler, RejectsSampleCountsThatAreNotSquares) {
  EXPECT_THROW(StratifiedSampler(10, 0), InputError);
  EXPECT_THROW(StratifiedSampler(0, 0), InputError);
  EXPECT_EQ(perfect_square_root(64), 8);
  EXPECT_EQ(perfect_square_root(63), 0);
}

}  // namespace
}  // namespace rtpro
