// The Charlie sheen: D is normalised, the lobe is symmetric, the albedo table agrees with a direct
// integration, and the bounded lobe a material uses is the lobe itself where that conserves energy
// and never reflects more than it receives where it does not (smooth sheens at grazing angles).
#include "sheen.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rtpro {
namespace sheen_test {

template <class Lobe>
double integrate_albedo(const Lobe& lobe, float mu) {
  return test::hemisphere_albedo(mu, 400, [&](const Vec3& wo, const Vec3& wi) { return lobe.eval(wo, wi); });
}

TEST(Sheen, DistributionIsNormalised) {
  for (float roughness : {0.0f, 0.1f, 0.3f, 0.6f, 1.0f}) {
    const CharlieSheen sheen{sheen_roughness_to_alpha(roughness)};
    constexpr int kSteps = 100000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
      const float c = (static_cast<float>(i) + 0.5f) / kSteps;
      sum += sheen.d(Vec3{std::sqrt(1.0f - c * c), 0.0f, c}) * c;
    }
    EXPECT_NEAR(sum * 2.0 * std::numbers::pi / kSteps, 1.0, 1e-4) << "roughness " << roughness;
  }
}

TEST(Sheen, IsSymmetricAndOneSidedPerPair) {
  test::Uniforms uniforms(41);
  const SheenLobe lobe(0.15f);
  for (int i = 0; i < 500; ++i) {
    const Vec3 a = uniforms.next_direction(), b = uniforms.next_direction();
    const float ab = lobe.eval(a, b), ba = lobe.eval(b, a);
    EXPECT_NEAR(ab, ba, 1e-5f * ab + 1e-30f);  // an absolute floor: values near 1e-37 are rounding dust
    if (a.z * b.z < 0.0f) {
      EXPECT_EQ(ab, 0.0f);
    }
    EXPECT_EQ(lobe.eval(-a, -b), ab);  // a sheen has no inside
  }
}

TEST(Sheen, AlbedoTableMatchesTheIntegral) {
  for (float roughness : {0.12f, 0.35f, 0.62f, 0.9f})
    for (float mu : {0.07f, 0.3f, 0.66f, 1.0f}) {
      const CharlieSheen sheen{sheen_roughness_to_alpha(roughness)};
      EXPECT_NEAR(sheen_directional_albedo(mu, roughness), integrate_albedo(sheen, mu), 4e-3)
          << "roughness " << roughness << ", mu " << mu;
      const SheenLobe lobe(roughness);
      EXPECT_NEAR(lobe.albedo(mu), integrate_albedo(lobe, mu), 4e-3) << "roughness " << roughness << ", mu " << mu;
    }
}

TEST(Sheen, BoundedLobeNeverReflectsMoreThanItReceives) {
  // The fit of Λ lets smooth sheens reflect more than they receive at grazing angles...
  EXPECT_GT(sheen_directional_albedo(0.01f, 0.1f), 1.5f);
  for (float roughness : {0.0f, 0.1f, 0.2f, 0.3f})
    for (float mu : {0.003f, 0.01f, 0.03f, 0.1f}) {
      // ... the bounded lobe does not.
      const SheenLobe lobe(roughness);
      EXPECT_LE(integrate_albedo(lobe, mu), 1.0) << "roughness " << roughness << ", mu " << mu;
    }
  // Where the lobe conserves energy by itself, the bound leaves it alone.
  const SheenLobe rough(0.6f);
  const CharlieSheen charlie{sheen_roughness_to_alpha(0.6f)};
  test::Uniforms uniforms(43);
  for (int i = 0; i < 200; ++i) {
    const Vec3 a = uniforms.next_direction(0.0f, 1.0f), b = uniforms.next_direction(0.0f, 1.0f);
    EXPECT_EQ(rough.eval(a, b), charlie.eval(a, b));
  }
}

}  // namespace sheen_test
}  // namespace rtpro
