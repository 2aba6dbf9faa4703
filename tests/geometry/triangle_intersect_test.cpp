#include "rtpro/geometry/triangle_intersect.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace rtpro {
namespace triangle_intersect_test {

constexpr float kInf = std::numeric_limits<float>::infinity();
const Vec3 p0{0, 0, 0}, p1{1, 0, 0}, p2{0, 1, 0};

TEST(TriangleIntersect, BarycentricsFollowEmbreeConvention) {
  TriangleHit hit{};
  ASSERT_TRUE(intersect_triangle(p0, p1, p2, {0.25f, 0.5f, 2.0f}, {0, 0, -1}, 0.0f, kInf, hit));
  EXPECT_FLOAT_EQ(hit.t, 2.0f);
  // p = (1-u-v)·p0 + u·p1 + v·p2 = (u, v, 0)
  EXPECT_FLOAT_EQ(hit.u, 0.25f);
  EXPECT_FLOAT_EQ(hit.v, 0.5f);
}

TEST(TriangleIntersect, HitFromBehindCounts) {
  TriangleHit hit{};
  EXPECT_TRUE(intersect_triangle(p0, p1, p2, {0.2f, 0.2f, -3.0f}, {0, 0, 1}, 0.0f, kInf, hit));
  EXPECT_FLOAT_EQ(hit.t, 3.0f);
}

TEST(TriangleIntersect, MissesOutsideParallelAndBehind) {
  TriangleHit hit{};
  EXPECT_FALSE(intersect_triangle(p0, p1, p2, {0.8f, 0.8f, 1.0f}, {0, 0, -1}, 0.0f, kInf, hit));
  EXPECT_FALSE(intersect_triangle(p0, p1, p2, {0.2f, 0.2f, 1.0f}, {1, 0, 0}, 0.0f, kInf, hit));
  EXPECT_FALSE(intersect_triangle(p0, p1, p2, {0.2f, 0.2f, 1.0f}, {0, 0, 1}, 0.0f, kInf, hit));
}

TEST(TriangleIntersect, DegenerateTriangleNeverHits) {
  TriangleHit hit{};
  EXPECT_FALSE(intersect_triangle(p0, p1, {2, 0, 0}, {0.5f, 0.0f, 1.0f}, {0, 0, -1}, 0.0f, kInf, hit));
}

TEST(TriangleIntersect, RaysThroughASharedEdgeHitAtLeastOneSide) {
  // Quad split along its diagonal: no ray through the diagonal may slip between the halves.
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{1, 1, 0}, d{0, 1, 0};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> along(0.0f, 1.0f);
  for (int i = 0; i < 10000; ++i) {
    const float s = along(rng);
    const Vec3 target{s, s, 0.0f};
    const Vec3 org{along(rng) * 3 - 1, along(rng) * 3 - 1, 2.0f};
    const Vec3 dir = target - org;
    TriangleHit h1{}, h2{};
    const bool hit =
        intersect_triangle(a, b, c, org, dir, 0.0f, kInf, h1) || intersect_triangle(a, c, d, org, dir, 0.0f, kInf, h2);
    ASSERT_TRUE(hit) << "ray " << i << " slipped through the diagonal at s=" << s;
  }
}

}  // namespace triangle_intersect_test
}  // namespace rtpro
