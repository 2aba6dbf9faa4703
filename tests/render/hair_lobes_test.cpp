// The hair model's factors: the Bessel function I0 and its logarithm across the hand-over to the
// asymptotic form; M_p normalised over θi for every variance, on both sides of its low-variance
// form; the trimmed logistic normalised and its sampler its inverse distribution; A_p summing to
// 1 without absorption.
#include "hair_lobes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rtpro {
namespace hair_lobes_test {

constexpr double kPi = std::numbers::pi;

TEST(HairLobes, BesselI0MatchesTablesAndItsLogarithmIsContinuous) {
  EXPECT_NEAR(bessel_i0(0.0f), 1.0f, 1e-7f);
  EXPECT_NEAR(bessel_i0(1.0f), 1.2660658777f, 1e-6f);
  EXPECT_NEAR(bessel_i0(10.0f) / 2815.716628f, 1.0f, 1e-5f);
  EXPECT_NEAR(bessel_i0(12.0f) / 18948.92534f, 1.0f, 1e-5f);
  // Series below 12, asymptotic above: the two agree where they meet, and far out.
  EXPECT_NEAR(log_bessel_i0(12.0f), log_bessel_i0(12.0001f), 2e-4f);
  EXPECT_NEAR(log_bessel_i0(12.0f), std::log(18948.92534f), 1e-5f);
  EXPECT_NEAR(log_bessel_i0(50.0f), std::log(2.93255378e20f), 1e-4f);
}

// ∫ M_p(θi, θo) cos θi dθi over [−π/2, π/2] by the midpoint rule, fine enough for v down to 1e-6.
double longitudinal_integral(float theta_o, float v, int steps = 40000) {
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double theta_i = -kPi / 2 + kPi * (i + 0.5) / steps;
    const float cos_i = static_cast<float>(std::cos(theta_i)), sin_i = static_cast<float>(std::sin(theta_i));
    sum += longitudinal_scattering(cos_i, std::cos(theta_o), sin_i, std::sin(theta_o), v) * cos_i;
  }
  return sum * kPi / steps;
}

TEST(HairLobes, LongitudinalScatteringIsNormalisedForEveryVariance) {
  for (float v : {1e-6f, 1e-4f, 0.0016f, 0.05f, 0.0999f, 0.1001f, 0.3f, 1.0f, 4.0f})
    for (float theta_o : {0.0f, 0.4f, -1.1f, 1.5f}) {
      SCOPED_TRACE("v " + std::to_string(v) + ", theta_o " + std::to_string(theta_o));
      EXPECT_NEAR(longitudinal_integral(theta_o, v), 1.0, 2e-3);
    }
  // The two forms meet at v = 0.1 (at the peak, θi = −θo).
  const float c = std::cos(0.3f), s = std::sin(0.3f);
  EXPECT_NEAR(longitudinal_scattering(c, c, -s, s, 0.0999999f) / longitudinal_scattering(c, c, -s, s, 0.1000001f), 1.0f,
              1e-3f);
}

TEST(HairLobes, LongitudinalSamplingInvertsTheConeDistribution) {
  // cos θ about the cone's axis has density e^((cos θ − 1)/v) / (v (1 − e^(−2/v))): its median.
  for (float v : {0.001f, 0.1f, 1.0f}) {
    const float median = 1.0f + v * std::log(0.5f + 0.5f * std::exp(-2.0f / v));
    EXPECT_NEAR(sample_longitudinal_cosine(0.5f, v), median, 1e-6f);
    EXPECT_NEAR(sample_longitudinal_cosine(1.0f - 0x1p-24f, v), 1.0f, 1e-5f);
    EXPECT_EQ(sample_longitudinal_cosine(0.0f, v), -1.0f);
  }
}

TEST(HairLobes, TrimmedLogisticIsNormalisedAndSampledByItsInverse) {
  for (float s : {0.02f, 0.2f, 1.0f, 3.0f}) {
    double sum = 0.0;
    constexpr int kSteps = 20000;
    for (int i = 0; i < kSteps; ++i)
      sum += trimmed_logistic(static_cast<float>(-kPi + 2 * kPi * (i + 0.5) / kSteps), s);
    EXPECT_NEAR(sum * 2 * kPi / kSteps, 1.0, 1e-4) << s;
    // The sampler's quartile q has a quarter of the density below it.
    const float q = sample_trimmed_logistic(0.25f, s);
    double below = 0.0;
    for (int i = 0; i < kSteps; ++i) {
      const double x = -kPi + (q + kPi) * (i + 0.5) / kSteps;
      below += trimmed_logistic(static_cast<float>(x), s);
    }
    EXPECT_NEAR(below * (q + kPi) / kSteps, 0.25, 1e-3) << s;
    EXPECT_NEAR(sample_trimmed_logistic(0.5f, s), 0.0f, 1e-5f);
  }
}

TEST(HairLobes, AzimuthalScatteringWrapsAroundTheFibre) {
  // The TRT exit azimuth lies beyond 2π: N_p is periodic in Δφ all the same.
  const float gamma_o = 0.4f, gamma_t = 0.25f;
  const float centre = exit_azimuth(2, gamma_o, gamma_t);
  const float wrapped = std::remainder(centre, 2.0f * static_cast<float>(kPi));
  EXPECT_NEAR(azimuthal_scattering(wrapped, 2, 0.3f, gamma_o, gamma_t), trimmed_logistic(0.0f, 0.3f), 1e-4f);
  EXPECT_NEAR(azimuthal_scattering(wrapped + 0.1f, 2, 0.3f, gamma_o, gamma_t),
              azimuthal_scattering(wrapped + 0.1f - 2.0f * static_cast<float>(kPi), 2, 0.3f, gamma_o, gamma_t), 1e-5f);
}

TEST(HairLobes, AttenuationSumsToOneWithoutAbsorptionAndLessWithIt) {
  for (float h : {0.0f, 0.5f, -0.95f})
    for (float cos_o : {1.0f, 0.6f, 0.1f}) {
      const auto clear = hair_attenuation(cos_o, 1.55f, h, Color(1.0f));
      Color sum(0.0f);
      for (const Color& a : clear) sum += a;
      EXPECT_NEAR(sum.x, 1.0f, 1e-5f);
      const auto dark = hair_attenuation(cos_o, 1.55f, h, Color(0.5f, 0.2f, 0.0f));
      EXPECT_EQ(dark[0], clear[0]);  // reflection at the surface absorbs nothing
      EXPECT_LT(dark[1].x, clear[1].x);
      EXPECT_EQ(dark[2].z, 0.0f);
    }
}

}  // namespace hair_lobes_test
}  // namespace rtpro
