#pragma once
// Sampling a rough glass interface (DielectricBsdf, PrincipledBsdf's glass): a visible normal,
// reflection or refraction by the facet's Fresnel term, and, energy-compensated, the direction
// kept with probability G(wo, wi)/G1(wo), else drawn again; what is kept is distributed as the
// compensated f·|cos θi| of energy (render/bsdf/dielectric_bsdf.h says why).
//
// The attempts' numbers: the first uses the sampler's own, so their stratification is kept where
// most samples are accepted; later ones are hashed from them, a pure function of the first, so
// images stay a function of scene and seed.
#include "dielectric.h"
#include "microfacet.h"
#include "rtpro/core/random.h"
#include "rtpro/render/sampler.h"

#include <bit>
#include <cstdint>
#include <optional>

namespace rtpro {

// Accepted within this many attempts, or given up: each is accepted with probability E(μo)
// (0.38 at worst, so 32 attempts all fail once in 4 million samples).
inline constexpr int kMaxSampleAttempts = 32;

struct AttemptSamples {
  float u_lobe;
  Sample2D u;
};

inline AttemptSamples attempt_samples(float u_lobe, Sample2D u, int attempt) {
  if (attempt == 0) return {u_lobe, u};
  std::uint64_t seed = hash_combine(std::bit_cast<std::uint32_t>(u_lobe), std::bit_cast<std::uint32_t>(u.x));
  seed = hash_combine(hash_combine(seed, std::bit_cast<std::uint32_t>(u.y)), static_cast<std::uint64_t>(attempt));
  return {to_unit_float(mix64(seed)), {to_unit_float(mix64(seed + 1)), to_unit_float(mix64(seed + 2))}};
}

// The chance that a compensated sample drawn for wi is kept: G(wo, wi)/G1(wo), at most 1.
inline float kept_fraction(const GgxDistribution& ggx, const Vec3& wo, const Vec3& wi) {
  return ggx.g(wo, wi) / ggx.g1(wo);
}

// A direction for wo (either side; η = n_inside / n_outside), or nothing. `reflectance(wo·wm)`
// is the probability of reflecting at the facet wm; with `compensated`, up to kMaxSampleAttempts
// attempts, the lobe's share of u_lobe rescaled for each one's acceptance test.
template <class Reflectance>
std::optional<Vec3> sample_rough_glass(const GgxDistribution& ggx, const Vec3& wo, float eta, float u_lobe, Sample2D u,
                                       bool compensated, Reflectance&& reflectance) {
  for (int attempt = 0; attempt < (compensated ? kMaxSampleAttempts : 1); ++attempt) {
    const AttemptSamples a = attempt_samples(u_lobe, u, attempt);
    const Vec3 wm = ggx.sample_visible_normal(wo, a.u);
    const float r = reflectance(dot(wo, wm));
    const bool reflects = a.u_lobe < r;
    const float u_accept = reflects ? a.u_lobe / r : (a.u_lobe - r) / (1.0f - r);
    std::optional<Vec3> wi;
    if (reflects) {
      if (const Vec3 mirrored = -reflect(wo, wm); mirrored.z * wo.z > 0.0f) wi = mirrored;
    } else if (const std::optional<Vec3> refracted = refract_through(wo, wm, eta);
               refracted && refracted->z * wo.z < 0.0f) {
      wi = refracted;
    }
    if (!wi) continue;
    if (compensated && u_accept >= kept_fraction(ggx, wo, *wi)) continue;
    return wi;
  }
  return std::nullopt;
}

}  // namespace rtpro
