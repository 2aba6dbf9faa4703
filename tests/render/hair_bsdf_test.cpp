// The hair BSDF (pbrt-v4's HairBSDF tests and more): without absorption it returns all the light it
// receives for every roughness, offset and direction, integrated over the sphere (the white
// furnace) and sampled (every sample's weight is the attenuation, 1); its sampler matches its pdf
// (χ²); and on a surface it lines its fibre up with the tangent and puts its highlight where a
// mirror would.
#include "hair_bsdf.h"

#include "bsdf_test_support.h"
#include "material_bsdf.h"
#include "rtpro/scene/hair_material.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

namespace rtpro {
namespace hair_bsdf_test {

constexpr float kPi = std::numbers::pi_v<float>;
const std::vector<float> kRoughnesses{0.1f, 0.3f, 0.5f, 0.7f, 0.9f, 1.0f};

HairBsdf fibre(float beta_m, float beta_n, float h, const Color& sigma_a = Color(0.0f), float alpha = 2.0f,
               float axis_angle = 0.7f) {
  return HairBsdf({1.55f, sigma_a, beta_m, beta_n, alpha}, std::cos(axis_angle), std::sin(axis_angle), h);
}

// ∫ f(wo, wi) |cos θi| dωi over the sphere by the midpoint rule over the fibre's own angles (θ
// along the axis at (cos 0.7, sin 0.7, 0), φ around it), with steps fine enough for the lobes'
// widths (at β = 0.1 M_p is about 0.04 rad wide and N_p 0.04 rad; both smooth, so a node a lobe
// width apart already integrates them to 1e-4).
Color furnace_integral(const HairBsdf& bsdf, const Vec3& wo) {
  const int theta_steps = bsdf.beta_m() < 0.2f ? 96 : 48;
  const int phi_steps = bsdf.beta_n() < 0.2f ? 192 : 96;
  const Vec3 axis{std::cos(0.7f), std::sin(0.7f), 0.0f}, across{-axis.y, axis.x, 0.0f}, normal{0.0f, 0.0f, 1.0f};
  double sum[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i < theta_steps; ++i) {
    const float theta = -kPi / 2 + kPi * (static_cast<float>(i) + 0.5f) / static_cast<float>(theta_steps);
    for (int j = 0; j < phi_steps; ++j) {
      const float phi = 2 * kPi * (static_cast<float>(j) + 0.5f) / static_cast<float>(phi_steps);
      const Vec3 wi = axis * std::sin(theta) + across * (std::cos(theta) * std::cos(phi)) +
                      normal * (std::cos(theta) * std::sin(phi));
      const Color f = bsdf.eval(wo, wi) * (std::fabs(wi.z) * std::cos(theta));
      for (int c = 0; c < 3; ++c) sum[c] += f[c];
    }
  }
  const double cell = (kPi / theta_steps) * (2 * kPi / phi_steps);
  return {static_cast<float>(sum[0] * cell), static_cast<float>(sum[1] * cell), static_cast<float>(sum[2] * cell)};
}

TEST(HairBsdf, WhiteFurnace) {
  test::Uniforms u(47);
  float worst = 0.0f;
  for (float beta_m : kRoughnesses)
    for (float beta_n : kRoughnesses) {
      const float h = -1.0f + 2.0f * u.next();
      const Vec3 wo = u.next_direction();
      const Color albedo = furnace_integral(fibre(beta_m, beta_n, h), wo);
      SCOPED_TRACE("beta_m " + std::to_string(beta_m) + ", beta_n " + std::to_string(beta_n) + ", h " +
                   std::to_string(h) + ", wo.z " + std::to_string(wo.z));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(albedo[c], 1.0f, 0.01f);
      worst = std::max(worst, std::fabs(albedo.y - 1.0f));
    }
  std::cout << "[furnace] largest |albedo - 1| over the 36 roughness pairs: " << worst << "\n";
}

TEST(HairBsdf, WhiteFurnaceSampled) {
  test::Uniforms u(48);
  constexpr int kSamples = 2000;
  for (float beta_m : kRoughnesses)
    for (float beta_n : kRoughnesses) {
      const Vec3 wo = u.next_direction();
      double sum = 0.0;
      for (int i = 0; i < kSamples; ++i) {
        const HairBsdf bsdf = fibre(beta_m, beta_n, -1.0f + 2.0f * u.next());
        const auto s = u.sample(bsdf, wo);
        if (!s) continue;
        // Every sample's weight is ΣA_p = 1: the sampler follows the lobes exactly.
        const float weight = s->f.y * std::fabs(s->wi.z) / s->pdf;
        ASSERT_NEAR(weight, 1.0f, 1e-3f) << "beta_m " << beta_m << ", beta_n " << beta_n;
        sum += weight;
      }
      EXPECT_NEAR(sum / kSamples, 1.0, 0.01) << "beta_m " << beta_m << ", beta_n " << beta_n;
    }
}

TEST(HairBsdf, SamplingWeightsAreTheAttenuation) {
  // With a grey σa the lobe choice follows the attenuation in every channel, so every sample's
  // weight is ΣA_p exactly; and it never exceeds 1.
  test::Uniforms u(49);
  for (float sigma_a : {0.1f, 1.0f, 5.0f})
    for (float beta : {0.2f, 0.6f}) {
      const HairBsdf bsdf = fibre(beta, beta, -1.0f + 2.0f * u.next(), Color(sigma_a));
      for (int i = 0; i < 200; ++i) {
        const Vec3 wo = u.next_direction();
        const Color expected = bsdf.attenuation(wo);
        EXPECT_LE(expected.x, 1.0f);
        const auto s = u.sample(bsdf, wo);
        if (!s) continue;
        EXPECT_NEAR(s->f.x * std::fabs(s->wi.z) / s->pdf, expected.x, 1e-3f * expected.x + 1e-6f);
        EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi), 1e-3f * s->pdf);
        EXPECT_NEAR(s->f.x, bsdf.eval(wo, s->wi).x, 1e-3f * s->f.x);
      }
    }
}

TEST(HairBsdfChi2, SamplerMatchesPdf) {
  const std::vector<Vec3> wos{test::direction(0.8f, 0.3f), test::direction(0.1f, 2.0f), test::direction(-0.5f, 4.0f)};
  test::expect_sampler_matches_pdf("hair beta 0.2/0.25 h 0.3 brown", fibre(0.2f, 0.25f, 0.3f, Color(0.3f, 0.6f, 1.2f)),
                                   wos, 200'000);
  test::expect_sampler_matches_pdf("hair beta 0.6/0.9 h -0.7 clear alpha 5",
                                   fibre(0.6f, 0.9f, -0.7f, Color(0.0f), 5.0f), wos, 200'000);
  test::expect_sampler_matches_pdf("hair beta 1/0.1 h from wo",
                                   fibre(1.0f, 0.1f, HairBsdf::kOffsetFromWo, Color(0.05f)), wos, 200'000);
}

TEST(HairBsdf, FilterGlossyWidensBothRoughnesses) {
  HairBsdf bsdf = fibre(0.1f, 0.4f, 0.2f);
  bsdf.roughen_to(0.3f);
  EXPECT_EQ(bsdf.beta_m(), 0.3f);
  EXPECT_EQ(bsdf.beta_n(), 0.4f);
  const Color albedo = furnace_integral(bsdf, test::direction(0.3f, 1.0f));
  EXPECT_NEAR(albedo.x, 1.0f, 0.01f);
}

// A hair material's BSDF at a surface point: its normal (0.6, 0, 0.8), its tangent along y.
SurfaceBsdf hair_at(const Vec3& tangent, float fiber_offset = 0.0f) {
  Material material;
  material.model = HairSurface{0.05f, 0.05f, 0.0f, 1.55f, false, Color(1e3f), Color(0.0f)};
  SurfacePoint point{};
  point.shading_normal = point.geometric_normal = Vec3(0.6f, 0.0f, 0.8f);
  point.front_face = true;
  point.tangent = tangent;
  point.fiber_offset = fiber_offset;
  return material_bsdf(material, point, nullptr);
}

TEST(HairBsdf, TheFibreRunsAlongTheSurfacesTangent) {
  const SurfaceBsdf surface = hair_at(Vec3(0.0f, 3.0f, 0.0f));
  const HairBsdf& bsdf = std::get<HairBsdf>(surface.bsdf);
  const Vec3 axis = surface.frame.to_world(bsdf.axis());
  EXPECT_NEAR(axis.y, 1.0f, 1e-5f);
  // A tangent with a part along the normal keeps the rest; none at all leaves some tangent.
  const SurfaceBsdf tilted = hair_at(Vec3(0.6f, 1.0f, 0.8f));
  const Vec3 tilted_axis = tilted.frame.to_world(std::get<HairBsdf>(tilted.bsdf).axis());
  EXPECT_NEAR(tilted_axis.y, 1.0f, 1e-5f);
  const SurfaceBsdf none = hair_at(Vec3(0.0f));
  const Vec3 any = none.frame.to_world(std::get<HairBsdf>(none.bsdf).axis());
  EXPECT_NEAR(length(any), 1.0f, 1e-5f);
  EXPECT_NEAR(dot(any, Vec3(0.6f, 0.0f, 0.8f)), 0.0f, 1e-5f);
}

TEST(HairBsdf, OnASurfaceTheHighlightIsTheMirrorDirection) {
  // Absorbing, nearly smooth hair reflects by R alone: where the shading normal mirrors wo,
  // whatever the azimuth (h follows from wo and the normal).
  const SurfaceBsdf surface = hair_at(Vec3(0.0f, 1.0f, 0.0f));
  test::Uniforms u(50);
  for (int i = 0; i < 20; ++i) {
    const Vec3 wo = u.next_direction(0.3f, 1.0f);
    const Vec3 mirror{-wo.x, -wo.y, wo.z};
    const float peak = bsdf_eval(surface.bsdf, wo, mirror).x;
    // 0.1 rad off the mirror direction, either way: the lobes are about 0.04 rad wide.
    const ShadingFrame around = ShadingFrame::from_normal(mirror);
    for (const Vec3& offset : {around.s, around.t, -around.s, -around.t}) {
      const Vec3 beside = normalize(mirror + offset * 0.1f);
      EXPECT_GT(peak * std::fabs(mirror.z), 2.0f * bsdf_eval(surface.bsdf, wo, beside).x * std::fabs(beside.z));
    }
  }
}

TEST(HairBsdf, ACurvesOffsetIsUsedAsGiven) {
  // Seen along the normal, h = 0 from the geometry; a curve's offset of 0.9 moves the highlight.
  const Vec3 wo = ShadingFrame::from_normal(Vec3(0.6f, 0.0f, 0.8f)).to_local(Vec3(0.6f, 0.0f, 0.8f));
  const SurfaceBsdf centre = hair_at(Vec3(0.0f, 1.0f, 0.0f));
  const SurfaceBsdf edge = hair_at(Vec3(0.0f, 1.0f, 0.0f), 0.9f);
  EXPECT_GT(bsdf_eval(centre.bsdf, wo, wo).x, 10.0f * bsdf_eval(edge.bsdf, wo, wo).x);
}

}  // namespace hair_bsdf_test
}  // namespace rtpro
