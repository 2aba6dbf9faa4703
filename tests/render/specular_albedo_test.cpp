// The GGX + Schlick albedo tables: their F0 = F90 = 1 sum is ggx_directional_albedo's E, they agree
// with a direct integration of the lobe over the hemisphere between the nodes, a mirror has the
// closed form, and the average is the cosine-weighted mean of what the lookup returns.
#include "specular_albedo.h"

#include "bsdf_test_support.h"
#include "microfacet.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rtpro {
namespace specular_albedo_test {

float schlick(float f0, float f90, float cos_theta) {
  const float m = 1.0f - cos_theta;
  return f0 + (f90 - f0) * m * m * m * m * m;
}

// ∫ F(wo·wm) D G / (4 μo μi) μi dωi.
double integrate(float mu, float alpha, float f0, float f90) {
  const GgxDistribution ggx{alpha};
  return test::hemisphere_albedo(mu, 600, [&](const Vec3& wo, const Vec3& wi) {
    const Vec3 wm = normalize(wo + wi);
    return ggx.d(wm) * ggx.g(wo, wi) / (4.0f * mu * wi.z) * schlick(f0, f90, dot(wo, wm));
  });
}

TEST(SpecularAlbedo, WithoutFresnelIsTheGgxAlbedo) {
  for (float alpha : {0.01f, 0.2f, 0.55f, 1.0f})
    for (float mu : {0.03f, 0.3f, 0.8f, 1.0f}) {
      const SchlickAlbedo e = ggx_schlick_albedo(mu, alpha);
      EXPECT_NEAR(e(1.0f, 1.0f), ggx_directional_albedo(mu, alpha), 1e-5f) << "alpha " << alpha << ", mu " << mu;
    }
}

TEST(SpecularAlbedo, MatchesTheIntegralBetweenNodes) {
  for (float alpha : {0.07f, 0.3f, 0.8f})
    for (float mu : {0.1f, 0.45f, 0.9f})
      for (auto [f0, f90] : {std::pair{0.04f, 1.0f}, std::pair{0.5f, 0.5f}, std::pair{0.0f, 1.0f}}) {
        const float table = ggx_schlick_albedo(mu, alpha)(f0, f90);
        EXPECT_NEAR(table, integrate(mu, alpha, f0, f90), 1.5e-3)
            << "alpha " << alpha << ", mu " << mu << ", F0 " << f0;
      }
}

TEST(SpecularAlbedo, AMirrorReflectsItsFresnel) {
  for (float mu : {0.05f, 0.5f, 1.0f}) {
    EXPECT_FLOAT_EQ(ggx_schlick_albedo(mu, 0.0f)(0.04f, 1.0f), schlick(0.04f, 1.0f, mu));
  }
  EXPECT_FLOAT_EQ(ggx_schlick_average_albedo(0.0f)(0.04f, 1.0f), 0.04f + 0.96f / 21.0f);
}

TEST(SpecularAlbedo, AverageIsTheCosineWeightedMeanOfTheLookup) {
  for (float alpha : {0.01f, 0.3f, 0.64f, 1.0f}) {
    constexpr int kSteps = 20000;
    double f0_part = 0.0, f90_part = 0.0;
    for (int i = 0; i < kSteps; ++i) {
      const float mu = (static_cast<float>(i) + 0.5f) / kSteps;
      const SchlickAlbedo e = ggx_schlick_albedo(mu, alpha);
      f0_part += e.f0_weight * mu;
      f90_part += e.f90_weight * mu;
    }
    const SchlickAlbedo average = ggx_schlick_average_albedo(alpha);
    EXPECT_NEAR(average.f0_weight, 2.0 * f0_part / kSteps, 1e-4) << "alpha " << alpha;
    EXPECT_NEAR(average.f90_weight, 2.0 * f90_part / kSteps, 1e-4) << "alpha " << alpha;
  }
}

}  // namespace specular_albedo_test
}  // namespace rtpro
