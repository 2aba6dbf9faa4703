// The Phong material under the path integrator (render/bsdf/phong_bsdf.h): its sampler matches its
// pdf (χ²) and its eval; it never reflects more than it receives, however the Whitted weights add
// up; its mirror lobe carries `reflectivity`; and its highlight's peak and width follow the whitted
// integrator's Phong lobe, narrowing as the shininess grows.
#include "phong_bsdf.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace rtpro {
namespace phong_bsdf_test {

std::vector<PhongBsdf> every_parameter_set() {
  std::vector<PhongBsdf> bsdfs;
  for (float shininess : {0.0f, 10.0f, 100.0f})
    for (float reflectivity : {0.0f, 0.4f}) {
      bsdfs.push_back(PhongBsdf::from_whitted(Color(0.6f, 0.3f, 0.1f), 0.8f, shininess, reflectivity));
      bsdfs.push_back(PhongBsdf::from_whitted(Color(0.0f), 1.0f, shininess, reflectivity));
    }
  return bsdfs;
}

TEST(PhongBsdf, SamplerMatchesPdf) {
  const std::vector<Vec3> wos{test::direction(0.9f, 0.3f), test::direction(0.35f, 2.0f), test::direction(-0.6f, 4.0f)};
  // A broad and a tight highlight over a diffuse colour (a mirror's delta samples no pdf describes).
  for (float shininess : {3.0f, 60.0f}) {
    const PhongBsdf bsdf = PhongBsdf::from_whitted(Color(0.5f, 0.4f, 0.3f), 4.0f, shininess, 0.0f);
    test::expect_sampler_matches_pdf("phong shininess " + std::to_string(shininess), bsdf, wos, 50'000);
  }
}

TEST(PhongBsdf, SampleAgreesWithEvalAndPdf) {
  test::Uniforms uniforms(21);
  for (const PhongBsdf& bsdf : every_parameter_set())
    for (int i = 0; i < 300; ++i) {
      const Vec3 wo = uniforms.next_direction();
      const auto s = uniforms.sample(bsdf, wo);
      if (!s) continue;
      ASSERT_TRUE(same_hemisphere(wo, s->wi));
      ASSERT_FALSE(s->transmitted);
      if (s->delta) {
        EXPECT_NEAR(s->wi.x, -wo.x, 1e-6f);
        EXPECT_NEAR(s->wi.z, wo.z, 1e-6f);
        EXPECT_NEAR(s->f.x * std::fabs(s->wi.z), bsdf.mirror(), 1e-5f);
        continue;
      }
      const Color f = bsdf.eval(wo, s->wi);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(s->f[k], f[k], 1e-5f * f[k]);
      EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi), 1e-5f * s->pdf);
    }
}

// kd + highlight + reflectivity above 1: the mirror stays, the highlight takes what it leaves, the
// colour shrinks to the rest with its hue, and the albedo stays at most 1 from every direction.
TEST(PhongBsdf, NeverReflectsMoreThanItReceives) {
  const PhongBsdf overfull = PhongBsdf::from_whitted(Color(0.9f, 0.6f, 0.3f), 0.8f, 80.0f, 0.45f);
  EXPECT_FLOAT_EQ(overfull.mirror(), 0.45f);
  EXPECT_FLOAT_EQ(overfull.highlight(), 2.0f * 0.8f / 82.0f);
  EXPECT_NEAR(overfull.diffuse().x + overfull.highlight() + overfull.mirror(), 1.0f, 1e-6f);
  EXPECT_NEAR(overfull.diffuse().y / overfull.diffuse().x, 0.6f / 0.9f, 1e-6f);
  const PhongBsdf all_highlight = PhongBsdf::from_whitted(Color(0.9f), 5.0f, 0.0f, 0.7f);
  EXPECT_FLOAT_EQ(all_highlight.mirror(), 0.7f);
  EXPECT_NEAR(all_highlight.highlight(), 0.3f, 1e-6f);
  EXPECT_EQ(all_highlight.diffuse(), Color(0.0f));
  for (const PhongBsdf& bsdf : {overfull, all_highlight, PhongBsdf::from_whitted(Color(1.0f), 1.0f, 10.0f, 0.0f)})
    for (float c : {0.95f, 0.6f, 0.2f}) {
      const Color albedo = test::estimate_albedo(bsdf, test::direction(c, 0.7f), 4096);
      for (int k = 0; k < 3; ++k) EXPECT_LE(albedo[k], 1.01f) << "cos " << c;
    }
  // Within its weights the Whitted model is kept as it is: a matte colour and a partial mirror.
  const PhongBsdf plain = PhongBsdf::from_whitted(Color(0.42f, 0.4f, 0.37f), 0.1f, 5.0f, 0.15f);
  EXPECT_EQ(plain.diffuse(), Color(0.42f, 0.4f, 0.37f));
  EXPECT_FLOAT_EQ(plain.mirror(), 0.15f);
}

TEST(PhongBsdf, AMirrorReflectsItsReflectivityAndIsDelta) {
  const PhongBsdf mirror = PhongBsdf::from_whitted(Color(0.0f), 0.0f, 10.0f, 0.9f);
  EXPECT_TRUE(mirror.is_delta());
  const Color albedo = test::estimate_albedo(mirror, test::direction(0.5f, 1.0f), 256);
  EXPECT_NEAR(albedo.x, 0.9f, 1e-5f);
  EXPECT_FALSE(PhongBsdf::from_whitted(Color(0.04f), 1.0f, 300.0f, 0.9f).is_delta());
}

// The whitted integrator's highlight, specular·(r·l)^n, as the radiance a white light of unit
// irradiance·π shows: f = specular·(r·l)^n / (π cos θl). The BSDF's peak at the mirror direction
// and the angle off it where f halves stay within a third and a half of those, at any shininess.
TEST(PhongBsdf, HighlightPeakAndWidthFollowTheWhittedLobe) {
  const Vec3 wo = normalize(Vec3(0.5f, 0.0f, 0.866f));  // 30° off the normal
  const float theta_r = std::acos(wo.z);
  const auto toward = [](float theta) { return Vec3(-std::sin(theta), 0.0f, std::cos(theta)); };
  for (float n : {10.0f, 40.0f, 300.0f}) {
    const PhongBsdf bsdf = PhongBsdf::from_whitted(Color(0.0f), 1.0f, n, 0.0f);
    const float peak = bsdf.eval(wo, toward(theta_r)).x;
    const float whitted_peak = 1.0f / (std::numbers::pi_v<float> * std::cos(theta_r));
    EXPECT_NEAR(peak / whitted_peak, 1.0f, 0.35f) << "shininess " << n;
    float width = 0.0f;
    while (bsdf.eval(wo, toward(theta_r + width)).x > 0.5f * peak) width += 1e-4f;
    const float whitted_width = std::acos(std::pow(0.5f, 1.0f / n));
    EXPECT_NEAR(width / whitted_width, 1.0f, 0.5f) << "shininess " << n;
  }
}

}  // namespace phong_bsdf_test
}  // namespace rtpro
