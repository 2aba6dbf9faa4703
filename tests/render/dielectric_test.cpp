// Fresnel and Snell against textbook values: normal incidence, Brewster angle, total internal
// reflection, and a ray through a parallel slab leaving parallel to how it came in.
#include "dielectric.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rtpro {
namespace dielectric_test {

TEST(Dielectric, NormalIncidenceMatchesClosedForm) {
  for (float eta : {1.33f, 1.5f, 2.4f}) {
    const float expected = ((eta - 1.0f) / (eta + 1.0f)) * ((eta - 1.0f) / (eta + 1.0f));
    EXPECT_NEAR(fresnel_dielectric(1.0f, eta), expected, 1e-6f);
    EXPECT_NEAR(fresnel_dielectric(1.0f, 1.0f / eta), expected, 1e-6f);  // leaving: same value
  }
}

TEST(Dielectric, BrewsterAngleReflectsOnlyPerpendicularHalf) {
  const float eta = 1.5f;
  const float theta_b = std::atan(eta);
  const float cos_i = std::cos(theta_b);
  const float cos_t = std::cos(std::asin(std::sin(theta_b) / eta));
  const float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  // At Brewster's angle the parallel component vanishes, so R is half the perpendicular one.
  EXPECT_NEAR(fresnel_dielectric(cos_i, eta), 0.5f * r_perp * r_perp, 1e-6f);
  EXPECT_GT(fresnel_dielectric(cos_i, eta), 0.0f);
}

TEST(Dielectric, TotalInternalReflectionBeyondCriticalAngle) {
  const float eta = 1.0f / 1.5f;  // glass to air
  const float critical = std::asin(eta);
  EXPECT_EQ(fresnel_dielectric(std::cos(critical + 0.01f), eta), 1.0f);
  EXPECT_LT(fresnel_dielectric(std::cos(critical - 0.01f), eta), 1.0f);
  const Vec3 d = normalize(Vec3{std::sin(critical + 0.01f), -std::cos(critical + 0.01f), 0.0f});
  EXPECT_FALSE(refract(d, Vec3{0, 1, 0}, eta).has_value());
}

TEST(Dielectric, SlabLeavesRayParallelAndObeysSnell) {
  const Vec3 d = normalize(Vec3{0.6f, -0.8f, 0.0f});
  const Vec3 up{0, 1, 0};
  const auto inside = refract(d, up, 1.5f);
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(length(*inside), 1.0f, 1e-6f);
  EXPECT_NEAR(inside->x, d.x / 1.5f, 1e-6f);           // sin θt = sin θi / η
  const auto out = refract(*inside, up, 1.0f / 1.5f);  // bottom face, normal on the inside side
  ASSERT_TRUE(out.has_value());
  EXPECT_NEAR(out->x, d.x, 1e-6f);
  EXPECT_NEAR(out->y, d.y, 1e-6f);
}

}  // namespace dielectric_test
}  // namespace rtpro
