// Lambert: f = R/π on the lit side only, reciprocal, cosine sampling matches its pdf (χ²), and the
// sampled albedo is the reflectance.
#include "diffuse_bsdf.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

namespace rtpro {
namespace diffuse_bsdf_test {

const DiffuseBsdf kBsdf{{0.8f, 0.5f, 0.2f}};

TEST(DiffuseBsdf, ReflectsOnlyIntoWosHemisphere) {
  const Vec3 wo = test::direction(0.6f, 0.4f);
  const Vec3 above = test::direction(0.3f, 2.0f), below = test::direction(-0.3f, 2.0f);
  EXPECT_FLOAT_EQ(kBsdf.eval(wo, above).x, 0.8f / std::numbers::pi_v<float>);
  EXPECT_EQ(kBsdf.eval(wo, below), Color(0.0f));
  EXPECT_EQ(kBsdf.pdf(wo, below), 0.0f);
  EXPECT_EQ(kBsdf.eval(-wo, below), kBsdf.eval(wo, above));  // lit from behind: the same
  EXPECT_FALSE(kBsdf.is_delta());
}

TEST(DiffuseBsdf, SamplerMatchesPdf) {
  std::vector<Vec3> wos;
  for (float c : {0.9f, 0.5f, 0.1f, -0.3f, -0.8f}) wos.push_back(test::direction(c, 1.0f + c));
  test::expect_sampler_matches_pdf("diffuse", kBsdf, wos);
}

TEST(DiffuseBsdf, SampleAgreesWithEvalAndPdf) {
  test::Uniforms uniforms(5);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 wo = uniforms.next_direction();
    const auto s = uniforms.sample(kBsdf, wo);
    if (!s) continue;
    EXPECT_TRUE(same_hemisphere(wo, s->wi));
    EXPECT_FALSE(s->delta || s->transmitted);
    EXPECT_EQ(s->f, kBsdf.eval(wo, s->wi));
    EXPECT_FLOAT_EQ(s->pdf, kBsdf.pdf(wo, s->wi));
  }
}

TEST(DiffuseBsdf, IsReciprocal) {
  test::Uniforms uniforms(6);
  for (int i = 0; i < 100; ++i) {
    const Vec3 a = uniforms.next_direction(0.0f, 1.0f);
    const Vec3 b = uniforms.next_direction(0.0f, 1.0f);
    EXPECT_EQ(kBsdf.eval(a, b), kBsdf.eval(b, a));
  }
}

TEST(DiffuseBsdf, AlbedoIsTheReflectance) {
  for (float c : {1.0f, 0.5f, 0.05f, -0.7f}) {
    const Color albedo = test::estimate_albedo(kBsdf, test::direction(c, 0.3f));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(albedo[k], kBsdf.reflectance[k], 1e-3f);
  }
}

}  // namespace diffuse_bsdf_test
}  // namespace rtpro
