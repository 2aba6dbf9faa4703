// The principled BSDF's subsurface lobe (render/bsdf/principled_bsdf.h): it takes the Lambert
// base's share of the energy, so that a walk that gives back the base colour leaves the material's
// albedo as it was, and light sampling does not see it.
#include "principled_bsdf.h"

#include "bsdf_test_support.h"
#include "rtpro/core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

namespace rtpro {
namespace principled_subsurface_test {

// What the BSDF returns for light arriving along wo, a subsurface sample counting its weight times
// the base colour (what a walk under a thick flat surface gives back, subsurface_medium.h), and
// separately the share of it that went under the surface.
struct Split {
  Color total{0.0f}, subsurface{0.0f};
};

Split split_albedo(const PrincipledParameters& p, const Vec3& wo, int count) {
  const PrincipledBsdf bsdf(p);
  Split split;
  for (int i = 0; i < count; ++i) {
    const float u_lobe = (i + 0.5f) / count;
    const Sample2D u{to_unit_float(mix64(2 * i + 1)), to_unit_float(mix64(2 * i + 2))};
    const std::optional<BsdfSample> s = bsdf.sample(wo, u_lobe, u);
    if (!s || !(s->pdf > 0.0f)) continue;
    const Color weight = s->f * (std::fabs(s->wi.z) / s->pdf) / static_cast<float>(count);
    if (s->lobe == BsdfLobe::kSubsurface) {
      split.subsurface += weight * p.base_color;
      split.total += weight * p.base_color;
    } else {
      split.total += weight;
    }
  }
  return split;
}

TEST(PrincipledBsdf, SubsurfaceTakesTheLambertBasesShare) {
  PrincipledParameters p;
  p.base_color = Color(0.7f, 0.45f, 0.2f);
  p.roughness = 0.4f;
  const Vec3 wo = test::direction(0.6f, 0.3f);
  const Split opaque = split_albedo(p, wo, 32768);
  p.subsurface_weight = 0.6f;
  const Split mixed = split_albedo(p, wo, 32768);
  p.subsurface_weight = 1.0f;
  const Split full = split_albedo(p, wo, 32768);
  EXPECT_EQ(max_component(opaque.subsurface), 0.0f);
  for (int c = 0; c < 3; ++c) {
    // The same energy leaves whichever way the base goes; under the surface goes its share.
    EXPECT_NEAR(mixed.total[c], opaque.total[c], 0.01f) << c;
    EXPECT_NEAR(full.total[c], opaque.total[c], 0.01f) << c;
    EXPECT_NEAR(mixed.subsurface[c], 0.6f * full.subsurface[c], 0.01f) << c;
  }
  EXPECT_GT(full.subsurface.x, 0.5f);
  // Light sampling sees no subsurface lobe: f is the rest, the Lambert base's (1 − 0.6).
  const Vec3 wi = test::direction(0.8f, 2.0f);
  p.subsurface_weight = 0.0f;
  const Color lambert_and_specular = PrincipledBsdf(p).eval(wo, wi);
  p.subsurface_weight = 0.6f;
  EXPECT_LT(max_component(PrincipledBsdf(p).eval(wo, wi)), max_component(lambert_and_specular));
}

}  // namespace principled_subsurface_test
}  // namespace rtpro
