#include "rtpro/geometry/sphere_intersect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace rtpro {
namespace sphere_intersect_test {

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(SphereIntersect, HitsNearSideWithUnitDirection) {
  float t = -1.0f;
  ASSERT_TRUE(intersect_sphere({0, 0, 0}, 1.0f, {0, 0, -5}, {0, 0, 1}, 0.0f, kInf, t));
  EXPECT_FLOAT_EQ(t, 4.0f);
}

TEST(SphereIntersect, DistanceIsInUnitsOfANonUnitDirection) {
  float t = -1.0f;
  ASSERT_TRUE(intersect_sphere({0, 0, 0}, 1.0f, {0, 0, -5}, {0, 0, 4}, 0.0f, kInf, t));
  EXPECT_FLOAT_EQ(t, 1.0f);
}

TEST(SphereIntersect, OriginInsideHitsFarSide) {
  float t = -1.0f;
  ASSERT_TRUE(intersect_sphere({0, 0, 0}, 2.0f, {0, 0, 1}, {0, 0, 1}, 0.0f, kInf, t));
  EXPECT_FLOAT_EQ(t, 1.0f);
}

TEST(SphereIntersect, SphereBehindTheOriginIsMissed) {
  float t;
  EXPECT_FALSE(intersect_sphere({0, 0, -10}, 1.0f, {0, 0, 0}, {0, 0, 1}, 0.0f, kInf, t));
}

TEST(SphereIntersect, TangentRayTouchesOnePoint) {
  float t = -1.0f;
  ASSERT_TRUE(intersect_sphere({0, 0, 0}, 1.0f, {1, 0, -5}, {0, 0, 1}, 0.0f, kInf, t));
  EXPECT_FLOAT_EQ(t, 5.0f);
  EXPECT_FALSE(intersect_sphere({0, 0, 0}, 1.0f, {std::nextafter(1.0f, 2.0f), 0, -5}, {0, 0, 1}, 0.0f, kInf, t));
}

TEST(SphereIntersect, FarAwaySmallSphereIsHitAccurately) {
  // A naive float quadratic loses every digit here: b² and c are ~1e16 apart by ~1e-4.
  const Vec3 center{0.0f, 0.0f, 1.0e5f};
  const float radius = 0.01f;
  float t = -1.0f;
  ASSERT_TRUE(intersect_sphere(center, radius, {0, 0, 0}, {0, 0, 1}, 0.0f, kInf, t));
  EXPECT_NEAR(t, 1.0e5 - 0.01, 1.0e5 * 1e-7);
  // A ray passing 0.99 radii off the axis still hits; 1.01 radii misses.
  const Vec3 near_dir = normalize(Vec3{0.0099f, 0.0f, 1.0e5f});
  const Vec3 far_dir = normalize(Vec3{0.0101f, 0.0f, 1.0e5f});
  EXPECT_TRUE(intersect_sphere(center, radius, {0, 0, 0}, near_dir, 0.0f, kInf, t));
  EXPECT_FALSE(intersect_sphere(center, radius, {0, 0, 0}, far_dir, 0.0f, kInf, t));
}

TEST(SphereIntersect, IntervalIsOpenAtNearAndClosedAtFar) {
  float t;
  EXPECT_TRUE(intersect_sphere({0, 0, 0}, 1.0f, {0, 0, -5}, {0, 0, 1}, 0.0f, 4.0f, t));
  EXPECT_FALSE(intersect_sphere({0, 0, 0}, 1.0f, {0, 0, -5}, {0, 0, 1}, 0.0f, std::nextafter(4.0f, 0.0f), t));
  // With tnear at the near root, the far root is returned.
  ASSERT_TRUE(intersect_sphere({0, 0, 0}, 1.0f, {0, 0, -5}, {0, 0, 1}, 4.0f, kInf, t));
  EXPECT_FLOAT_EQ(t, 6.0f);
}

TEST(SphereIntersect, ZeroDirectionNeverHits) {
  float t;
  EXPECT_FALSE(intersect_sphere({0, 0, 0}, 1.0f, {0, 0, 0}, {0, 0, 0}, 0.0f, kInf, t));
}

}  // namespace sphere_intersect_test
}  // namespace rtpro
