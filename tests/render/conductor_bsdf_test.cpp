// The microfacet conductor: its sampler matches its pdf (χ²) for both Fresnel models with and
// without multiple-scattering compensation; it is reciprocal and never creates energy; and with a
// perfect reflector (F0 = 1) the compensation brings the albedo back to 1, where single
// scattering alone loses up to 69% (α = 1, normal incidence).
#include "conductor_bsdf.h"

#include "dielectric.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

namespace rtpro {
namespace conductor_bsdf_test {

// Gold at roughly 650, 550 and 450 nm.
const Color kGoldEta{0.143f, 0.374f, 1.442f};
const Color kGoldK{3.983f, 2.385f, 1.603f};
const Color kCopperF0{0.955f, 0.638f, 0.538f};
constexpr float kAlphas[] = {0.05f, 0.25f, 0.5f, 1.0f};
// Fewer than the other kinds' χ² runs: sixteen parameter sets, and each sample evaluates f.
constexpr int kChi2Samples = 300'000;

// Five runs per parameter set, from near normal to grazing incidence and once from below. Both
// Fresnel models sample single scattering alike, so they get different directions.
std::vector<Vec3> incident_directions(bool second_set = false) {
  std::vector<Vec3> wos;
  const std::vector<float> cosines = second_set ? std::vector<float>{0.9f, 0.55f, 0.3f, 0.08f, -0.8f}
                                                : std::vector<float>{0.97f, 0.7f, 0.4f, 0.15f, -0.55f};
  for (float c : cosines) wos.push_back(test::direction(c, 0.9f * c + 0.4f));
  return wos;
}

std::vector<ConductorBsdf> every_parameter_set() {
  std::vector<ConductorBsdf> bsdfs;
  for (float alpha : kAlphas)
    for (bool compensation : {true, false}) {
      bsdfs.push_back(ConductorBsdf::from_f0(kCopperF0, alpha, compensation));
      bsdfs.push_back(ConductorBsdf::from_complex_ior(kGoldEta, kGoldK, alpha, compensation));
      bsdfs.push_back(ConductorBsdf::from_f0(Color(1.0f), alpha, compensation));
    }
  return bsdfs;
}

std::string describe(const ConductorBsdf& bsdf) {
  std::ostringstream out;
  out << "alpha " << bsdf.alpha() << (bsdf.energy_compensation() ? " compensated" : " single-scattering");
  return out.str();
}

class ConductorChi2 : public testing::TestWithParam<float> {};

TEST_P(ConductorChi2, SchlickSamplerMatchesPdf) {
  for (bool compensation : {true, false}) {
    const ConductorBsdf bsdf = ConductorBsdf::from_f0(kCopperF0, GetParam(), compensation);
    test::expect_sampler_matches_pdf("conductor F0 " + describe(bsdf), bsdf, incident_directions(), kChi2Samples);
  }
}

TEST_P(ConductorChi2, ComplexIorSamplerMatchesPdf) {
  for (bool compensation : {true, false}) {
    const ConductorBsdf bsdf = ConductorBsdf::from_complex_ior(kGoldEta, kGoldK, GetParam(), compensation);
    test::expect_sampler_matches_pdf("conductor gold " + describe(bsdf), bsdf, incident_directions(true), kChi2Samples);
  }
}

INSTANTIATE_TEST_SUITE_P(Alphas, ConductorChi2, testing::ValuesIn(kAlphas));

TEST(ConductorBsdf, SampleAgreesWithEvalAndPdf) {
  test::Uniforms uniforms(11);
  for (const ConductorBsdf& bsdf : every_parameter_set())
    for (int i = 0; i < 300; ++i) {
      const Vec3 wo = uniforms.next_direction();
      const auto s = uniforms.sample(bsdf, wo);
      if (!s) continue;
      ASSERT_TRUE(same_hemisphere(wo, s->wi));
      ASSERT_FALSE(s->delta || s->transmitted);
      const Color f = bsdf.eval(wo, s->wi);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(s->f[k], f[k], 1e-5f * f[k]) << describe(bsdf);
      EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi), 1e-5f * s->pdf) << describe(bsdf);
    }
}

TEST(ConductorBsdf, IsReciprocal) {
  test::Uniforms uniforms(12);
  for (const ConductorBsdf& bsdf : every_parameter_set())
    for (int i = 0; i < 200; ++i) {
      const Vec3 a = uniforms.next_direction(0.0f, 1.0f);
      const Vec3 b = uniforms.next_direction(0.0f, 1.0f);
      const Color ab = bsdf.eval(a, b), ba = bsdf.eval(b, a);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(ab[k], ba[k], 1e-5f * ab[k] + 1e-7f) << describe(bsdf);
    }
}

TEST(ConductorBsdf, AlbedoNeverExceedsOne) {
  for (const ConductorBsdf& bsdf : every_parameter_set())
    for (float c : {1.0f, 0.6f, 0.3f, 0.1f, 0.03f, -0.5f}) {
      const Color albedo = test::estimate_albedo(bsdf, test::direction(c, 0.5f));
      EXPECT_LE(max_component(albedo), 1.01f) << describe(bsdf) << ", cos " << c;
    }
}

TEST(ConductorBsdf, CompensationConservesAPerfectReflectorsEnergy) {
  for (float alpha : kAlphas)
    for (float c : {1.0f, 0.7f, 0.4f, 0.2f, 0.08f}) {
      const Vec3 wo = test::direction(c, 0.3f);
      const float compensated = test::estimate_albedo(ConductorBsdf::from_f0(Color(1.0f), alpha), wo, 65536).x;
      const float single = test::estimate_albedo(ConductorBsdf::from_f0(Color(1.0f), alpha, false), wo, 65536).x;
      std::ostringstream line;
      line << std::fixed << std::setprecision(4) << "[energy] F0=1 alpha=" << alpha << " cos=" << c
           << " compensated=" << compensated << " single-scattering=" << single << " (loses " << std::setprecision(1)
           << 100.0f * (1.0f - single) << "%)\n";
      std::cout << line.str();
      EXPECT_NEAR(compensated, 1.0f, 0.02f) << "alpha " << alpha << ", cos " << c;
      EXPECT_LE(single, compensated + 1e-3f);
      if (alpha == 1.0f) {
        EXPECT_LT(single, 0.97f) << "single scattering should visibly lose energy at alpha 1, cos " << c;
        RecordProperty("single_scattering_albedo_alpha1_cos" + std::to_string(static_cast<int>(100 * c)),
                       std::to_string(single));
      }
    }
}

TEST(ConductorBsdf, CompensationBrightensTintedMetalsWithoutCreatingEnergy) {
  const Vec3 wo = test::direction(0.5f, 0.0f);
  const Color compensated = test::estimate_albedo(ConductorBsdf::from_complex_ior(kGoldEta, kGoldK, 0.8f), wo);
  const Color single = test::estimate_albedo(ConductorBsdf::from_complex_ior(kGoldEta, kGoldK, 0.8f, false), wo);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(compensated[k], single[k] + 0.02f);
    EXPECT_LT(compensated[k], 1.0f);
  }
  // A tinted metal is more saturated after many bounces: red gains relatively more than blue.
  EXPECT_GT(compensated.x / single.x, compensated.z / single.z);
}

TEST(ConductorBsdf, SmoothIsADeltaMirrorWeightedByFresnel) {
  const ConductorBsdf bsdf = ConductorBsdf::from_complex_ior(kGoldEta, kGoldK, 1e-4f);
  EXPECT_TRUE(bsdf.is_delta());
  const Vec3 wo = test::direction(0.6f, 1.0f);
  const auto s = bsdf.sample(wo, 0.5f, {0.3f, 0.7f});
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(s->delta);
  EXPECT_FLOAT_EQ(s->pdf, 1.0f);
  EXPECT_NEAR(s->wi.x, -wo.x, 1e-7f);
  EXPECT_NEAR(s->wi.y, -wo.y, 1e-7f);
  EXPECT_NEAR(s->wi.z, wo.z, 1e-7f);
  const Color throughput = s->f * (std::fabs(s->wi.z) / s->pdf);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(throughput[k], bsdf.fresnel(0.6f)[k], 1e-6f);
  EXPECT_EQ(bsdf.eval(wo, s->wi), Color(0.0f));
  EXPECT_EQ(bsdf.pdf(wo, s->wi), 0.0f);
  EXPECT_FALSE(ConductorBsdf::from_f0(Color(1.0f), 0.01f).is_delta());
}

TEST(ConductorBsdf, ComplexFresnelMatchesClosedForms) {
  for (float eta : {0.2f, 1.5f}) {
    const float k = 3.0f;
    const float normal = ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k);
    EXPECT_NEAR(fresnel_complex(1.0f, eta, k), normal, 1e-5f);
    EXPECT_NEAR(fresnel_complex(0.0f, eta, k), 1.0f, 1e-5f);
  }
  for (float c : {1.0f, 0.7f, 0.2f})  // κ = 0 is a dielectric
    EXPECT_NEAR(fresnel_complex(c, 1.5f, 0.0f), fresnel_dielectric(c, 1.5f), 1e-5f);
}

TEST(ConductorBsdf, FresnelAverageIsTheCosineWeightedMean) {
  for (const ConductorBsdf& bsdf :
       {ConductorBsdf::from_f0(kCopperF0, 0.3f), ConductorBsdf::from_complex_ior(kGoldEta, kGoldK, 0.3f)}) {
    constexpr int kIntervals = 100000;
    double total[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < kIntervals; ++i) {
      const float mu = (static_cast<float>(i) + 0.5f) / kIntervals;
      for (int k = 0; k < 3; ++k) total[k] += bsdf.fresnel(mu)[k] * mu;
    }
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(bsdf.fresnel_average()[k], 2.0 * total[k] / kIntervals, 2e-4);
  }
}

}  // namespace conductor_bsdf_test
}  // namespace rtpro
