// The dielectric interface: smooth, it reflects with probability F and refracts otherwise, with
// total internal reflection beyond the critical angle and the (n_o/n_i)² radiance scale on
// transmission; rough, its sampler matches its pdf (χ²) from both sides, it obeys the generalised
// reciprocity of a radiance BTDF (up to its energy compensation), never creates energy, and with
// its compensation keeps all of it from either side at every roughness (the white furnace).
#include "dielectric_bsdf.h"

#include "dielectric.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace rtpro {
namespace dielectric_bsdf_test {

constexpr float kGlass = 1.5f;

std::vector<Vec3> incident_directions(float sign) {
  std::vector<Vec3> wos;
  for (float c : {0.95f, 0.75f, 0.5f, 0.3f, 0.12f}) wos.push_back(test::direction(sign * c, 2.1f * c + 0.3f));
  return wos;
}

// The index ratio a sample crossed into: n_wi / n_wo.
float crossed_eta(const Vec3& wo, float eta) { return wo.z > 0.0f ? eta : 1.0f / eta; }

TEST(DielectricBsdf, SmoothReflectsWithTheFresnelProbability) {
  const DielectricBsdf glass{kGlass, 0.0f};
  ASSERT_TRUE(glass.is_delta());
  for (float c : {0.9f, 0.5f, 0.1f, -0.95f, -0.8f}) {
    const Vec3 wo = test::direction(c, 0.7f);
    const float f = c > 0 ? fresnel_dielectric(c, kGlass) : fresnel_dielectric(-c, 1.0f / kGlass);
    const auto below = glass.sample(wo, f * 0.999f, {0.5f, 0.5f});
    const auto above = glass.sample(wo, f * 1.001f + 1e-6f, {0.5f, 0.5f});
    ASSERT_TRUE(below && above);
    EXPECT_FALSE(below->transmitted);
    EXPECT_TRUE(above->transmitted);
    EXPECT_TRUE(below->delta && above->delta);
    EXPECT_NEAR(below->pdf, f, 1e-6f);
    EXPECT_NEAR(above->pdf, 1.0f - f, 1e-6f);
    EXPECT_NEAR(below->wi.z, wo.z, 1e-6f);
    EXPECT_NEAR(below->f.x * std::fabs(below->wi.z) / below->pdf, 1.0f, 1e-5f);  // F / F
    EXPECT_EQ(glass.eval(wo, below->wi), Color(0.0f));
    EXPECT_EQ(glass.pdf(wo, above->wi), 0.0f);
    // Snell: n_o sin θo = n_i sin θi.
    const float sin_o = std::sqrt(1.0f - c * c), sin_i = std::sqrt(1.0f - above->wi.z * above->wi.z);
    EXPECT_NEAR(sin_i * crossed_eta(wo, kGlass), sin_o, 1e-5f);
  }
  // Over many uniform u_lobe, the reflected fraction is F.
  const Vec3 wo = test::direction(0.2f, 0.0f);
  test::Uniforms uniforms(21);
  int reflected = 0;
  constexpr int kSamples = 100000;
  for (int i = 0; i < kSamples; ++i) reflected += !uniforms.sample(glass, wo)->transmitted;
  EXPECT_NEAR(static_cast<double>(reflected) / kSamples, fresnel_dielectric(0.2f, kGlass), 4e-3);
}

TEST(DielectricBsdf, TotalInternalReflectionBeyondTheCriticalAngle) {
  const DielectricBsdf glass{kGlass, 0.0f};
  const float critical_cos = std::sqrt(1.0f - 1.0f / (kGlass * kGlass));
  for (float c : {critical_cos * 0.98f, 0.5f, 0.05f}) {
    const Vec3 wo = test::direction(-c, 1.0f);  // inside, beyond the critical angle
    for (float u_lobe : {0.0f, 0.5f, 0.9999f}) {
      const auto s = glass.sample(wo, u_lobe, {0.5f, 0.5f});
      ASSERT_TRUE(s.has_value());
      EXPECT_FALSE(s->transmitted);
      EXPECT_FLOAT_EQ(s->pdf, 1.0f);
      EXPECT_NEAR(s->f.x * std::fabs(s->wi.z), 1.0f, 1e-5f);
    }
  }
  // Just inside the critical angle light still escapes.
  const auto escaping = glass.sample(test::direction(-critical_cos * 1.02f, 1.0f), 0.9999f, {0.5f, 0.5f});
  ASSERT_TRUE(escaping.has_value());
  EXPECT_TRUE(escaping->transmitted);
}

TEST(DielectricBsdf, TransmissionCarriesTheRadianceFactor) {
  for (float alpha : {0.0f, 0.3f})
    for (float c : {0.8f, 0.4f, -0.9f, -0.8f}) {
      const DielectricBsdf glass{kGlass, alpha};
      const Vec3 wo = test::direction(c, 0.2f);
      if (alpha == 0.0f) {
        const auto s = glass.sample(wo, 0.99999f, {0.5f, 0.5f});
        ASSERT_TRUE(s && s->transmitted);
        const float eta = crossed_eta(wo, kGlass);
        EXPECT_NEAR(s->f.x * std::fabs(s->wi.z) / s->pdf, 1.0f / (eta * eta), 1e-5f) << "cos " << c;
      }
    }
  // A closed smooth glass object in a furnace: in and straight out again carries exactly 1.
  const DielectricBsdf glass{kGlass, 0.0f};
  const Vec3 wo = test::direction(0.6f, 0.0f);
  const auto in = glass.sample(wo, 0.99999f, {0.5f, 0.5f});
  ASSERT_TRUE(in.has_value());
  const auto out = glass.sample(in->wi, 0.99999f, {0.5f, 0.5f});  // the far side, parallel faces
  ASSERT_TRUE(out.has_value());
  const float in_weight = in->f.x * std::fabs(in->wi.z) / in->pdf;
  const float out_weight = out->f.x * std::fabs(out->wi.z) / out->pdf;
  EXPECT_NEAR(in_weight * out_weight, 1.0f, 1e-5f);
}

TEST(DielectricBsdf, IndexOneLetsLightStraightThrough) {
  for (float alpha : {0.0f, 0.5f}) {
    const DielectricBsdf nothing{1.0f, alpha};
    EXPECT_TRUE(nothing.is_delta());
    for (float u_lobe : {0.0f, 0.5f, 0.999f}) {
      const Vec3 wo = test::direction(0.3f, 1.0f);
      const auto s = nothing.sample(wo, u_lobe, {0.2f, 0.9f});
      ASSERT_TRUE(s.has_value());
      EXPECT_TRUE(s->transmitted);
      EXPECT_NEAR(s->wi.x, -wo.x, 1e-6f);
      EXPECT_NEAR(s->wi.z, -wo.z, 1e-6f);
      EXPECT_NEAR(s->f.x * std::fabs(s->wi.z) / s->pdf, 1.0f, 1e-5f);
    }
  }
}

class RoughDielectricChi2 : public testing::TestWithParam<float> {};

// The compensated pdf is normalised by the tabulated E, within 4e-3 of the exact integral.
constexpr double kCompensatedPdfTolerance = 4e-3;

TEST_P(RoughDielectricChi2, SamplerMatchesPdfFromOutside) {
  const DielectricBsdf glass{kGlass, GetParam()};
  test::expect_sampler_matches_pdf("dielectric outside alpha " + std::to_string(GetParam()), glass,
                                   incident_directions(1.0f), test::kChi2Samples, kCompensatedPdfTolerance);
}

TEST_P(RoughDielectricChi2, SamplerMatchesPdfFromInside) {
  const DielectricBsdf glass{kGlass, GetParam()};
  test::expect_sampler_matches_pdf("dielectric inside alpha " + std::to_string(GetParam()), glass,
                                   incident_directions(-1.0f), test::kChi2Samples, kCompensatedPdfTolerance);
}

INSTANTIATE_TEST_SUITE_P(Alphas, RoughDielectricChi2, testing::Values(0.1f, 0.3f, 0.7f));

TEST(DielectricBsdf, RoughSampleAgreesWithEvalAndPdf) {
  test::Uniforms uniforms(23);
  for (float eta : {kGlass, 1.0f / 1.33f})
    for (float alpha : {0.05f, 0.3f, 0.9f}) {
      const DielectricBsdf glass{eta, alpha};
      int transmitted = 0, reflected = 0;
      for (int i = 0; i < 2000; ++i) {
        const Vec3 wo = uniforms.next_direction();
        const auto s = uniforms.sample(glass, wo);
        if (!s) continue;
        ASSERT_FALSE(s->delta);
        ASSERT_EQ(s->transmitted, !same_hemisphere(wo, s->wi));
        (s->transmitted ? transmitted : reflected)++;
        const float f = glass.eval(wo, s->wi).x;
        EXPECT_NEAR(s->f.x, f, 1e-5f * f);
        EXPECT_NEAR(s->pdf, glass.pdf(wo, s->wi), 1e-5f * s->pdf);
      }
      EXPECT_GT(transmitted, 500);
      EXPECT_GT(reflected, 20);
    }
}

TEST(DielectricBsdf, RoughTransmissionObeysGeneralisedReciprocity) {
  // A radiance BTDF satisfies f(wo, wi) n_wi² = f(wi, wo) n_wo²; the compensated one
  // f(wo, wi) n_wi² / c(wo) = f(wi, wo) n_wo² / c(wi), c being its 1/E. Where a facet is met at
  // grazing incidence, T = 1 − F is small and float rounding leaves percents of it: hence the floor.
  test::Uniforms uniforms(24);
  for (const bool compensated : {false, true}) {
    const DielectricBsdf glass{kGlass, 0.4f, compensated};
    int checked = 0;  // most random pairs have no facet facing both, and f = 0 both ways
    for (int i = 0; i < 2000; ++i) {
      const Vec3 outside = uniforms.next_direction(0.0f, 1.0f);
      const Vec3 inside = uniforms.next_direction(-1.0f, 0.0f);
      const float into = glass.eval(outside, inside).x / glass.compensation(outside).value_or(1.0f);
      const float out_of = glass.eval(inside, outside).x / glass.compensation(inside).value_or(1.0f);
      EXPECT_NEAR(into * kGlass * kGlass, out_of, 2e-3f * out_of + 1e-5f);
      checked += into > 0.0f;
    }
    EXPECT_GT(checked, 200);
  }
}

// The energy albedo: the radiance factor taken back out of transmitted samples, since radiance
// legitimately grows by η² leaving glass without any energy being created.
Color energy_albedo(const DielectricBsdf& bsdf, const Vec3& wo) {
  struct EnergyView {
    const DielectricBsdf& bsdf;
    std::optional<BsdfSample> sample(const Vec3& w, float u_lobe, Sample2D u) const {
      auto s = bsdf.sample(w, u_lobe, u);
      if (s && s->transmitted) s->f = s->f * (crossed_eta(w, bsdf.eta) * crossed_eta(w, bsdf.eta));
      return s;
    }
  };
  return test::estimate_albedo(EnergyView{bsdf}, wo);
}

// The white furnace of the interface alone: with compensation, all the energy arriving from either
// side leaves it, reflected or refracted, at every roughness (without, 0.59 at roughness 1 from
// outside, grazing, and 0.52 from inside at normal incidence).
TEST(DielectricBsdf, CompensatedRoughGlassKeepsAllTheEnergyFromEitherSide) {
  for (float roughness : {0.0f, 0.1f, 0.2f, 0.3f, 0.5f, 0.7f, 1.0f})
    for (float eta : {kGlass, 1.33f})
      for (float c : {1.0f, 0.7f, 0.35f, 0.1f, -1.0f, -0.7f, -0.35f, -0.1f}) {
        const DielectricBsdf glass{eta, roughness_to_alpha(roughness)};
        const Vec3 wo = test::direction(c, 0.4f);
        EXPECT_NEAR(energy_albedo(glass, wo).x, 1.0f, 0.01f)
            << "roughness " << roughness << ", eta " << eta << ", cos " << c;
      }
}

TEST(DielectricBsdf, NeverCreatesEnergy) {
  for (float alpha : {0.0f, 0.05f, 0.1f, 0.3f, 0.7f, 1.0f})
    for (float c : {1.0f, 0.6f, 0.2f, 0.05f, -1.0f, -0.9f, -0.6f, -0.2f}) {
      const DielectricBsdf glass{kGlass, alpha};
      const Vec3 wo = test::direction(c, 0.4f);
      const float energy = energy_albedo(glass, wo).x;
      EXPECT_LE(energy, 1.01f) << "alpha " << alpha << ", cos " << c;
      if (alpha == 0.0f) {
        EXPECT_NEAR(energy, 1.0f, 1e-4f);  // smooth: R + T = 1 exactly
      }
      // Radiance entering glass is diluted by 1/η², so the radiance albedo from outside is lower.
      if (c > 0) {
        EXPECT_LE(test::estimate_albedo(glass, wo).x, 1.01f);
      }
    }
}

}  // namespace dielectric_bsdf_test
}  // namespace rtpro
