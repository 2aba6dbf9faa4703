// The Bsdf variant dispatches to its kind: the free functions agree with the member functions of
// whichever kind is held, and only all-specular kinds are delta.
#include "bsdf.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <vector>

namespace rtpro {
namespace bsdf_test {

TEST(Bsdf, DeltaOnlyWhenEveryLobeIsSpecular) {
  EXPECT_FALSE(bsdf_is_delta(DiffuseBsdf{Color(0.5f)}));
  EXPECT_TRUE(bsdf_is_delta(ConductorBsdf::from_f0(Color(0.9f), 0.0f)));
  EXPECT_FALSE(bsdf_is_delta(ConductorBsdf::from_f0(Color(0.9f), 0.2f)));
  EXPECT_TRUE(bsdf_is_delta(DielectricBsdf{1.5f, 0.0f}));
  EXPECT_TRUE(bsdf_is_delta(DielectricBsdf{1.0f, 0.3f}));
  EXPECT_FALSE(bsdf_is_delta(DielectricBsdf{1.5f, 0.3f}));
  PrincipledParameters mirror;
  mirror.metalness = 1.0f;
  mirror.roughness = 0.0f;
  EXPECT_TRUE(bsdf_is_delta(PrincipledBsdf(mirror)));
  EXPECT_FALSE(bsdf_is_delta(PrincipledBsdf(PrincipledParameters{})));
}

template <class Kind>
void expect_dispatch_matches(const Kind& kind) {
  const Bsdf bsdf = kind;
  test::Uniforms uniforms(31);
  for (int i = 0; i < 200; ++i) {
    const Vec3 wo = uniforms.next_direction();
    const Vec3 wi = uniforms.next_direction();
    EXPECT_EQ(bsdf_eval(bsdf, wo, wi), kind.eval(wo, wi));
    EXPECT_EQ(bsdf_pdf(bsdf, wo, wi), kind.pdf(wo, wi));
    const float u_lobe = uniforms.next();
    const Sample2D u = uniforms.next_2d();
    const auto via_variant = bsdf_sample(bsdf, wo, u_lobe, u);
    const auto direct = kind.sample(wo, u_lobe, u);
    ASSERT_EQ(via_variant.has_value(), direct.has_value());
    if (direct) {
      EXPECT_EQ(via_variant->wi, direct->wi);
      EXPECT_EQ(via_variant->f, direct->f);
      EXPECT_EQ(via_variant->pdf, direct->pdf);
      EXPECT_EQ(via_variant->delta, direct->delta);
    }
  }
}

TEST(Bsdf, DispatchesToTheHeldKind) {
  expect_dispatch_matches(DiffuseBsdf{Color(0.7f)});
  expect_dispatch_matches(ConductorBsdf::from_complex_ior({0.2f, 0.4f, 1.4f}, {4.0f, 2.4f, 1.6f}, 0.3f));
  expect_dispatch_matches(DielectricBsdf{1.5f, 0.2f});
  expect_dispatch_matches(DielectricBsdf{1.5f, 0.0f});
  // Every layer of the glTF model at once: a rough copper-coloured metal half, fuzz and a coat.
  PrincipledParameters layered;
  layered.base_color = Color(0.95f, 0.64f, 0.54f);
  layered.metalness = 0.5f;
  layered.roughness = 0.4f;
  layered.fuzz_color = Color(0.5f);
  layered.fuzz_roughness = 0.5f;
  layered.coat_weight = 1.0f;
  layered.coat_roughness = 0.2f;
  expect_dispatch_matches(PrincipledBsdf(layered));
}

}  // namespace bsdf_test
}  // namespace rtpro
