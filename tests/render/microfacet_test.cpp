// GGX: D is normalised, Λ matches its closed form at α = 1, the visible-normal sampler matches
// its pdf (χ²), and the single-scattering albedo table matches an independent Monte Carlo
// estimate and the closed form 1 − ln 2 at α = 1, normal incidence.
#include "microfacet.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace rtpro {
namespace microfacet_test {

constexpr double kPi = std::numbers::pi;

std::vector<Vec3> incident_directions(float sign) {
  std::vector<Vec3> wos;
  const float cosines[] = {0.98f, 0.75f, 0.45f, 0.2f, 0.06f};
  for (int i = 0; i < 5; ++i) wos.push_back(test::direction(sign * cosines[i], 1.3f * static_cast<float>(i) + 0.2f));
  return wos;
}

TEST(Microfacet, RoughnessToAlphaSquares) {
  EXPECT_FLOAT_EQ(roughness_to_alpha(0.5f), 0.25f);
  EXPECT_FLOAT_EQ(roughness_to_alpha(1.0f), 1.0f);
  EXPECT_TRUE(GgxDistribution{roughness_to_alpha(0.03f)}.effectively_smooth());
  EXPECT_FALSE(GgxDistribution{roughness_to_alpha(0.05f)}.effectively_smooth());
}

TEST(Microfacet, ProjectedNormalDensityIntegratesToOne) {
  for (float alpha : {0.01f, 0.05f, 0.25f, 0.5f, 1.0f}) {
    const GgxDistribution ggx{alpha};
    // Isotropic: 2π ∫ D(θ) cos θ sin θ dθ, composite Simpson fine enough for the α = 0.01 peak.
    constexpr int kIntervals = 200000;
    const double h = (kPi / 2) / kIntervals;
    double sum = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
      const double theta = i * h;
      const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      const Vec3 wm{static_cast<float>(std::sin(theta)), 0.0f, static_cast<float>(std::cos(theta))};
      sum += weight * ggx.d(wm) * std::cos(theta) * std::sin(theta);
    }
    EXPECT_NEAR(2.0 * kPi * sum * h / 3.0, 1.0, 2e-3) << "alpha " << alpha;
  }
}

TEST(Microfacet, LambdaMatchesClosedFormAtAlphaOne) {
  // At α = 1, Λ(w) = (1/cos θ − 1)/2 and D = 1/π everywhere.
  const GgxDistribution ggx{1.0f};
  for (float c : {1.0f, 0.8f, 0.3f, 0.05f}) {
    const Vec3 w = test::direction(c, 0.7f);
    EXPECT_NEAR(ggx.lambda(w), (1.0f / c - 1.0f) / 2.0f, 1e-4f * (1.0f / c));
    EXPECT_NEAR(ggx.d(w), 1.0f / std::numbers::pi_v<float>, 1e-6f);
  }
}

TEST(Microfacet, HeightCorrelatedMaskingLiesBetweenTheSeparableBounds) {
  const GgxDistribution ggx{0.6f};
  for (float co : {0.9f, 0.4f, 0.1f})
    for (float ci : {0.95f, 0.5f, 0.15f}) {
      const Vec3 wo = test::direction(co, 0.3f), wi = test::direction(ci, 2.0f);
      EXPECT_LE(ggx.g(wo, wi), std::min(ggx.g1(wo), ggx.g1(wi)));
      EXPECT_GE(ggx.g(wo, wi), ggx.g1(wo) * ggx.g1(wi));
    }
}

TEST(Microfacet, VisibleNormalSamplingMatchesItsPdf) {
  for (float alpha : {0.05f, 0.3f, 1.0f})
    for (float sign : {1.0f, -1.0f}) {
      const GgxDistribution ggx{alpha};
      const double level = test::sidak_level(test::kChi2Significance, 5);
      for (const Vec3& w : incident_directions(sign)) {
        const test::Chi2Outcome outcome =
            test::chi2_test([&](float, Sample2D u) -> std::optional<Vec3> { return ggx.sample_visible_normal(w, u); },
                            [&](const Vec3& wm) { return ggx.visible_normal_pdf(w, wm); }, 200'000, 17);
        SCOPED_TRACE("alpha " + std::to_string(alpha) + ", w.z " + std::to_string(w.z));
        EXPECT_TRUE(outcome.failure.empty()) << outcome.failure;
        EXPECT_GE(outcome.p_value, level);
        EXPECT_NEAR(outcome.pdf_integral, 1.0, 2e-3);  // every visible normal faces up and towards w
      }
    }
}

// E(μ, α) the direct way: mean of G(wo,wi)/G1(wo) over visible normals drawn at random.
double monte_carlo_albedo(float mu, float alpha) {
  const GgxDistribution ggx{alpha};
  const Vec3 wo = test::direction(mu, 0.0f);
  test::Uniforms uniforms(99);
  constexpr int kSamples = 1 << 19;
  double sum = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const Vec3 wi = -reflect(wo, ggx.sample_visible_normal(wo, uniforms.next_2d()));
    if (wi.z > 0.0f) sum += ggx.g(wo, wi) / ggx.g1(wo);
  }
  return sum / kSamples;
}

TEST(Microfacet, AlbedoTableMatchesMonteCarlo) {
  for (float alpha : {0.05f, 0.2f, 0.5f, 0.9f})
    for (float mu : {0.05f, 0.3f, 0.65f, 1.0f})
      EXPECT_NEAR(ggx_directional_albedo(mu, alpha), monte_carlo_albedo(mu, alpha), 2e-3)
          << "alpha " << alpha << ", mu " << mu;
}

TEST(Microfacet, AlbedoAtAlphaOneNormalIncidenceIsOneMinusLnTwo) {
  // D = 1/π and G = 2 cos θi / (1 + cos θi), so E = ∫₀¹ 2μ/(1 + μ) dμ = 1 − ln 2.
  EXPECT_NEAR(ggx_directional_albedo(1.0f, 1.0f), 1.0 - std::log(2.0), 5e-4);
}

TEST(Microfacet, AlbedoIsAtMostOneAndOneForAMirror) {
  for (float alpha : {0.0f, 0.1f, 0.5f, 1.0f, 2.0f})
    for (float mu : {0.0f, 0.01f, 0.5f, 1.0f}) {
      EXPECT_LE(ggx_directional_albedo(mu, alpha), 1.0f);
      EXPECT_GT(ggx_directional_albedo(mu, alpha), 0.2f);
    }
  EXPECT_FLOAT_EQ(ggx_directional_albedo(0.5f, 0.0f), 1.0f);
  EXPECT_FLOAT_EQ(ggx_average_albedo(0.0f), 1.0f);
}

TEST(Microfacet, AverageAlbedoIsTheCosineWeightedMeanOfTheLookup) {
  for (float alpha : {0.05f, 0.37f, 1.0f}) {
    constexpr int kIntervals = 20000;
    double sum = 0.0;
    for (int i = 0; i < kIntervals; ++i) {
      const double mu = (i + 0.5) / kIntervals;
      sum += ggx_directional_albedo(static_cast<float>(mu), alpha) * mu;
    }
    EXPECT_NEAR(ggx_average_albedo(alpha), 2.0 * sum / kIntervals, 1e-4) << "alpha " << alpha;
  }
  EXPECT_GT(ggx_average_albedo(0.05f), ggx_average_albedo(0.5f));
  EXPECT_GT(ggx_average_albedo(0.5f), ggx_average_albedo(1.0f));
}

}  // namespace microfacet_test
}  // namespace rtpro
