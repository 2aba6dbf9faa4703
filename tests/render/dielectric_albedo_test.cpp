// The rough dielectric's single-scattering energy albedo: the tables against a fine integration
// between their nodes, a smooth interface's R + T = 1, and an independent Monte Carlo estimate
// through the visible-normal sampler and Fresnel-chosen lobes.
#include "dielectric_albedo.h"

#include "bsdf_test_support.h"
#include "dielectric.h"
#include "microfacet.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

namespace rtpro {
namespace dielectric_albedo_test {

// E by sampling: a visible normal, then reflection with probability F, refraction otherwise,
// each weighted G(wo, wi)/G1(wo), as the BSDF samples it.
double monte_carlo_albedo(float mu, float alpha, float eta) {
  const GgxDistribution ggx{alpha};
  const Vec3 wo{std::sqrt(1.0f - mu * mu), 0.0f, mu};
  test::Uniforms uniforms(101);
  constexpr int kSamples = 100000;
  double sum = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const Vec3 wm = ggx.sample_visible_normal(wo, uniforms.next_2d());
    if (uniforms.next() < fresnel_dielectric(dot(wo, wm), eta)) {
      const Vec3 wi = -reflect(wo, wm);
      if (wi.z > 0.0f) sum += ggx.g(wo, wi) / ggx.g1(wo);
    } else if (const std::optional<Vec3> wi = refract(-wo, wm, eta); wi && wi->z < 0.0f) {
      sum += ggx.g(wo, *wi) / ggx.g1(wo);
    }
  }
  return sum / kSamples;
}

TEST(DielectricAlbedo, MatchesMonteCarloOnBothSides) {
  for (float eta : {1.5f, 1.0f / 1.5f, 2.4f})
    for (float alpha : {0.3f, 1.0f})
      for (float mu : {0.1f, 0.9f})
        EXPECT_NEAR(rough_dielectric_albedo(mu, alpha, eta), monte_carlo_albedo(mu, alpha, eta), 4e-3)
            << "eta " << eta << ", alpha " << alpha << ", mu " << mu;
}

// Between nodes in every coordinate, against the same integral taken finely at the point itself:
// what interpolation costs. Most at grazing incidence on nearly smooth glass, where E falls from 1
// within a node's width.
TEST(DielectricAlbedo, InterpolationMatchesTheIntegralBetweenNodes) {
  for (float eta : {1.45f, 1.0f / 1.45f, 1.0f / 1.2f})
    for (float alpha : {0.02f, 0.13f, 0.41f, 0.83f})
      for (float mu : {0.03f, 0.27f, 0.61f, 0.9f})
        EXPECT_NEAR(rough_dielectric_albedo(mu, alpha, eta),
                    integrate_rough_dielectric_albedo(mu, alpha, eta, GlassFresnel::kExact, 64),
                    mu < 0.05f ? 5e-3 : 4e-3)
            << "eta " << eta << ", alpha " << alpha << ", mu " << mu;
}

TEST(DielectricAlbedo, IsOneWhenSmoothAndLessWhenRough) {
  for (float eta : {1.5f, 1.0f / 1.5f}) {
    EXPECT_FLOAT_EQ(rough_dielectric_albedo(0.5f, 0.0f, eta), 1.0f);
    for (float mu : {0.0f, 0.2f, 1.0f}) {
      float previous = 1.0f;
      for (float alpha : {0.05f, 0.25f, 0.5f, 1.0f}) {
        const float e = rough_dielectric_albedo(mu, alpha, eta);
        EXPECT_LE(e, previous + 1e-3f) << "eta " << eta << ", alpha " << alpha << ", mu " << mu;
        EXPECT_GT(e, 0.25f);
        previous = e;
      }
    }
  }
  EXPECT_LT(rough_dielectric_albedo(0.5f, 1.0f, 1.5f), 0.95f);
}

// Tables prepared ahead (as a render does before its tiles) while other threads already look up the
// same interfaces, some nodes built by the preparation, some by the lookups: no thread waits for
// ever, and every lookup gives what a lookup alone gives, bit for bit (here: the same nodes'
// values read back a second time, on one thread, after all are built), for indices no other test
// reads.
TEST(DielectricAlbedo, PreparingWhileOtherThreadsLookUpGivesTheSameValues) {
  // 2.7 prepared for both Fresnel models; 1.9 left to the lookups (exact Fresnel only).
  const std::vector<RoughInterface> interfaces{{2.7f, GlassFresnel::kExact}, {2.7f, GlassFresnel::kSchlick}};
  struct Lookup {
    float eta;
    GlassFresnel fresnel;
  };
  const std::vector<Lookup> lookups{{2.7f, GlassFresnel::kExact},
                                    {1.0f / 2.7f, GlassFresnel::kExact},
                                    {1.0f / 2.7f, GlassFresnel::kSchlick},
                                    {1.9f, GlassFresnel::kExact},
                                    {1.0f / 1.9f, GlassFresnel::kExact}};
  const std::vector<float> mus{0.04f, 0.77f};
  std::vector<float> concurrent(lookups.size() * mus.size());
  const auto look_up = [&](std::size_t i) {
    const Lookup& l = lookups[i / mus.size()];
    return rough_dielectric_albedo(mus[i % mus.size()], 0.3f, l.eta, l.fresnel);
  };
  tbb::parallel_invoke([&] { prepare_rough_dielectric_albedo(interfaces); },
                       [&] {
                         tbb::parallel_for(std::size_t{0}, concurrent.size(),
                                           [&](std::size_t i) { concurrent[i] = look_up(i); });
                       });
  for (std::size_t i = 0; i < concurrent.size(); ++i) {
    const Lookup& l = lookups[i / mus.size()];
    const float mu = mus[i % mus.size()];
    EXPECT_EQ(concurrent[i], look_up(i)) << "eta " << l.eta << ", mu " << mu;
    EXPECT_NEAR(concurrent[i], integrate_rough_dielectric_albedo(mu, 0.3f, l.eta, l.fresnel, 64), 5e-3)
        << "eta " << l.eta << ", mu " << mu;
  }
}

}  // namespace dielectric_albedo_test
}  // namespace rtpro
