#include "rtpro/core/ray.h"

#include <gtest/gtest.h>

#include <limits>

namespace rtpro {
namespace ray_test {

TEST(Ray, OrdinaryRaysAreTraceable) {
  EXPECT_TRUE(is_traceable(Ray{{0, 0, 0}, 0.0f, {0, 0, 1}}));
  EXPECT_TRUE(is_traceable(Ray{{1e6f, -1e6f, 0}, 0.5f, {0.1f, 0, 0}, 100.0f}));
}

TEST(Ray, NonFiniteHugeOrDegenerateRaysAreNot) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(is_traceable(Ray{{nan, 0, 0}, 0.0f, {0, 0, 1}}));
  EXPECT_FALSE(is_traceable(Ray{{0, 0, 0}, 0.0f, {0, inf, 1}}));
  EXPECT_FALSE(is_traceable(Ray{{1e30f, 0, 0}, 0.0f, {0, 0, 1}}));
  EXPECT_FALSE(is_traceable(Ray{{0, 0, 0}, 0.0f, {0, 0, 0}}));
  EXPECT_FALSE(is_traceable(Ray{{0, 0, 0}, -1.0f, {0, 0, 1}}));
  EXPECT_FALSE(is_traceable(Ray{{0, 0, 0}, 2.0f, {0, 0, 1}, 1.0f}));
  EXPECT_FALSE(is_traceable(Ray{{0, 0, 0}, 0.0f, {0, 0, 1}, nan}));
}

}  // namespace ray_test
}  // namespace rtpro
