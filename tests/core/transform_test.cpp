#include "rtpro/core/transform.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace transform_test {

void expect_near(const Vec3& a, const Vec3& b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Transform, RotationIsRightHanded) {
  expect_near(Affine::rotate({0, 0, 1}, 90.0f).apply_point({1, 0, 0}), {0, 1, 0});
  expect_near(Affine::rotate({0, 1, 0}, 90.0f).apply_point({0, 0, 1}), {1, 0, 0});
}

TEST(Transform, ComposeAppliesRightOperandFirst) {
  const Affine t = compose(Affine::translate({1, 2, 3}), Affine::scale({2, 2, 2}));
  expect_near(t.apply_point({1, 1, 1}), {3, 4, 5});
  expect_near(t.apply_vector({1, 1, 1}), {2, 2, 2});
}

TEST(Transform, InverseUndoesTheTransform) {
  const Affine t = compose(Affine::translate({1, -2, 3}),
                           compose(Affine::rotate({1, 2, 3}, 37.0f), Affine::scale({0.5f, 2.0f, 3.0f})));
  const auto inv = inverse(t);
  ASSERT_TRUE(inv);
  const Vec3 p{0.3f, -1.7f, 2.2f};
  expect_near(inv->apply_point(t.apply_point(p)), p);
  expect_near(t.apply_point(inv->apply_point(p)), p);
}

TEST(Transform, SingularOrNonFiniteMatricesHaveNoInverse) {
  EXPECT_FALSE(inverse(Affine::scale({1, 0, 1})));
  Affine nan = Affine::identity();
  nan.m[0][3] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(inverse(nan));
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
  const Affine t = compose(Affine::rotate({0, 0, 1}, 30.0f), Affine::scale({4.0f, 1.0f, 1.0f}));
  const Affine inv = *inverse(t);
  // The plane x + y = 0 has normal (1,1,0) and tangent (1,-1,0).
  const Vec3 tangent = t.apply_vector({1, -1, 0});
  const Vec3 normal = inv.apply_normal_of_inverse({1, 1, 0});
  EXPECT_NEAR(dot(normalize(tangent), normalize(normal)), 0.0f, 1e-6f);
  // Transforming the normal like a vector would be wrong.
  EXPECT_GT(std::fabs(dot(normalize(tangent), normalize(t.apply_vector({1, 1, 0})))), 0.1f);
}

TEST(Transform, BoxBoundsContainTransformedCorners) {
  const Affine t = Affine::rotate({0, 0, 1}, 45.0f);
  const BBox b = t.apply(BBox{{-1, -1, -1}, {1, 1, 1}});
  EXPECT_NEAR(b.upper.x, std::sqrt(2.0f), 1e-5f);
  EXPECT_NEAR(b.lower.y, -std::sqrt(2.0f), 1e-5f);
  EXPECT_NEAR(b.upper.z, 1.0f, 1e-6f);
}

}  // namespace transform_test
}  // namespace rtpro
